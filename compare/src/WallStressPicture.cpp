#include "vesica/compare/WallStressPicture.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

#include <unistd.h>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSetMapper.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>
#include <vtkUnstructuredGrid.h>
#include <vtkWindowToImageFilter.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "vesica/core/Error.h"

// VTK's render window and text classes come from object factories that must be
// registered explicitly in a plain (non-vtk_module_autoinit) build.
#include <vtkAutoInit.h>
VTK_MODULE_INIT(vtkRenderingOpenGL2);
VTK_MODULE_INIT(vtkRenderingFreeType);

namespace vesica::compare {
namespace {

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The array that best shows wall stress: a name with "stress" (principal or von Mises
// first), cell data before point data.
struct Chosen {
  vtkDataArray* array = nullptr;
  bool cell = true;
};
Chosen choose_array(vtkPolyData* poly) {
  Chosen best;
  int best_score = -1;
  auto consider = [&](vtkDataArray* a, bool cell) {
    if (!a || !a->GetName()) return;
    const std::string n = lower(a->GetName());
    int score = 0;
    if (n.find("stress") != std::string::npos) score += 10;
    if (n.find("principal") != std::string::npos || n.find("mises") != std::string::npos)
      score += 5;
    if (n.find("max") != std::string::npos) score += 2;
    if (n == "region" || n.find("fiber") != std::string::npos) score -= 20;
    if (cell) score += 1;
    if (score > best_score) best_score = score, best = {a, cell};
  };
  for (int i = 0; i < poly->GetCellData()->GetNumberOfArrays(); ++i)
    consider(poly->GetCellData()->GetArray(i), true);
  for (int i = 0; i < poly->GetPointData()->GetNumberOfArrays(); ++i)
    consider(poly->GetPointData()->GetArray(i), false);
  if (best_score < 0) return {};
  return best;
}

std::string quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string read_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

std::string base64(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) |
                       (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    for (int s = 18; s >= 0; s -= 6) out += table[(v >> s) & 63];
  }
  if (i < bytes.size()) {
    unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string render_wall_stress_png(const std::filesystem::path& vtu,
                                   const std::filesystem::path& png, int width, int height) {
  if (!std::filesystem::exists(vtu)) fail(vtu.string(), "mesh not found");
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(vtu.c_str());
  reader->Update();
  if (!reader->GetOutput() || reader->GetOutput()->GetNumberOfCells() == 0)
    fail(vtu.string(), "no cells could be read", "expected a VTK XML .vtu");
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputConnection(reader->GetOutputPort());
  surface->Update();
  vtkPolyData* poly = surface->GetOutput();

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  vtkNew<vtkRenderer> renderer;
  const Chosen chosen = choose_array(poly);
  std::string shown = "none";
  if (chosen.array) {
    shown = chosen.array->GetName();
    if (chosen.cell)
      mapper->SetScalarModeToUseCellFieldData();
    else
      mapper->SetScalarModeToUsePointFieldData();
    mapper->SelectColorArray(chosen.array->GetName());
    mapper->ScalarVisibilityOn();
    double range[2];
    chosen.array->GetRange(range, chosen.array->GetNumberOfComponents() > 1 ? -1 : 0);
    mapper->SetScalarRange(range);
    vtkNew<vtkLookupTable> lut;
    lut->SetHueRange(0.667, 0.0);  // blue (low) to red (high)
    lut->Build();
    mapper->SetLookupTable(lut);
    vtkNew<vtkScalarBarActor> bar;
    bar->SetLookupTable(lut);
    bar->SetTitle(chosen.array->GetName());
    bar->GetTitleTextProperty()->SetColor(0, 0, 0);
    bar->GetLabelTextProperty()->SetColor(0, 0, 0);
    bar->SetNumberOfLabels(5);
    renderer->AddActor2D(bar);
  } else {
    mapper->ScalarVisibilityOff();
  }
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  renderer->SetBackground(1, 1, 1);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Elevation(20);
  renderer->GetActiveCamera()->Azimuth(30);
  renderer->ResetCamera();

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->SetSize(width, height);
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(png.c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  return shown;
}

WallStressPicture make_wall_stress_picture(const std::filesystem::path& vtu,
                                           const std::filesystem::path& executable) {
  namespace fs = std::filesystem;
  WallStressPicture pic;
  if (!fs::exists(vtu)) {
    pic.message = "no wall-stress picture: mesh " + vtu.string() + " not found";
    return pic;
  }
  const std::string tag = std::to_string(::getpid());
  const fs::path tmp = fs::temp_directory_path() / ("vesica-compare-" + tag + ".png");
  const fs::path log = fs::temp_directory_path() / ("vesica-compare-" + tag + ".log");
  std::string cmd = quote(executable.string()) + " --render-wall-stress " + quote(vtu.string()) +
                    " --render-png " + quote(tmp.string());
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display) {
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) {
      pic.message = "no wall-stress picture: no X display and xvfb-run is not installed";
      return pic;
    }
    cmd = "xvfb-run -a " + cmd;
  }
  const int status = std::system((cmd + " >" + quote(log.string()) + " 2>&1").c_str());
  const std::string bytes = fs::exists(tmp) ? read_bytes(tmp) : std::string();
  std::string out = read_bytes(log);
  fs::remove(tmp);
  fs::remove(log);
  if (status != 0 || bytes.size() < 8) {
    if (out.size() > 300) out = out.substr(out.size() - 300);
    pic.message = "no wall-stress picture: off-screen rendering failed (" + out + ")";
    return pic;
  }
  const auto pos = out.find("array: ");
  pic.array = pos == std::string::npos ? "" : out.substr(pos + 7, out.find('\n', pos) - pos - 7);
  pic.png_base64 = base64(bytes);
  pic.message = "wall at capacity from " + vtu.filename().string() +
                (pic.array.empty() ? "" : ", coloured by " + pic.array);
  return pic;
}

std::optional<std::filesystem::path> vtu_at_time(const std::filesystem::path& pvd, double time_s) {
  std::ifstream in(pvd);
  if (!in) return std::nullopt;
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  // <DataSet timestep="12.5" ... file="series/step_0012.vtu"/>: attributes in any order
  const std::regex dataset("<DataSet[^>]*>");
  const std::regex timestep("timestep=\"([^\"]*)\""), file("file=\"([^\"]*)\"");
  std::optional<std::filesystem::path> best;
  double best_gap = HUGE_VAL;
  for (std::sregex_iterator it(text.begin(), text.end(), dataset), end; it != end; ++it) {
    const std::string tagtext = it->str();
    std::smatch t, f;
    if (!std::regex_search(tagtext, t, timestep) || !std::regex_search(tagtext, f, file)) continue;
    const double gap = std::abs(std::atof(t[1].str().c_str()) - time_s);
    if (gap < best_gap) best_gap = gap, best = pvd.parent_path() / f[1].str();
  }
  return best;
}

}  // namespace vesica::compare
