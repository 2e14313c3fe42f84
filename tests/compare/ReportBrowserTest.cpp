// The report in a real browser, as a urologist opens it: Debian's chromium, headless, in a
// 1280-px window. After load the page must hold the trace, the three plots (each with drawn
// data), the parameter and criteria tables and the wall-stress picture; no script error;
// no element wider than the window; no debug text. report.pdf, printed by the same
// chromium, must be a PDF of several A4 pages. The interactive wall (WebGL through
// SwiftShader, as a machine without a GPU draws it) must draw, and its time slider move the
// trace's cursor. The screenshots, the pages and the PDF stay in build/test-artefacts/report*
// for a look (a folder per test: ctest runs them side by side, and each empties its own).
#include <regex>
#include <set>

#include <gtest/gtest.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include "CompareTestSupport.h"
#include "vesica/io/PvdSeries.h"

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

// WebGL without a GPU: Chromium's software renderer, which it only uses when told.
const char* kSoftwareWebGl = " --use-gl=angle --use-angle=swiftshader --enable-unsafe-swiftshader";

#define VESICA_REQUIRE_CHROMIUM()                               \
  if (run_command("command -v chromium").exit_code != 0) {      \
    if (running_in_ci()) FAIL() << "chromium is not installed"; \
    GTEST_SKIP() << "chromium is not installed";                \
  }

// The DOM of `page` after its scripts ran with `check` as the address's fragment (the
// viewer's self-checks), in a 1280 x 900 window with software WebGL; the console on stderr.
CommandResult dom_after_check(const fs::path& page, const fs::path& profile,
                              const std::string& check) {
  return run_command(chromium(profile) + kSoftwareWebGl +
                     " --window-size=1280,900 --enable-logging=stderr --v=0 --dump-dom 'file://" +
                     page.string() + "#" + check + "'");
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

// The value of a data-* attribute of <body> in the dumped DOM.
std::string body_data(const std::string& dom, const std::string& name) {
  std::smatch m;
  const std::regex re("<body[^>]*\\sdata-" + name + "=\"([^\"]*)\"");
  return std::regex_search(dom, m, re) ? m[1].str() : "";
}

}  // namespace

TEST(ReportBrowser, TheReportFitsA1280WindowWithEveryPartDrawnAndPrints) {
  VESICA_REQUIRE_CHROMIUM();
  const fs::path dir = scratch_dir("compare-browser");
  write_stress_sphere(dir / "wall.vtu");
  const auto run =
      run_command(compare_exe() + " --measured " + compare_data("normal-female-34y.csv").string() +
                  " --simulated " + compare_data("synthetic-history.csv").string() + " --mesh " +
                  (dir / "wall.vtu").string() + " -o " + (dir / "report").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const fs::path page = dir / "report" / "index.html";
  const fs::path keep = artefact_dir("report");
  fs::copy_file(page, keep / "index.html");

  const auto dom = run_command(chromium(dir / "profile1") +
                               " --window-size=1280,900 --enable-logging=stderr --v=0 "
                               "--dump-dom file://" +
                               page.string());
  ASSERT_EQ(dom.exit_code, 0) << dom.output;
  EXPECT_EQ(dom.output.find("Uncaught"), std::string::npos) << dom.output;
  EXPECT_FALSE(std::regex_search(dom.output, std::regex("CONSOLE.*[Ee]rror"))) << dom.output;
  EXPECT_NE(dom.output.find("<pre id=\"js-errors\" hidden=\"\"></pre>"), std::string::npos);
  // every plot drew its data; nothing sticks out of the 1280-px window
  EXPECT_EQ(body_data(dom.output, "plots"), "4") << dom.output.substr(0, 3000);
  EXPECT_EQ(body_data(dom.output, "drawn"), "4");
  EXPECT_EQ(body_data(dom.output, "overflowing"), "0");
  EXPECT_EQ(body_data(dom.output, "window-width"), "1280");
  EXPECT_EQ(body_data(dom.output, "scroll-width"), "1280");
  for (const char* id : {"plot-trace", "plot-filling", "plot-flow", "plot-pressure-flow"}) {
    const auto at = dom.output.find(std::string("id=\"") + id + "\"");
    ASSERT_NE(at, std::string::npos) << id;
    const std::string svg = dom.output.substr(at, dom.output.find("</svg>", at) - at);
    EXPECT_NE(svg.find("class=\"series\""), std::string::npos) << id << " has no data";
  }
  for (const char* id :
       {"id=\"parameters\"", "id=\"criteria\"", "id=\"wall-stress\"", "id=\"wall-stress-numbers\""})
    EXPECT_NE(dom.output.find(id), std::string::npos) << id;
  // no debug text such as the former "plots=4 drawn=4"
  EXPECT_FALSE(std::regex_search(dom.output, std::regex("(plots|drawn)=[0-9]")));
  // the pressure-flow axes fit the data (Pdet up to 18 cmH2O), not a fixed 150
  const auto pf = dom.output.find("id=\"plot-pressure-flow\"");
  const std::string pf_svg = dom.output.substr(pf, dom.output.find("</svg>", pf) - pf);
  EXPECT_EQ(pf_svg.find(">150<"), std::string::npos);

  const fs::path shot = keep / "report-1280.png";
  const auto s = run_command(chromium(dir / "profile2") + " --window-size=1280,4200 --screenshot=" +
                             shot.string() + " file://" + page.string());
  ASSERT_EQ(s.exit_code, 0) << s.output;
  ASSERT_TRUE(fs::exists(shot)) << s.output;
  const Ink ink = ink_of(shot);
  EXPECT_GT(ink.fraction, 0.02);
  EXPECT_GT(ink.colours, 8);

  const fs::path pdf = dir / "report" / "report.pdf";
  ASSERT_TRUE(fs::exists(pdf)) << read_text(dir / "report" / "metrics.json");
  fs::copy_file(pdf, keep / "report.pdf");
  const std::string bytes = read_text(pdf);
  EXPECT_EQ(bytes.rfind("%PDF-", 0), 0u);
  std::smatch pages;
  ASSERT_TRUE(std::regex_search(bytes, pages, std::regex("/Count ([0-9]+)")));
  EXPECT_GE(std::stoi(pages[1]), 2);
  EXPECT_NE(bytes.find("/MediaBox [0 0 594.9"), std::string::npos) << "not A4";
}

// A simulation with its series: five frames of the stress sphere over filling and voiding.
TEST(ReportBrowser, TheInteractiveWallDrawsAndItsSliderMovesTheTraceCursor) {
  VESICA_REQUIRE_CHROMIUM();
  const fs::path dir = scratch_dir("compare-browser-wall3d");
  fs::create_directories(dir / "sim/series");
  std::vector<std::pair<double, std::string>> steps;
  for (int k = 0; k < 5; ++k) {
    const std::string file = "series/step_000" + std::to_string(k) + ".vtu";
    write_stress_sphere(dir / "sim" / file);
    steps.emplace_back(std::vector<double>{0, 100, 200, 360, 390}[k], file);
  }
  std::ofstream(dir / "sim/series.pvd") << vesica::io::pvd_text(steps);
  fs::copy_file(compare_data("synthetic-history.csv"), dir / "sim/history.csv");
  const auto run = run_command(
      compare_exe() + " --measured " + compare_data("normal-female-34y.csv").string() +
      " --simulated " + (dir / "sim/history.csv").string() + " -o " + (dir / "report").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const fs::path page = dir / "report" / "index.html";
  const std::string html = read_text(page);
  ASSERT_NE(html.find("id=\"wall3d-canvas\""), std::string::npos) << "no interactive wall";
  EXPECT_EQ(html.find("<script src="), std::string::npos) << "the page must fetch nothing";
  const fs::path keep = artefact_dir("report-wall3d");  // each test its own: they run side by side
  fs::copy_file(page, keep / "index-wall3d.html", fs::copy_options::overwrite_existing);

  const auto dom = dom_after_check(page, dir / "profile1", "check-slider");
  ASSERT_EQ(dom.exit_code, 0) << dom.output;
  EXPECT_EQ(dom.output.find("Uncaught"), std::string::npos) << dom.output;
  EXPECT_NE(dom.output.find("<pre id=\"js-errors\" hidden=\"\"></pre>"), std::string::npos);
  EXPECT_EQ(body_data(dom.output, "overflowing"), "0");
  const std::string ink = body_data(dom.output, "wall3d-ink");
  ASSERT_FALSE(ink.empty()) << dom.output.substr(0, 3000);
  EXPECT_GT(std::stod(ink), 0.05) << "the canvas is blank";
  // The slider's ends: the first frame (t = 0 s) and the last (390 s) put the cursor at the
  // trace's left and further right; the capacity frame (360 s) is labelled as such.
  EXPECT_EQ(body_data(dom.output, "wall3d-capacity-label").rfind("nearest capacity: t = 360 s", 0),
            0u)
      << body_data(dom.output, "wall3d-capacity-label");
  const double first = std::stod(body_data(dom.output, "wall3d-first-cursor"));
  const double last = std::stod(body_data(dom.output, "wall3d-last-cursor"));
  const double capacity = std::stod(body_data(dom.output, "wall3d-capacity-cursor"));
  EXPECT_LT(first, capacity);
  EXPECT_LT(capacity, last);
  EXPECT_EQ(body_data(dom.output, "wall3d-last-label").rfind("t = 390 s", 0), 0u);

  const fs::path shot = keep / "report-wall3d-1280.png";
  const auto s = run_command(chromium(dir / "profile2") + kSoftwareWebGl +
                             " --window-size=1280,4200 --screenshot=" + shot.string() + " file://" +
                             page.string());
  ASSERT_EQ(s.exit_code, 0) << s.output;
  EXPECT_GT(ink_of(shot).colours, 8);
}

// A level-2 run's frames: the wall, and the urine on its fluid mesh, whose velocity grows
// with the voiding (u = (0, 0, k z), k up to 200/s: 2 m/s on the section's top and bottom).
// Choosing the urine's speed draws its section inside a faint wall, on a colour bar from 0
// to that largest speed.
TEST(ReportBrowser, ALevelTwoRunShowsTheUrineSpeedInsideTheWall) {
  VESICA_REQUIRE_CHROMIUM();
  const fs::path dir = scratch_dir("compare-browser-urine");
  fs::create_directories(dir / "sim/series");
  fs::create_directories(dir / "sim/fluid");
  std::vector<std::pair<double, std::string>> steps, fluid;
  const double times[] = {0, 100, 200, 360, 390}, k[] = {0, 0, 0, 50, 200};
  for (int i = 0; i < 5; ++i) {
    const std::string n = std::to_string(i);
    write_stress_sphere(dir / "sim/series" / ("step_000" + n + ".vtu"));
    write_fluid_box(dir / "sim/fluid" / ("fluid_000" + n + ".vtu"), k[i]);
    steps.emplace_back(times[i], "series/step_000" + n + ".vtu");
    fluid.emplace_back(times[i], "fluid/fluid_000" + n + ".vtu");
  }
  std::ofstream(dir / "sim/series.pvd") << vesica::io::pvd_text(steps);
  std::ofstream(dir / "sim/fluid.pvd") << vesica::io::pvd_text(fluid);
  fs::copy_file(compare_data("synthetic-history.csv"), dir / "sim/history.csv");
  const auto run =
      run_command(compare_exe() + " --simulated " + (dir / "sim/history.csv").string() + " -o " +
                  (dir / "report").string() + " --no-pdf");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const fs::path page = dir / "report" / "index.html";
  const std::string html = read_text(page);
  ASSERT_NE(html.find("<option value=\"speed\">"), std::string::npos) << "no urine speed to choose";
  fs::copy_file(page, artefact_dir("report-urine") / "index-urine.html",
                fs::copy_options::overwrite_existing);

  const auto dom = dom_after_check(page, dir / "profile", "check-urine");
  ASSERT_EQ(dom.exit_code, 0) << dom.output;
  EXPECT_EQ(dom.output.find("Uncaught"), std::string::npos) << dom.output;
  EXPECT_NE(dom.output.find("<pre id=\"js-errors\" hidden=\"\"></pre>"), std::string::npos);
  EXPECT_EQ(body_data(dom.output, "wall3d-urine-frames"), "5");
  const std::string ink = body_data(dom.output, "wall3d-urine-ink");
  ASSERT_FALSE(ink.empty()) << dom.output.substr(0, 3000);
  EXPECT_GT(std::stod(ink), 0.01) << "the urine's section is not drawn";
  EXPECT_EQ(body_data(dom.output, "wall3d-urine-bar").rfind("urine speed |u| (m/s) 0 to 2.00 ", 0),
            0u)
      << body_data(dom.output, "wall3d-urine-bar");
}
