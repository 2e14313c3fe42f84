// The wall series as ParaView meets it: every step carries its time, volume and Pdet as
// numeric field data (read back with VTK's own reader), and view.py beside the series is
// valid Python that opens the step of largest volume. With a pvpython (on PATH, or named by
// $VESICA_PVPYTHON) the script runs and saves its view into build/test-artefacts; Debian's
// python3-paraview conflicts with python3-vtk9, which the build needs, so it is usually
// absent and the test says so.
#include <gtest/gtest.h>

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

#include "OctahedronMesh.h"
#include "ShellCommand.h"
#include "TestData.h"
#include "vesica/io/PvdSeries.h"

namespace vesica::test {
namespace {

namespace fs = std::filesystem;

double field_value(vtkUnstructuredGrid* grid, const char* name) {
  auto* a = vtkDoubleArray::SafeDownCast(grid->GetFieldData()->GetArray(name));
  return a && a->GetNumberOfTuples() == 1 ? a->GetValue(0) : std::nan("");
}

// Three steps of the octahedron: volume 100, 300, 200 ml at t = 0, 10, 20 s.
fs::path write_series(const fs::path& dir) {
  const io::VolumeMesh m = octahedron_mesh();
  io::PvdSeries series(dir, "series");
  series.set_paraview_script(
      {"cauchy_principal_kpa", 0, "max principal Cauchy stress (kPa)", "region", 2});
  const double volume[] = {100, 300, 200}, pdet[] = {1, 4, 3};
  for (int step = 0; step < 3; ++step) {
    io::VtuGrid frame;
    frame.points_mm = m.nodes * (1.0 + 0.1 * step);
    frame.triangles = m.triangles;
    io::VtuArray stress{"cauchy_principal_kpa", 2, {}, false};
    io::VtuArray region{"region", 1, {}, true};
    // σ1 = 2..9 kPa; the last triangle (9 kPa) is the outlet cap, region 2
    for (int t = 0; t < 8; ++t) {
      stress.values.insert(stress.values.end(), {2.0 + t, 1.0});
      region.values.push_back(t == 7 ? 2 : 1);
    }
    frame.cell_data = {stress, region};
    frame.field_data = {{"volume_ml", 1, {volume[step]}, false},
                        {"pdet_cmh2o", 1, {pdet[step]}, false}};
    series.add_step(10.0 * step, frame);
  }
  series.finish();
  return series.pvd_path();
}

std::string pvpython() {
  if (const char* env = std::getenv("VESICA_PVPYTHON")) return env;
  return run_command("command -v pvpython").exit_code == 0 ? "pvpython" : "";
}

TEST(ParaViewSeries, EveryStepCarriesItsTimeVolumeAndPdetAsNumbers) {
  const fs::path dir = scratch_dir("io-paraview-series");
  write_series(dir);
  const double volume[] = {100, 300, 200}, pdet[] = {1, 4, 3};
  for (int step = 0; step < 3; ++step) {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    const fs::path vtu = dir / "series" / ("step_000" + std::to_string(step) + ".vtu");
    reader->SetFileName(vtu.c_str());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    EXPECT_EQ(field_value(grid, "time_s"), 10.0 * step) << vtu;
    EXPECT_EQ(field_value(grid, "volume_ml"), volume[step]) << vtu;
    EXPECT_EQ(field_value(grid, "pdet_cmh2o"), pdet[step]) << vtu;
  }
  // vesica's own reader gives them back too.
  const io::VtuGrid back = io::read_vtu(dir / "series/step_0001.vtu");
  ASSERT_NE(back.field_array("volume_ml"), nullptr);
  EXPECT_EQ(back.field_array("volume_ml")->values, std::vector<double>{300.0});
}

TEST(ParaViewSeries, ViewScriptIsPythonThatOpensTheStepOfLargestVolume) {
  const fs::path dir = scratch_dir("io-paraview-script");
  write_series(dir);
  const fs::path script = dir / "view.py";
  ASSERT_TRUE(fs::exists(script));
  std::ifstream in(script);
  std::stringstream text;
  text << in.rdbuf();
  std::smatch open_at;
  const std::string s = text.str();
  ASSERT_TRUE(std::regex_search(s, open_at, std::regex("\nOPEN_AT = ([0-9.]+)")));
  EXPECT_EQ(std::stod(open_at[1]), 10.0);  // the 300 ml step
  EXPECT_NE(s.find("ARRAY = \"cauchy_principal_kpa\""), std::string::npos);
  EXPECT_NE(s.find("LEFT_OUT = (\"region\", 2)"), std::string::npos);
  const auto compiled = run_command("/usr/bin/python3 -m py_compile " + script.string());
  EXPECT_EQ(compiled.exit_code, 0) << compiled.output;

  const std::string pv = pvpython();
  if (pv.empty()) {
    std::printf(
        "[ paraview ] no pvpython (python3-paraview conflicts with python3-vtk9): "
        "view.py compiled, not run\n");
    return;
  }
  const fs::path shot = artefact_dir("paraview-view") / "view.png";
  const bool display = std::getenv("DISPLAY") && *std::getenv("DISPLAY");
  const auto run = run_command("cd " + dir.string() + " && timeout 300 " +
                               (display || std::getenv("VESICA_PVPYTHON") ? "" : "xvfb-run -a ") +
                               pv + " view.py --screenshot " + shot.string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_GT(fs::exists(shot) ? fs::file_size(shot) : 0u, 1000u) << run.output;
  // the colour bar spans the wall's σ1, 2..8 kPa: the outlet cap's 9 kPa is left out
  std::smatch bar;
  ASSERT_TRUE(std::regex_search(run.output, bar, std::regex("colour bar: ([^ ]+) ([^\\s]+)")))
      << run.output;
  EXPECT_DOUBLE_EQ(std::stod(bar[1]), 2.0);
  EXPECT_DOUBLE_EQ(std::stod(bar[2]), 8.0);
}

}  // namespace
}  // namespace vesica::test
