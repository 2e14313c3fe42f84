// study.csv and study.html from a real, small study (vesica-surface pouch shapes, coarse
// meshes, vesica-mesh, vesica-simulate), run once for the suite. Checks against physical
// truths rather than earlier output: at equal volume a stiffer wall has a higher pressure;
// a pouch built larger has a lower pressure at 500 ml; and the runner's promises: a
// second run does nothing, a changed variant reruns only its own stages. The page must
// load in headless chromium without console errors.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "PipelineTestSupport.h"
#include "vesica/pipelines/CystometryCurve.h"

namespace fs = std::filesystem;
using namespace vesica::test;
using vesica::pipelines::CystometryCurve;

namespace {

// Volumes in ml, moduli in kPa; ~540 triangles a pouch. `soft` and `stiff` share the
// surface and mesh; `large` (built at 350 ml) and `oblong` (elongation 1.3) have their own.
// Pouches are built at 250 ml or more so that 500 ml stays below the neo-Hookean limit-point
// stretch (7^(1/6) ~ 1.38, physics.md §6) where today's level-1 run still converges, and
// voiding stops after 5 s (max_void_s), before the wall goes slack below its stress-free
// volume (wrinkling, not handled yet).
std::string study_yaml(const std::string& stiff_mu_kpa) {
  return "pipeline: small-study\n"
         "workdir: out\n"
         "stages:\n"
         "  surface: {output: pouch.vtp,\n"
         "            params: {shape: pouch, volume_ml: 250, elongation: 1, edge_mm: 10}}\n"
         "  mesh: {input: pouch.vtp, output: pouch.msh, params: {thickness_mm: 3}}\n"
         "  simulate:\n"
         "    input: pouch.msh\n"
         "    output: sim\n"
         "    params: {material: neo-hookean, mu_kpa: 1, residual_ml: 250,\n"
         "             start_ml: 250, capacity_ml: 500, fill_rate_ml_min: 50,\n"
         "             straining_kpa: 3.6, max_void_s: 5, no_series: true}\n"
         "study:\n"
         "  variants:\n"
         "    soft: {simulate.mu_kpa: 1}\n"
         "    stiff: {simulate.mu_kpa: " +
         stiff_mu_kpa +
         "}\n"
         "    large: {surface.volume_ml: 350, simulate.residual_ml: 350, simulate.start_ml: 350}\n"
         "    oblong: {surface.elongation: 1.3}\n";
}

// study.csv as variant -> column -> cell.
std::map<std::string, std::map<std::string, std::string>> read_table(const fs::path& csv) {
  std::istringstream in(slurp(csv));
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::stringstream hs(line);
  for (std::string cell; std::getline(hs, cell, ',');) header.push_back(cell);
  std::map<std::string, std::map<std::string, std::string>> table;
  while (std::getline(in, line)) {
    std::stringstream ls(line);
    std::map<std::string, std::string> row;
    std::size_t i = 0;
    for (std::string cell; i < header.size() && std::getline(ls, cell, ',');)
      row[header[i++]] = cell;
    table[row["variant"]] = row;
  }
  return table;
}

double number(const std::map<std::string, std::string>& row, const std::string& column) {
  const auto it = row.find(column);
  if (it == row.end() || it->second.empty()) return std::nan("");
  return std::stod(it->second);
}

class StudyOutputs : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(scratch_dir("study-outputs"));
    write_text(*dir_ / "study.yaml", study_yaml("2"));
    first_run_ = new Ids(run_json(*dir_ / "study.yaml", *dir_, "-j 2 --keep-going", &exit_code_));
  }
  static void TearDownTestSuite() {
    delete dir_;
    delete first_run_;
  }
  static fs::path out() { return *dir_ / "out"; }
  static CystometryCurve curve(const std::string& variant) {
    return vesica::pipelines::read_history_csv(out() / "variants" / variant / "sim/history.csv");
  }

  static fs::path* dir_;
  static Ids* first_run_;
  static int exit_code_;
};
fs::path* StudyOutputs::dir_ = nullptr;
Ids* StudyOutputs::first_run_ = nullptr;
int StudyOutputs::exit_code_ = -1;

}  // namespace

TEST_F(StudyOutputs, TableHasEveryVariantAndItsReadOuts) {
  // shared surface + mesh; soft/stiff: simulate; large/oblong: surface, mesh, simulate.
  EXPECT_EQ(first_run_->size(), 10u) << ::testing::PrintToString(*first_run_);
  EXPECT_EQ(exit_code_, 0) << slurp(out() / "study.csv");
  const auto table = read_table(out() / "study.csv");
  ASSERT_EQ(table.size(), 4u) << slurp(out() / "study.csv");
  for (const auto& [variant, row] : table) {
    EXPECT_EQ(row.at("status"), "ok") << variant << ": " << row.at("failure");
    // filled to 500 ml: both read-outs exist; 40 cmH2O is either reached or "> max".
    EXPECT_FALSE(std::isnan(number(row, "pdet_at_500ml_cmh2o"))) << variant;
    // `large` starts filling at 350 ml: it has no Pdet at 300 ml.
    EXPECT_EQ(std::isnan(number(row, "pdet_at_300ml_cmh2o")), variant == "large") << variant;
    EXPECT_FALSE(row.at("capacity_at_40cmh2o_ml").empty()) << variant;
    EXPECT_GE(number(row, "max_pdet_cmh2o"), number(row, "pdet_at_500ml_cmh2o")) << variant;
    EXPECT_GT(number(row, "max_wall_stress_kpa"), 0.0) << variant;
  }
  // The varied parameters are columns, the shared ones are not.
  const std::string header = slurp(out() / "study.csv").substr(0, 200);
  EXPECT_EQ(header.rfind("variant,status,surface.volume_ml,surface.elongation,simulate.mu_kpa,", 0),
            0u)
      << header;
  EXPECT_EQ(header.find("simulate.k_kpa"), std::string::npos);
}

TEST_F(StudyOutputs, StifferWallHasHigherPressureAtEqualVolume) {
  const CystometryCurve soft = curve("soft"), stiff = curve("stiff");
  for (double v : {300.0, 400.0, 500.0}) {
    const auto ps = vesica::pipelines::filling_pdet_at_volume(soft, v);
    const auto pt = vesica::pipelines::filling_pdet_at_volume(stiff, v);
    ASSERT_TRUE(ps && pt) << v << " ml not reached";
    EXPECT_GT(*pt, *ps) << "at " << v << " ml";
    std::printf("[ monotonic ] %g ml: Pdet soft (mu 1 kPa) %.3f, stiff (mu 2 kPa) %.3f cmH2O\n", v,
                *ps, *pt);
  }
}

TEST_F(StudyOutputs, LargerInitialCapacityHasLowerPressureAt500ml) {
  const auto table = read_table(out() / "study.csv");
  const double built250 = number(table.at("soft"), "pdet_at_500ml_cmh2o");
  const double built350 = number(table.at("large"), "pdet_at_500ml_cmh2o");
  std::printf("[ monotonic ] Pdet at 500 ml: built at 250 ml %.3f, at 350 ml %.3f cmH2O\n",
              built250, built350);
  EXPECT_LT(built350, built250);
}

TEST_F(StudyOutputs, PageOpensInHeadlessChromiumWithoutErrors) {
  if (std::system("command -v chromium > /dev/null 2>&1") != 0) {
    if (running_in_ci()) FAIL() << "chromium is not installed";
    GTEST_SKIP() << "chromium is not installed";
  }
  const fs::path page = out() / "study.html";
  ASSERT_TRUE(fs::exists(page));
  const auto dom = run_command(
      "timeout 120 chromium --headless --no-sandbox --disable-gpu "
      "--disable-background-networking --disable-component-update --no-first-run "
      "--disable-dev-shm-usage --virtual-time-budget=3000 --user-data-dir=" +
          quoted((*dir_ / "profile").string()) + " --enable-logging=stderr --v=0 --dump-dom " +
          quoted("file://" + page.string()),
      *dir_);
  ASSERT_EQ(dom.exit_code, 0) << dom.err;
  const std::string log = dom.out + dom.err;
  EXPECT_EQ(log.find("Uncaught"), std::string::npos) << log;
  EXPECT_FALSE(std::regex_search(log, std::regex("CONSOLE.*[Ee]rror"))) << log;
  EXPECT_NE(dom.out.find("<pre id=\"js-errors\"></pre>"), std::string::npos);
  EXPECT_NE(dom.out.find("plots=3 drawn=3"), std::string::npos) << dom.out.substr(0, 3000);
  for (const char* variant : {"soft", "stiff", "large", "oblong"})
    EXPECT_NE(dom.out.find(std::string("<td>") + variant + "</td>"), std::string::npos) << variant;
}

// Last in the suite: it changes the study.
TEST_F(StudyOutputs, SecondRunDoesNothingAndAChangedVariantRerunsOnlyItsStages) {
  const auto csv_time = fs::last_write_time(out() / "study.csv");
  EXPECT_EQ(run_json(*dir_ / "study.yaml", *dir_, "-j 2"), Ids{});
  EXPECT_EQ(fs::last_write_time(out() / "study.csv"), csv_time);  // not rewritten

  const auto first = read_table(out() / "study.csv");
  const double soft = number(first.at("soft"), "pdet_at_300ml_cmh2o");
  const double mu2 = number(first.at("stiff"), "pdet_at_300ml_cmh2o");
  write_text(*dir_ / "study.yaml", study_yaml("1.5"));
  EXPECT_EQ(run_json(*dir_ / "study.yaml", *dir_, "-j 2"), Ids{"simulate@stiff"});
  const auto table = read_table(out() / "study.csv");
  EXPECT_EQ(table.at("stiff").at("simulate.mu_kpa"), "1.5");
  // mu 1 < 1.5 < 2 kPa: the new pressure lies between the two earlier ones.
  const double mu15 = number(table.at("stiff"), "pdet_at_300ml_cmh2o");
  EXPECT_GT(mu15, soft);
  EXPECT_LT(mu15, mu2);
}
