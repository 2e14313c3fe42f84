#include "vesica/compare/report/WallStressPicture.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCaptionActor2D.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include "vesica/compare/analysis/WallStress.h"
#include "vesica/compare/html/Viridis.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/HelperProgram.h"

// VTK's render window and text classes come from object factories that must be
// registered explicitly in a plain (non-vtk_module_autoinit) build.
#include <vtkAutoInit.h>

#include <nlohmann/json.hpp>
VTK_MODULE_INIT(vtkRenderingOpenGL2);
VTK_MODULE_INIT(vtkRenderingFreeType);

namespace vesica::compare {
namespace {

namespace fs = std::filesystem;

// A picture of a wall takes seconds; a renderer stuck on a display is stopped.
constexpr std::chrono::seconds kRenderDeadline{120};

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

vtkNew<vtkPolyData> wall_polydata(const WallStressField& f) {
  vtkNew<vtkPolyData> poly;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (Eigen::Index i = 0; i < f.points_mm.rows(); ++i)
    points->InsertNextPoint(f.points_mm(i, 0), f.points_mm(i, 1), f.points_mm(i, 2));
  vtkNew<vtkCellArray> cells;
  for (Eigen::Index t = 0; t < f.triangles.rows(); ++t) {
    const vtkIdType ids[3] = {f.triangles(t, 0), f.triangles(t, 1), f.triangles(t, 2)};
    cells->InsertNextCell(3, ids);
  }
  vtkNew<vtkDoubleArray> sigma1;
  sigma1->SetName("sigma1_kpa");
  for (double s : f.sigma1_kpa) sigma1->InsertNextValue(s);  // NaN (grey) on the outlet
  poly->SetPoints(points);
  poly->SetPolys(cells);
  poly->GetCellData()->AddArray(sigma1);
  return poly;
}

constexpr std::array<double, 3> kBelowRange = {0.0, 0.0, 0.0};   // black
constexpr std::array<double, 3> kAboveRange = {1.0, 0.35, 0.7};  // pink

vtkNew<vtkLookupTable> viridis_table(const std::array<double, 2>& range) {
  vtkNew<vtkLookupTable> lut;
  lut->SetNumberOfTableValues(256);
  lut->SetTableRange(range[0], range[1]);
  lut->Build();
  for (int i = 0; i < 256; ++i) {
    const auto rgb = viridis(i / 255.0);
    lut->SetTableValue(i, rgb[0], rgb[1], rgb[2], 1.0);
  }
  const auto grey = viridis(std::nan(""));
  lut->SetNanColor(grey[0], grey[1], grey[2], 1.0);
  // The tails beyond the 2nd and 98th percentiles in colours viridis never takes, so that
  // a few extreme triangles are seen as such and do not flatten the rest into one colour.
  lut->SetBelowRangeColor(kBelowRange[0], kBelowRange[1], kBelowRange[2], 1.0);
  lut->UseBelowRangeColorOn();
  lut->SetAboveRangeColor(kAboveRange[0], kAboveRange[1], kAboveRange[2], 1.0);
  lut->UseAboveRangeColorOn();
  return lut;
}

vtkNew<vtkTextActor> text(const std::string& value, double x, double y, int size, int justify) {
  vtkNew<vtkTextActor> t;
  t->SetInput(value.c_str());
  t->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  t->GetPositionCoordinate()->SetValue(x, y);
  vtkTextProperty* p = t->GetTextProperty();
  p->SetFontSize(size);
  p->SetColor(0.1, 0.1, 0.1);
  p->SetJustification(justify);
  p->SetVerticalJustificationToCentered();
  return t;
}

// From the front: the camera on -y (anterior in LPS) looking along +y, head (+z) up, so
// the patient's right is on the left of the picture.
void look_from_front(vtkRenderer* renderer, vtkPolyData* poly) {
  double b[6];
  poly->GetBounds(b);
  const double c[3] = {0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5])};
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(c);
  camera->SetPosition(c[0], c[1] - 1000.0, c[2]);
  camera->SetViewUp(0, 0, 1);
  renderer->ResetCamera();
  camera->Zoom(0.95);
}

void add_patient_directions(vtkRenderer* r, const std::string& state) {
  r->AddActor2D(text("R", 0.03, 0.5, 26, VTK_TEXT_LEFT));
  r->AddActor2D(text("L", 0.97, 0.5, 26, VTK_TEXT_RIGHT));
  r->AddActor2D(text("S", 0.5, 0.93, 26, VTK_TEXT_CENTERED));
  r->AddActor2D(text("I", 0.5, 0.04, 26, VTK_TEXT_CENTERED));
  r->AddActor2D(text("anterior view (from the front)", 0.03, 0.975, 16, VTK_TEXT_LEFT));
  r->AddActor2D(text("pink: above the 98th percentile\nblack: below the 2nd", 0.03, 0.06, 14,
                     VTK_TEXT_LEFT));
  if (!state.empty()) r->AddActor2D(text(state, 0.97, 0.975, 16, VTK_TEXT_RIGHT));
}

// Seen from the front, an outlet behind the wall's middle plane is hidden by the wall: the
// label then says so rather than point at a colour that is not there.
void add_outlet_label(vtkRenderer* r, const Eigen::Vector3d& outlet, vtkPolyData* poly) {
  double b[6];
  poly->GetBounds(b);
  const bool hidden = outlet.y() > 0.5 * (b[2] + b[3]);  // y: posterior in LPS
  vtkNew<vtkCaptionActor2D> caption;
  caption->SetCaption(hidden ? "outlet (grey, behind)" : "outlet (grey)");
  caption->SetAttachmentPoint(outlet.x(), outlet.y(), outlet.z());
  caption->BorderOff();
  caption->LeaderOn();
  caption->ThreeDimensionalLeaderOff();
  caption->GetProperty()->SetColor(0.1, 0.1, 0.1);
  caption->SetPosition(40, -60);
  caption->SetWidth(0.22);
  caption->SetHeight(0.05);
  caption->GetCaptionTextProperty()->SetColor(0.1, 0.1, 0.1);
  caption->GetCaptionTextProperty()->BoldOff();
  caption->GetCaptionTextProperty()->ItalicOff();
  caption->GetCaptionTextProperty()->ShadowOff();
  r->AddActor2D(caption);
}

vtkNew<vtkRenderer> colour_bar(vtkLookupTable* lut) {
  vtkNew<vtkRenderer> r;
  r->SetViewport(0.78, 0.0, 1.0, 1.0);
  r->SetBackground(1, 1, 1);
  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(lut);
  bar->SetOrientationToVertical();
  bar->SetNumberOfLabels(5);
  bar->SetLabelFormat("%.3g");
  bar->UnconstrainedFontSizeOn();
  bar->GetLabelTextProperty()->SetFontSize(18);
  bar->GetLabelTextProperty()->SetColor(0.1, 0.1, 0.1);
  bar->GetLabelTextProperty()->ShadowOff();
  bar->GetLabelTextProperty()->ItalicOff();
  bar->GetLabelTextProperty()->BoldOff();
  bar->SetPosition(0.1, 0.08);
  bar->SetWidth(0.6);
  bar->SetHeight(0.7);
  bar->DrawNanAnnotationOff();
  bar->DrawBelowRangeSwatchOn();
  bar->DrawAboveRangeSwatchOn();
  bar->DrawAnnotationsOff();  // the tails are named under the wall (add_patient_directions)
  r->AddActor2D(bar);
  r->AddActor2D(text("max principal\nCauchy stress\n(kPa)", 0.1, 0.88, 18, VTK_TEXT_LEFT));
  return r;
}

std::string state_line(const WallStressSummary& s) {
  std::ostringstream o;
  o.precision(3);
  if (s.volume_ml) o << "V = " << std::lround(*s.volume_ml) << " ml";
  if (s.pdet_cmh2o) o << (o.tellp() > 0 ? ", " : "") << "Pdet = " << *s.pdet_cmh2o << " cmH2O";
  if (s.time_s) o << (o.tellp() > 0 ? ", " : "") << "t = " << std::lround(*s.time_s) << " s";
  return o.str();
}

// What the picture shows, from the frame's own numbers: the series frame nearest capacity
// may be the first step of voiding, whose Pdet is no longer the table's Pdet at capacity.
std::string frame_caption(const WallStressPicture& p) {
  std::string line = state_line(p.summary);
  return "the series frame nearest capacity (" + p.frame + (line.empty() ? "" : ": " + line) + ")";
}

}  // namespace

std::array<double, 2> colour_bar_range(const WallStressSummary& s) {
  double lo = s.p2_kpa, hi = s.p98_kpa;
  if (std::abs(lo) < 1e-6 * std::abs(hi)) lo = 0.0;
  if (!(hi - lo > 1e-9 * std::max(1.0, std::abs(hi)))) lo = hi - 1.0;
  return {lo, hi};
}

nlohmann::json picture_facts(const WallStressPicture& p) {
  return {{"frame", p.frame},
          {"quantity", "maximum principal Cauchy stress"},
          {"unit", "kPa"},
          {"colour_map", "viridis"},
          {"colour_bar_kpa", {p.colour_bar_kpa[0], p.colour_bar_kpa[1]}},
          {"colour_bar", "2nd to 98th area percentile of sigma1; below it black, above it pink"},
          {"view", "anterior: camera on -y (LPS), head up, patient right on the left"},
          {"outlet", "grey, left out of the numbers"},
          {"summary", to_json(p.summary)}};
}

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

void render_wall_stress_png(const fs::path& vtu, const fs::path& png, int width, int height) {
  const WallStressField field = read_wall_stress_field(vtu);
  const WallStressSummary summary = summarize(field);
  if (summary.triangles == 0) fail(vtu.string(), "every triangle is outlet: no wall stress");
  const auto range = colour_bar_range(summary);
  vtkNew<vtkPolyData> poly = wall_polydata(field);
  vtkNew<vtkLookupTable> lut = viridis_table(range);

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  mapper->SetScalarModeToUseCellFieldData();
  mapper->SelectColorArray("sigma1_kpa");
  mapper->SetLookupTable(lut);
  mapper->SetScalarRange(range[0], range[1]);
  mapper->ScalarVisibilityOn();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  // The colour map's own colours: lighting would darken them into other values.
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);
  actor->GetProperty()->SetSpecular(0.0);

  vtkNew<vtkRenderer> model;
  model->SetViewport(0.0, 0.0, 0.78, 1.0);
  model->SetBackground(1, 1, 1);
  model->AddActor(actor);
  look_from_front(model, poly);
  add_patient_directions(model, state_line(summary));
  if (summary.outlet_mm) add_outlet_label(model, *summary.outlet_mm, poly);
  vtkNew<vtkRenderer> bar = colour_bar(lut);

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(model);
  window->AddRenderer(bar);
  window->SetSize(width, height);
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->Update();

  nlohmann::json facts = {
      {"frame", vtu.filename().string()},
      {"quantity", "maximum principal Cauchy stress"},
      {"unit", "kPa"},
      {"colour_map", "viridis"},
      {"colour_bar_kpa", {range[0], range[1]}},
      {"colour_bar", "2nd to 98th area percentile of sigma1; below it black, above it pink"},
      {"view", "anterior: camera on -y (LPS), head up, patient right on the left"},
      {"outlet", "grey, left out of the numbers"},
      {"summary", to_json(summary)}};
  char bar_text[64];
  std::snprintf(bar_text, sizeof bar_text, "%.9g %.9g", range[0], range[1]);
  write_atomically(png, [&](const fs::path& tmp) {
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName(tmp.c_str());
    writer->SetInputConnection(grab->GetOutputPort());
    writer->AddText("vesica:colour_bar_kpa", bar_text);
    writer->Write();
  });
}

WallStressPicture make_wall_stress_picture(const fs::path& vtu, const fs::path& executable) {
  WallStressPicture pic;
  if (!fs::exists(vtu)) {
    pic.message = "no wall-stress picture: frame " + vtu.string() + " not found";
    return pic;
  }
  pic.frame = vtu.filename().string();
  try {
    pic.summary = summarize(read_wall_stress_field(vtu));
  } catch (const Error& e) {
    pic.message = std::string("no wall-stress picture: ") + e.what();
    return pic;
  }
  pic.colour_bar_kpa = colour_bar_range(pic.summary);
  // The renderer runs as a child (VTK's off-screen window may abort the process), without
  // a shell, writing into a folder only this process made.
  std::vector<std::string> argv = {executable.string(), "--render-wall-stress", vtu.string(),
                                   "--render-png"};
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display) {
    if (!find_program("xvfb-run")) {
      pic.message = "no wall-stress picture: no X display and xvfb-run is not installed";
      return pic;
    }
    argv.insert(argv.begin(), {"xvfb-run", "-a"});
  }
  const TemporaryFolder dir("compare");
  const fs::path png = dir.path() / "wall-stress.png";
  argv.push_back(png.string());
  const HelperResult run = run_helper(argv, dir.path() / "render.log", kRenderDeadline);
  std::error_code ec;
  const std::string bytes = fs::is_regular_file(png, ec) ? read_bytes(png) : std::string();
  if (run.exit_code != 0 || bytes.size() < 8) {
    std::string out = run.timed_out
                          ? "no picture within " + std::to_string(kRenderDeadline.count()) + " s"
                          : run.output;
    if (out.size() > 300) out = out.substr(out.size() - 300);
    pic.message = "no wall-stress picture: off-screen rendering failed (" + out + ")";
    return pic;
  }
  pic.png = bytes;
  pic.message = frame_caption(pic);
  return pic;
}

}  // namespace vesica::compare
