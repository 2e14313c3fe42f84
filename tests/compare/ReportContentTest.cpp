// What the report says, checked against hand-worked values: the pressure-flow criteria of
// the patient's sex (a woman gets BOOIf and no male class, a man BOOI and BCI), the sex
// and age read from the recording's header or --sex, the measured fill rate and start of
// filling, and a simulated void shown as a phase with its model card (the drive it names
// is the card's, never guessed), never as artefacts.
#include <cmath>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "CompareTestSupport.h"
#include "vesica/compare/analysis/RecordingAnalysis.h"
#include "vesica/compare/recording/FillingTimes.h"
#include "vesica/compare/recording/RecordingHeader.h"
#include "vesica/core/ContentHash.h"
#include "vesica/io/RecordingReader.h"
#include "vesica/simulate/ModelCardJson.h"

namespace fs = std::filesystem;
using namespace vesica::test;
namespace vc = vesica::compare;

namespace {

struct Report {
  nlohmann::json metrics;
  std::string html;
};

Report compare(const std::string& name, const std::string& args, const std::string& extra = "") {
  const fs::path out = scratch_dir("compare-content-" + name) / "report";
  const auto r =
      run_command(compare_exe() + " " + args + " -o " + out.string() + " --no-pdf " + extra);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return {nlohmann::json::parse(read_text(out / "metrics.json")), read_text(out / "index.html")};
}

std::string measured(const std::string& csv) {
  return "--measured " + compare_data(csv).string();
}

// A model card of a straining void, as vesica-simulate writes it into summary.json: the
// thesis's neo-Hookean wall (mu 3 kPa) strained at 4 kPa, whose last 50 ml went on as the
// wall's sphere-equivalent.
std::string straining_summary() {
  namespace vs = vesica::simulate;
  vs::ModelCard card;
  card.material.name = "neo-hookean";
  card.material.mu_pa = 3e3;
  card.material.k_pa = 3e6;
  card.material.beta_vol = 9;
  card.protocol.drive = vs::VoidingDrive::Straining;
  card.protocol.straining_kpa = 4.0;
  card.protocol.capacity_ml = 350.0;
  card.mean_thickness_mm = 3.0;
  card.reference_volume_ml = 50.0;
  card.mesh = {"missing.msh", "sha256:0", 1710, 857, 0, 6.0};
  card.hand_overs = {{1, 0, 50.0, 365.5, "the wall could not take a voiding step"}};
  const nlohmann::json summary = {{"version", "0.1.0"}, {"model_card", card}};
  return summary.dump();
}

}  // namespace

TEST(ReportContent, AWomanGetsTheFemaleIndexAndNoMaleClass) {
  const Report r = compare("female", measured("normal-female-34y.csv"));
  EXPECT_EQ(r.metrics["patient"]["sex"], "female");
  EXPECT_EQ(r.metrics["patient"]["sex_source"], "recording header");
  EXPECT_EQ(r.metrics["patient"]["age_years"], 34);
  const auto& p = r.metrics["measured"]["parameters"];
  EXPECT_EQ(p["booi_class"], "");
  EXPECT_EQ(p["bci_class"], "");
  // BOOIf = PdetQmax - 2.2 Qmax = 5 - 2.2 x 17 = -32.4 < 0: obstruction unlikely
  const auto& f = r.metrics["criteria"]["measured"]["booif"];
  EXPECT_NEAR(f["value"].get<double>(), -32.4, 1e-9);
  EXPECT_EQ(f["class"], "obstruction unlikely (< 10 %)");
  EXPECT_NE(f["reference"].get<std::string>().find("Neurourol Urodyn 2018"), std::string::npos);
  EXPECT_FALSE(r.metrics["criteria"]["measured"].contains("booi"));
  EXPECT_FALSE(r.metrics["criteria"]["measured"].contains("bci"));
  EXPECT_NE(r.html.find("id=\"criterion-booif\""), std::string::npos);
  EXPECT_EQ(r.html.find("id=\"criterion-booi\""), std::string::npos);
  EXPECT_EQ(r.html.find("id=\"criterion-bci\""), std::string::npos);
  for (const char* male_class : {">weak<", ">unobstructed<", ">equivocal<", "BCI 100", "BOOI 40"})
    EXPECT_EQ(r.html.find(male_class), std::string::npos) << male_class;
  EXPECT_NE(r.html.find("BOOI and BCI are nomograms for men"), std::string::npos);  // caveat
}

TEST(ReportContent, AManGetsBooiAndBciClasses) {
  const Report r = compare("male", measured("obstructed-male-68y.csv"));
  EXPECT_EQ(r.metrics["patient"]["sex"], "male");
  EXPECT_EQ(r.metrics["patient"]["age_years"], 68);
  // hand-checked in the file's header: Qmax 8 ml/s at PdetQmax 72 cmH2O
  const auto& c = r.metrics["criteria"]["measured"];
  EXPECT_DOUBLE_EQ(c["booi"]["value"].get<double>(), 72 - 2 * 8);  // 56
  EXPECT_EQ(c["booi"]["class"], "obstructed");                     // > 40
  EXPECT_DOUBLE_EQ(c["bci"]["value"].get<double>(), 72 + 5 * 8);   // 112
  EXPECT_EQ(c["bci"]["class"], "normal");                          // 100-150
  EXPECT_FALSE(c.contains("booif"));
  EXPECT_EQ(r.metrics["measured"]["parameters"]["booi_class"], "obstructed");
  EXPECT_NE(r.html.find("id=\"criterion-booi\""), std::string::npos);
  EXPECT_NE(r.html.find("id=\"criterion-bci\""), std::string::npos);
  EXPECT_NE(r.html.find("BOOI 40"), std::string::npos);  // the nomogram lines for men
}

TEST(ReportContent, SexFromTheCommandLineWinsOverTheHeader) {
  const Report r = compare("sex-option", measured("obstructed-male-68y.csv"), "--sex female");
  EXPECT_EQ(r.metrics["patient"]["sex"], "female");
  EXPECT_EQ(r.metrics["patient"]["sex_source"], "--sex");
  EXPECT_EQ(r.metrics["measured"]["parameters"]["booi_class"], "");
  // BOOIf = 72 - 2.2 x 8 = 54.4 > 18
  EXPECT_EQ(r.metrics["criteria"]["measured"]["booif"]["class"],
            "obstruction almost certain (> 90 %)");
}

TEST(ReportContent, HeaderLinesGiveSexAgeAndStatedFillRate) {
  const auto female = vc::parse_recording_header(
      {" Multichannel cystometry, adult female, 34 years, normal bladder function.",
       " Medium fill rate 50 ml/min; pressures in cmH2O"});
  EXPECT_EQ(female.sex, vc::Sex::female);
  EXPECT_EQ(female.age_years, 34);
  EXPECT_EQ(female.stated_fill_rate_ml_min, 50);
  const auto man = vc::parse_recording_header({"a 71-year-old man with LUTS"});
  EXPECT_EQ(man.sex, vc::Sex::male);
  EXPECT_EQ(man.age_years, 71);
  EXPECT_EQ(vc::parse_recording_header({"sex: F", "age: 52"}).sex, vc::Sex::female);
  EXPECT_EQ(vc::parse_recording_header({"men and women"}).sex, vc::Sex::unknown);
}

TEST(ReportContent, FillRateAndStartOfFillingFromTheInfusedVolume) {
  const auto a = vc::analyse(vesica::io::read_recording(compare_data("normal-female-34y.csv")));
  const vc::FillingTimes f = vc::filling_times(a.recording, a.ics);
  // 25 ml at 00:45 to 349 ml at 06:20: 324 ml in 335 s
  const double rate = 324.0 / 335.0;
  ASSERT_TRUE(f.mean_rate_ml_min.has_value());
  EXPECT_NEAR(*f.mean_rate_ml_min, 60 * rate, 1e-9);  // 58.0 ml/min
  EXPECT_NEAR(f.start_s, 45 - 25 / rate, 1e-9);       // 19.2 s: the infusion began there
}

TEST(ReportContent, SimulatedStrainingIsAPhaseWithItsModelCardNotAnArtefact) {
  // A history voided by straining: Pabd 4 -> 44 cmH2O, Pdet falling below zero at the end,
  // beside the summary.json vesica-simulate leaves with its model card.
  const fs::path dir = scratch_dir("compare-content-straining");
  fs::create_directories(dir / "sim");
  {
    std::ofstream h(dir / "sim/history.csv");
    h << "time_s,infused_ml,volume_ml,pves_cmh2o,pabd_cmh2o,pdet_cmh2o,flow_ml_s,voided_ml\n";
    for (int t = 0; t <= 360; t += 10)
      h << t << ',' << t * 50.0 / 60 << ',' << 50 + t * 50.0 / 60 << ',' << 6 + t / 100.0 << ",4,"
        << 2 + t / 100.0 << ",0,0\n";
    const double pdet[] = {5, 4, 2, 0, -2};
    for (int k = 1; k <= 5; ++k)
      h << 360 + k << ",300," << 350 - 60 * k << ',' << 44 + pdet[k - 1] << ",44," << pdet[k - 1]
        << ",60," << 60 * k << '\n';
  }
  std::ofstream(dir / "sim/summary.json") << straining_summary();

  const Report r = compare("straining-run", "--simulated " + (dir / "sim/history.csv").string());
  EXPECT_TRUE(r.metrics["simulated"]["artefacts"].empty()) << r.metrics["simulated"]["artefacts"];
  EXPECT_EQ(r.html.find("artefact rows"), std::string::npos);
  const auto& m = r.metrics["simulated_model"];
  EXPECT_EQ(m["voiding_drive"], "abdominal straining 4 kPa (40.79 cmH2O)");  // 4000/98.0665
  EXPECT_EQ(m["model_card"]["material"]["mu_pa"], 3000.0);
  EXPECT_EQ(m["model_card"]["mesh"]["triangles"], 1710);
  EXPECT_NE(r.html.find("voiding by abdominal straining"), std::string::npos);
  EXPECT_NE(r.html.find("neo-hookean: &mu; = 3 kPa"), std::string::npos);
  EXPECT_NE(r.html.find("1710 wall triangles"), std::string::npos);
  // The wall handed the last 50 ml of its voiding to its sphere-equivalent: the reader is told.
  EXPECT_NE(r.html.find("level 1 -&gt; 0 at 50 ml"), std::string::npos);
}

TEST(ReportContent, WithoutAModelCardTheModelIsUnknownNotGuessed) {
  const fs::path dir = scratch_dir("compare-content-no-card-run");
  fs::create_directories(dir / "sim");
  std::ofstream(dir / "sim/history.csv")
      << "time_s,infused_ml,volume_ml,pves_cmh2o,pabd_cmh2o,pdet_cmh2o,flow_ml_s,voided_ml\n"
         "0,0,50,2,0,2,0,0\n60,50,100,3,0,3,0,0\n61,50,90,40,30,10,10,10\n";
  const Report r = compare("no-card", "--simulated " + (dir / "sim/history.csv").string());
  EXPECT_TRUE(r.metrics["simulated_model"]["model_card"].is_null());
  EXPECT_NE(r.html.find("no model card: no summary.json beside history.csv"), std::string::npos);
  EXPECT_EQ(r.html.find("straining"), std::string::npos);  // Pabd rose, but nothing is guessed
}

namespace {

// vesica-simulate on a 50 ml sphere with `model`, then vesica-compare of its history against
// the shared normal recording, as the demo does: the report page.
std::string simulated_report(const std::string& name, const std::string& model) {
  const fs::path dir = scratch_dir("compare-content-" + name);
  const std::string bin = bin_dir().string();
  CommandResult r = run_command(bin + "/vesica-surface -o " + (dir / "sphere.vtp").string() +
                                " --shape sphere --volume-ml 50 --edge-mm 8 --outlet auto --json");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  r = run_command(bin + "/vesica-simulate " + (dir / "sphere.vtp").string() + " -o " +
                  (dir / "sim").string() + " --capacity-ml 150 --no-series " + model);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return compare(name + "-report", measured("normal-female-34y.csv") + " --simulated " +
                                       (dir / "sim/history.csv").string())
      .html;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

// The demo's model (the default bladder wall voided by its detrusor) is named as voided by
// the detrusor wherever the page names the drive: the model card, the trace's band and the
// plots' captions; a straining-voided neobladder is named as straining in the same places.
TEST(ReportContent, TheDetrusorVoidedDemoAndAStrainedRunNameTheirOwnDrive) {
  const std::string detrusor = simulated_report("detrusor", "--material bladder --drive detrusor");
  EXPECT_NE(detrusor.find("Voiding driven by</th><td>detrusor contraction, contractility 100 kPa"),
            std::string::npos);
  EXPECT_GE(count(detrusor, "voiding by detrusor contraction"), 3u);  // band and two captions
  EXPECT_EQ(detrusor.find("abdominal straining"), std::string::npos);
  EXPECT_EQ(detrusor.find("stays passive"), std::string::npos);

  const std::string straining = simulated_report(
      "straining",
      "--material neobladder --residual-ml 50 --drive straining --straining-kpa 3.5");
  EXPECT_NE(straining.find("Voiding driven by</th><td>abdominal straining 3.5 kPa (35.69 cmH2O)"),
            std::string::npos);
  EXPECT_GE(count(straining, "voiding by abdominal straining"), 3u);
  EXPECT_NE(straining.find("stays passive"), std::string::npos);  // the dagger's note
  EXPECT_EQ(straining.find("voiding by detrusor contraction"), std::string::npos);
  EXPECT_EQ(straining.find("Voiding driven by</th><td>detrusor"), std::string::npos);
}
