// The report in a real browser: Debian's chromium, headless, loads index.html; the DOM
// after load must hold every plot with drawn marks, no script error, the embedded
// wall-stress picture; the screenshot must not be blank.
#include <regex>
#include <set>

#include <gtest/gtest.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include "CompareTestSupport.h"

namespace fs = std::filesystem;
using namespace vesica::test;

namespace {

std::string chromium(const fs::path& profile) {
  return "timeout 120 chromium --headless --no-sandbox --disable-gpu "
         "--disable-background-networking --disable-component-update --no-first-run "
         "--disable-dev-shm-usage --hide-scrollbars --virtual-time-budget=3000 "
         "--user-data-dir=" +
         profile.string();
}

// Fraction of pixels that are not (near) white, and whether several colours occur.
struct Ink {
  double fraction = 0;
  int colours = 0;
};
Ink ink_of(const fs::path& png) {
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(png.c_str());
  reader->Update();
  auto* img = reader->GetOutput();
  auto* px = vtkUnsignedCharArray::SafeDownCast(img->GetPointData()->GetScalars());
  Ink ink;
  if (!px) return ink;
  const int nc = px->GetNumberOfComponents();
  std::set<int> colours;
  long inked = 0;
  for (vtkIdType i = 0; i < px->GetNumberOfTuples(); ++i) {
    const int r = px->GetValue(i * nc), g = px->GetValue(i * nc + 1), b = px->GetValue(i * nc + 2);
    if (r + g + b < 720) ++inked;
    if (colours.size() < 1000) colours.insert((r / 16) * 256 + (g / 16) * 16 + b / 16);
  }
  ink.fraction = double(inked) / px->GetNumberOfTuples();
  ink.colours = static_cast<int>(colours.size());
  return ink;
}

}  // namespace

TEST(ReportBrowser, EveryPlotRendersWithoutErrors) {
  if (run_command("command -v chromium").exit_code != 0) {
    if (running_in_ci()) FAIL() << "chromium is not installed";
    GTEST_SKIP() << "chromium is not installed";
  }
  const fs::path dir = scratch_dir("compare-browser");
  write_stress_sphere(dir / "wall.vtu");
  const auto run =
      run_command(compare_exe() + " --measured " + compare_data("normal-female-34y.csv").string() +
                  " --simulated " + compare_data("synthetic-history.csv").string() + " --mesh " +
                  (dir / "wall.vtu").string() + " -o " + (dir / "report").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const fs::path page = dir / "report" / "index.html";

  const auto dom = run_command(chromium(dir / "profile1") +
                               " --enable-logging=stderr --v=0 --dump-dom file://" + page.string());
  ASSERT_EQ(dom.exit_code, 0) << dom.output;
  EXPECT_EQ(dom.output.find("Uncaught"), std::string::npos) << dom.output;
  EXPECT_FALSE(std::regex_search(dom.output, std::regex("CONSOLE.*[Ee]rror"))) << dom.output;
  EXPECT_NE(dom.output.find("<pre id=\"js-errors\"></pre>"), std::string::npos);
  // the page's load handler counted the plots with visible series
  EXPECT_NE(dom.output.find("plots=4 drawn=4"), std::string::npos) << dom.output.substr(0, 2000);
  for (const char* id : {"plot-filling", "plot-volume", "plot-flow", "plot-pressure-flow"}) {
    const auto at = dom.output.find(std::string("id=\"") + id + "\"");
    ASSERT_NE(at, std::string::npos) << id;
    const auto end = dom.output.find("</svg>", at);
    const std::string svg = dom.output.substr(at, end - at);
    EXPECT_TRUE(svg.find("class=\"series\"") != std::string::npos) << id << " has no data";
  }
  EXPECT_NE(dom.output.find("id=\"wall-stress\""), std::string::npos)
      << "no embedded wall-stress picture";

  const fs::path shot = dir / "shot.png";
  const auto s = run_command(chromium(dir / "profile2") + " --window-size=1200,2400 --screenshot=" +
                             shot.string() + " file://" + page.string());
  ASSERT_EQ(s.exit_code, 0) << s.output;
  ASSERT_TRUE(fs::exists(shot)) << s.output;
  const Ink ink = ink_of(shot);
  EXPECT_GT(ink.fraction, 0.02);
  EXPECT_GT(ink.colours, 8);
}
