// Calibration through vesica-compare --calibrate (simulations in process): the shear
// modulus on the real bladder geometry (the CT reference label of ../shared -> closed
// surface of ~1,200 triangles -> wall) fitted to the shared recording's filling; the whole
// recording (filling and voiding); the two table formats without time; and a fit that
// starts from the default wall and hands its model on as a card.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "CompareTestSupport.h"

namespace fs = std::filesystem;
using namespace vesica::test;

namespace {

// The thesis's one-parameter wall, stress-free at the 50 ml the fits start from: what these
// fits of mu alone are about (the default is the bladder wall, stress-free at 20 ml).
const std::string kNeoHookeanAtTheStart = " --material neo-hookean --residual-ml 50";

std::string surface_exe() {
  return (bin_dir() / "vesica-surface").string();
}

// A 50 ml sphere of about 270 triangles: a wall whose runs take a fraction of a second.
fs::path small_sphere(const fs::path& dir) {
  const fs::path vtp = dir / "sphere.vtp";
  const auto r =
      run_command(surface_exe() + " --shape sphere --volume-ml 50 --edge-mm 8 -o " + vtp.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return vtp;
}

nlohmann::json calibrate(const std::string& arguments, const fs::path& dir) {
  const auto r = run_command(compare_exe() + " " + arguments + " -o " + (dir / "report").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  if (r.exit_code != 0) return {};
  return nlohmann::json::parse(read_text(dir / "report" / "metrics.json"))["calibration"];
}

const nlohmann::json* series(const nlohmann::json& c, const std::string& name) {
  for (const auto& s : c["series"])
    if (s["name"] == name) return &s;
  return nullptr;
}

bool has_note(const nlohmann::json& c, const std::string& text) {
  for (const auto& n : c["notes"])
    if (n.get<std::string>().find(text) != std::string::npos) return true;
  return false;
}

// Every fitted parameter either identifiable with an interval around its value, or not,
// with a reason and its search range as the interval.
void expect_honest_parameters(const nlohmann::json& c) {
  for (const auto& p : c["parameters"]) {
    const double v = p["value"].get<double>();
    EXPECT_LE(p["ci95_low"].get<double>(), v) << p;
    EXPECT_GE(p["ci95_high"].get<double>(), v) << p;
    if (p["identifiable"].get<bool>()) {
      EXPECT_LT(p["ci95_low"].get<double>(), p["ci95_high"].get<double>()) << p;
    } else {
      EXPECT_FALSE(p["note"].get<std::string>().empty()) << p;
    }
  }
}

}  // namespace

TEST(Calibration, ShearModulusOnTheRealBladderFitsTheFillingCurve) {
  VESICA_REQUIRE_SHARED(label, "data/ct/abdomen-3mm/bladder-reference.nii.gz");
  const fs::path dir = scratch_dir("compare-calibration");
  // ~1,200 triangles: the filling curve is mesh-converged there (Pdet at 350 ml within
  // 0.3 % of a 2,474-triangle wall) and each of the ~10 simulations takes seconds.
  const long triangles = write_label_surface(label, dir / "wall.vtp", 1200);
  EXPECT_NEAR(triangles, 1200, 200);
  const auto c = calibrate("--measured " + compare_data("normal-female-34y.csv").string() +
                               " --mesh " + (dir / "wall.vtp").string() +
                               " --calibrate mu --fit-volume-ml 50,350" + kNeoHookeanAtTheStart,
                           dir);
  ASSERT_FALSE(c.is_null());
  const double mu = c["parameters"][0]["value"].get<double>();
  const double rmse = c["rmse_cmh2o"].get<double>();
  std::cout << "fitted mu " << mu << " kPa, RMSE " << rmse << " cmH2O, " << c["simulations"]
            << " simulations, " << c["seconds"] << " s: " << c["status"] << "\n";
  EXPECT_LE(rmse, 2.0);
  EXPECT_GE(mu, 1.0);
  EXPECT_LE(mu, 10.0);
  expect_honest_parameters(c);
  EXPECT_TRUE(c["parameters"][0]["identifiable"].get<bool>());
  EXPECT_DOUBLE_EQ(c["volume_range_ml"][0].get<double>(), 50);
  EXPECT_DOUBLE_EQ(c["volume_range_ml"][1].get<double>(), 349);
  // The shared recording's 15 unflagged filling readings from 50 to 349 ml, and its
  // baselines worked out from them: mean 3.6 cmH2O, constant RMSE 1.02, line RMSE 0.741.
  const auto* f = series(c, "filling Pdet");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ((*f)["points"], 15);
  EXPECT_NEAR((*f)["constant_baseline_rmse"].get<double>(), 1.0198, 1e-4);
  EXPECT_NEAR((*f)["line_baseline_rmse"].get<double>(), 0.7414, 1e-4);
  // a one-parameter neo-Hookean wall does not beat the straight line, and says so
  EXPECT_EQ(c["fitted"].get<bool>(), rmse < 0.7414);
  if (!c["fitted"].get<bool>()) {
    EXPECT_NE(c["status"].get<std::string>().find("no better than a straight line"),
              std::string::npos);
  }
}

TEST(Calibration, TheWholeRecordingFillingAndVoidingOnTheRealBladder) {
  VESICA_REQUIRE_SHARED(label, "data/ct/abdomen-3mm/bladder-reference.nii.gz");
  const fs::path dir = scratch_dir("compare-calibration-whole");
  write_label_surface(label, dir / "wall.vtp", 1200);
  // Voided by straining (fitted), the thesis's neo-Hookean wall.
  const auto c = calibrate("--measured " + compare_data("normal-female-34y.csv").string() +
                               " --mesh " + (dir / "wall.vtp").string() +
                               " --calibrate mu,p_open,r2,straining --straining-kpa 4"
                               " --surrogate-starts 2" +
                               kNeoHookeanAtTheStart,
                           dir);
  ASSERT_FALSE(c.is_null());
  std::cout << c["status"] << "\n";
  for (const auto& p : c["parameters"])
    std::cout << p["name"] << " " << p["value"] << " [" << p["ci95_low"] << ", " << p["ci95_high"]
              << "] " << p["note"] << "\n";
  expect_honest_parameters(c);
  for (const char* name : {"filling Pdet", "voiding flow", "voiding Pdet", "voided volume"})
    EXPECT_NE(series(c, name), nullptr) << name;
  // the shared recording's voiding: 13 flow readings from the onset (06:40) to 07:19
  EXPECT_EQ((*series(c, "voiding flow"))["points"], 13);
  const auto& v = c["voiding"];
  EXPECT_DOUBLE_EQ(v["qmax_ml_s"]["measured"].get<double>(), 17);
  EXPECT_DOUBLE_EQ(v["flow_time_s"]["measured"].get<double>(), 39);
  EXPECT_DOUBLE_EQ(v["voided_ml"]["measured"].get<double>(), 350);
  EXPECT_GT(v["voided_ml"]["simulated"].get<double>(), 0);
  EXPECT_FALSE(v["flow_correlation_aligned_onsets"].is_null());
  // both flow curves for the report's plot, from the onset of flow
  EXPECT_DOUBLE_EQ(v["measured_flow"]["time_s"][0].get<double>(), 0);
  EXPECT_GT(v["simulated_flow"]["time_s"].size(), 10u);
  // The passive wall from the filling first (surrogate, wall), then the voiding (the same).
  ASSERT_EQ(c["stages"].size(), 4u);
  EXPECT_EQ(c["stages"][0]["name"].get<std::string>().rfind("filling: ", 0), 0u);
  int simulations = 0;
  for (const auto& stage : c["stages"]) simulations += stage["simulations"].get<int>();
  EXPECT_EQ(c["simulations"].get<int>(), simulations);
}

TEST(Calibration, AVolumeIndexedFillingTableCalibratesThroughTheCli) {
  const fs::path dir = scratch_dir("compare-calibration-filling-table");
  const auto c = calibrate("--measured " + compare_data("filling-table.csv").string() + " --mesh " +
                               small_sphere(dir).string() +
                               " --calibrate mu --fill-rate-ml-min 30" + kNeoHookeanAtTheStart,
                           dir);
  ASSERT_FALSE(c.is_null());
  const auto* f = series(c, "filling Pdet");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ((*f)["points"], 7);  // the table's rows from 50 (the start volume) to 350 ml
  EXPECT_TRUE(has_note(c, "fills at 30 ml/min"));
  expect_honest_parameters(c);
  EXPECT_FALSE(c["status"].get<std::string>().empty());
}

TEST(Calibration, AVoidingTableCalibratesThroughTheCli) {
  const fs::path dir = scratch_dir("compare-calibration-voiding-table");
  const auto c = calibrate("--measured " + compare_data("voiding-table.csv").string() + " --mesh " +
                               small_sphere(dir).string() +
                               " --calibrate p_open,r2 --drive straining --straining-kpa 4"
                               " --capacity-ml 320 --surrogate-starts 2" +
                               kNeoHookeanAtTheStart,
                           dir);
  ASSERT_FALSE(c.is_null());
  // Pdet and flow against the voided volume (9 readings each), and the voided volume
  const auto* p = series(c, "voiding Pdet");
  const auto* q = series(c, "voiding flow");
  ASSERT_NE(p, nullptr);
  ASSERT_NE(q, nullptr);
  EXPECT_EQ((*p)["abscissa"], "voided volume (ml)");
  EXPECT_EQ((*q)["measured"]["x"].size(), 9u);
  EXPECT_NE(series(c, "voided volume"), nullptr);
  EXPECT_TRUE(has_note(c, "no fill rate"));
  expect_honest_parameters(c);
  // without time there is no flow time and no aligned correlation
  EXPECT_TRUE(c["voiding"]["flow_time_s"]["measured"].is_null());
  EXPECT_TRUE(c["voiding"]["flow_correlation_aligned_onsets"].is_null());
}

TEST(Calibration, VoidingParametersWithoutAVoidingInTheRecordingAreRefused) {
  const fs::path dir = scratch_dir("compare-calibration-no-voiding");
  const auto r = run_command(
      compare_exe() + " --measured " + compare_data("filling-table.csv").string() + " --mesh " +
      small_sphere(dir).string() + " --calibrate mu,p_open -o " + (dir / "report").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("voiding parameters need a voiding phase"), std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir / "report" / "metrics.json"));
}

// Acceptance of issue 24 on the README's 2,474-triangle CT wall, for the detrusor-voided
// default bladder wall: its matrix and fibers (mu, k1) from the filling first, then the
// detrusor's shortening rate, the drive's latency, the sphincter's recovery and the
// urethra's closing pressure from the voiding (6 parameters), each searched on simulate's
// level 0 and refined by output space mapping with a few runs of the wall. The default
// wall's k2 is set by its compliance beyond 350 ml, which this recording (to 349 ml) does
// not reach, so it is not fitted; her 39 s of flow asks a slower shortening than the
// population's default, and with it fitted the contractility is not identified apart from
// it, so that stays at its default. Targets: filling RMSE <= 1 cmH2O and below the
// straight line; Qmax within 10 % of 17 ml/s; flow time within 20 % of the measured 39 s;
// voided volume within 5 % of 350 ml; PdetQmax within 3 cmH2O of 5; Q(t) correlation >= 0.9
// after aligning the onsets. The fit runs as every run does, without the labelled
// fallback down the levels (--hand-over, off by default): the wall voids itself, and where
// it cannot take a late voiding step (a few elements of the CT wall switching between taut
// and slack) its void ends there, with a note naming the volume (docs/simulate.md, "The
// tail of voiding").
TEST(Calibration, TheWholeRecordingMeetsTheAcceptanceTargetsOnTheCtWall) {
  VESICA_REQUIRE_SHARED(label, "data/ct/abdomen-3mm/bladder-reference.nii.gz");
  const fs::path dir = scratch_dir("compare-calibration-acceptance");
  const auto s =
      run_command(surface_exe() + " " + label.string() + " -o " + (dir / "ct.vtp").string() +
                  " --target-triangles 2300 --outlet auto --outlet-radius-mm 12");
  ASSERT_EQ(s.exit_code, 0) << s.output;
  const auto m = run_command((bin_dir() / "vesica-mesh").string() + " " +
                             (dir / "ct.vtp").string() + " -o " + (dir / "ct.msh").string());
  ASSERT_EQ(m.exit_code, 0) << m.output;
  const auto c = calibrate("--measured " + compare_data("normal-female-34y.csv").string() +
                               " --mesh " + (dir / "ct.vtu").string() +
                               " --calibrate mu,k1,activation_delay,"
                               "urethra_recovery_half,p_close,hill_vmax",
                           dir);
  ASSERT_FALSE(c.is_null());
  std::cout << c["status"] << "\n";
  const auto* f = series(c, "filling Pdet");
  ASSERT_NE(f, nullptr);
  EXPECT_LE((*f)["rmse"].get<double>(), 1.0);
  EXPECT_LT((*f)["rmse"].get<double>(), (*f)["line_baseline_rmse"].get<double>());
  const auto& v = c["voiding"];
  auto simulated = [&](const char* key) { return v[key]["simulated"].get<double>(); };
  EXPECT_NEAR(simulated("qmax_ml_s"), 17, 1.7);
  EXPECT_NEAR(simulated("flow_time_s"), 39, 0.2 * 39);
  EXPECT_NEAR(simulated("voided_ml"), 350, 0.05 * 350);
  EXPECT_NEAR(simulated("pdet_qmax_cmh2o"), 5, 3);
  EXPECT_GE(v["flow_correlation_aligned_onsets"].get<double>(), 0.9);
  expect_honest_parameters(c);
  // Every parameter moved by the data, with an interval around it.
  for (const auto& p : c["parameters"]) EXPECT_TRUE(p["identifiable"].get<bool>()) << p;
  EXPECT_NE(c["status"].get<std::string>().rfind("failed", 0), 0u) << c["status"];
  // The wall itself voids at least nine tenths of the 349 ml: where its void ends early
  // the note names the volume, below 35 ml; no hand-over, on the notes or the fitted card.
  const std::string run = "the fitted model's run: ", ended = "voiding ended at ";
  for (const auto& n : c["notes"]) {
    const std::string note = n.get<std::string>();
    if (note.rfind(run, 0) != 0) continue;
    EXPECT_EQ(note.find("could not go on"), std::string::npos) << note;
    const std::size_t at = note.find(ended);
    if (at == std::string::npos) continue;
    std::cout << note << "\n";
    EXPECT_LT(std::stod(note.substr(at + ended.size())), 35.0) << note;
  }
  const auto card = nlohmann::json::parse(read_text(dir / "report" / "model.json"));
  EXPECT_FALSE(card["numerics"]["hand_over"].get<bool>());
  EXPECT_TRUE(card["level"]["hand_overs"].empty()) << card["level"]["hand_overs"];
}

namespace {

// The rows of a history.csv (comment lines skipped): volume and Pdet by column name.
std::vector<std::pair<double, double>> volume_and_pdet(const fs::path& csv) {
  std::istringstream in(read_text(csv));
  std::vector<std::pair<double, double>> rows;
  std::vector<std::string> names;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream cs(line);
    for (std::string cell; std::getline(cs, cell, ',');) cells.push_back(cell);
    if (names.empty()) {
      names = cells;
      continue;
    }
    const auto at = [&](const char* name) {
      return std::stod(cells[std::find(names.begin(), names.end(), name) - names.begin()]);
    };
    rows.emplace_back(at("volume_ml"), at("pdet_cmh2o"));
  }
  return rows;
}

}  // namespace

// Issue 38: a fit starts from the model vesica-simulate runs by default, the bladder wall
// stress-free at its own 20 ml (docs/simulate.md "Default walls": mu 0.6 kPa, k1 125 Pa,
// k2 0.02), on a volume-indexed filling table; the fitted model is a card (model.json) that
// vesica-simulate --model-card runs to the fitted curve within 1e-6 cmH2O.
TEST(Calibration, AFitStartsFromTheDefaultWallAndItsCardRunsTheFittedCurveAgain) {
  const fs::path dir = scratch_dir("compare-calibration-default-wall");
  const fs::path sphere = small_sphere(dir);
  for (const std::string fitted : {"k1,k2", "mu,k1,k2"}) {
    SCOPED_TRACE(fitted);
    const fs::path run = dir / fitted;
    const auto c = calibrate("--measured " + compare_data("filling-table.csv").string() +
                                 " --mesh " + sphere.string() + " --calibrate " + fitted +
                                 " --fill-rate-ml-min 30 --surrogate-starts 2 --max-simulations 12",
                             run);
    ASSERT_FALSE(c.is_null());
    const std::map<std::string, double> bladder = {{"mu", 0.6}, {"k1", 0.125}, {"k2", 0.02}};
    for (const auto& p : c["parameters"])
      EXPECT_DOUBLE_EQ(p["initial"].get<double>(), bladder.at(p["name"].get<std::string>())) << p;
    EXPECT_TRUE(has_note(c, "; material bladder (mu 0.6 kPa")) << c["notes"];
    EXPECT_TRUE(has_note(c, "stress-free at 20 ml")) << c["notes"];

    const fs::path card = run / "report" / "model.json";
    ASSERT_TRUE(fs::exists(card));
    const nlohmann::json j = nlohmann::json::parse(read_text(card));
    EXPECT_EQ(j["material"]["name"], "bladder");
    EXPECT_NEAR(j["reference"]["volume_ml"].get<double>(), 20.0, 1e-9);
    for (const auto& p : c["parameters"]) {
      const std::string name = p["name"];
      const double value = p["value"].get<double>();
      if (name == "mu") {
        EXPECT_DOUBLE_EQ(j["material"]["mu_pa"].get<double>(), 1e3 * value);
      }
      if (name == "k1") {
        EXPECT_DOUBLE_EQ(j["material"]["fibers"]["k1_pa"].get<double>(), 1e3 * value);
      }
      if (name == "k2") {
        EXPECT_DOUBLE_EQ(j["material"]["fibers"]["k2"].get<double>(), value);
      }
    }

    const auto r =
        run_command((bin_dir() / "vesica-simulate").string() + " " + sphere.string() + " -o " +
                    (run / "again").string() + " --no-series --model-card " + card.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto rows = volume_and_pdet(run / "again" / "history.csv");
    const auto& curve = c["fitted_filling"];
    ASSERT_GT(curve["volume_ml"].size(), 5u);
    for (std::size_t i = 0; i < curve["volume_ml"].size(); ++i) {
      const double v = curve["volume_ml"][i].get<double>(),
                   p = curve["pdet_cmh2o"][i].get<double>();
      const auto row = std::find_if(rows.begin(), rows.end(),
                                    [&](const auto& r) { return std::abs(r.first - v) < 1e-6; });
      ASSERT_NE(row, rows.end()) << "no row at " << v << " ml";
      EXPECT_NEAR(row->second, p, 1e-6) << "at " << v << " ml";
    }
  }
}
