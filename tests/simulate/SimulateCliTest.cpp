// vesica-simulate refuses a protocol no run can follow before reading anything, with one
// line and exit code 2, at both levels alike (one validation): with no infusion, filling
// never reaches capacity (level 2 used to step in fill() forever). The mesh is a real
// level-2 input (a 50 ml sphere with its outlet patch and urine tetrahedra), so that only
// the protocol is wrong.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "ShellCommand.h"
#include "TestData.h"

namespace fs = std::filesystem;
using namespace vesica::test;

TEST(SimulateCli, NoInfusionIsAOneLineUsageErrorAtBothLevels) {
  const fs::path dir = scratch_dir("simulate-cli-no-infusion");
  const std::string bin = bin_dir().string();
  CommandResult r = run_command(bin + "/vesica-surface -o " + (dir / "sphere.vtp").string() +
                                " --shape sphere --volume-ml 50 --edge-mm 8 --outlet auto --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = run_command(bin + "/vesica-mesh " + (dir / "sphere.vtp").string() + " -o " +
                  (dir / "sphere.msh").string() + " --fluid --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* level : {"1", "2"}) {
    const fs::path out = dir / (std::string("level") + level);
    // A time limit, so that a run that never ends fails the test instead of hanging it.
    r = run_command("timeout 60 " + bin + "/vesica-simulate " + (dir / "sphere.vtu").string() +
                    " -o " + out.string() + " --level " + level + " --fill-rate-ml-min 0");
    EXPECT_EQ(r.exit_code, 2) << "level " << level << ": " << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1)
        << "level " << level << ": " << r.output;
    EXPECT_NE(r.output.find("--fill-rate-ml-min 0 is outside [1, 1000] ml/min: at 0 filling never "
                            "ends"),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(out)) << "level " << level << " wrote " << out;
  }
}

// Values no run can use are refused before the mesh is read, each naming its option: a
// shear modulus whose wall never moves (1e30 kPa livelocked Newton), an hour-long hold (1e30 s
// filled the disk with frames), K = 0 (it used to mean "auto"), negative resistances,
// stresses, springs and pressures.
TEST(SimulateCli, OutOfRangeOptionsAreRefusedNamingTheOption) {
  const fs::path dir = scratch_dir("simulate-cli-ranges");
  const std::string bin = bin_dir().string();
  for (const std::string option :
       {"--mu-kpa 1e30", "--hold-s 1e30", "--k-kpa 0", "--r1 -0.1", "--contractility-kpa -5",
        "--support-kpa-per-mm -1", "--p-open-cmh2o -20"}) {
    const CommandResult r = run_command(bin + "/vesica-simulate missing.vtu -o " +
                                        (dir / "out").string() + " " + option);
    EXPECT_EQ(r.exit_code, 2) << option << ": " << r.output;
    const std::string name = option.substr(0, option.find(' '));
    EXPECT_NE(r.output.find("usage error: " + option + " is outside"), std::string::npos)
        << option << ": " << r.output;
    EXPECT_EQ(r.output.find("missing.vtu"), std::string::npos) << "read the mesh: " << r.output;
    EXPECT_FALSE(fs::exists(dir / "out")) << name;
  }
}

// A pipeline file's simulate params are checked against the same table before any stage
// runs: a misspelt key is named at its line and column with the key meant.
TEST(SimulateCli, MisspeltPipelineKeyIsFoundByValidateWithTheKeyMeant) {
  const fs::path dir = scratch_dir("simulate-cli-validate");
  {
    std::ofstream yaml(dir / "pipe.yaml");
    yaml << "pipeline: p\n"
            "stages:\n"
            "  surface: {output: s.vtp, params: {shape: sphere}}\n"
            "  mesh: {input: s.vtp, output: s.msh}\n"
            "  simulate: {input: s.msh, output: sim, params: {mu_kp: 3}}\n";
  }
  const CommandResult r =
      run_command(bin_dir().string() + "/vesica validate " + (dir / "pipe.yaml").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("pipe.yaml:5:50: unknown parameter 'mu_kp' for simulate (did you "
                          "mean 'mu_kpa'?)"),
            std::string::npos)
      << r.output;
}

namespace {

nlohmann::json summary_of(const fs::path& dir) {
  return nlohmann::json::parse(std::ifstream(dir / "summary.json"));
}

}  // namespace

// The model card says what ran, in summary.json and in history.csv's header: a neobladder
// (its own fibers, no muscle) voided by straining at 3.5 kPa; the card runs the same
// cystometry again to the last digit of history.csv; beside the card no model option is
// taken, and a card made on another mesh is refused (docs/simulate.md, "The model card").
TEST(SimulateCli, TheModelCardSaysWhatRanAndRunsItAgain) {
  const fs::path dir = scratch_dir("simulate-cli-model-card");
  const std::string bin = bin_dir().string();
  for (const char* volume : {"50", "60"}) {
    const CommandResult r = run_command(
        bin + "/vesica-surface -o " + (dir / (std::string("sphere") + volume + ".vtp")).string() +
        " --shape sphere --volume-ml " + volume + " --edge-mm 8 --outlet auto --json");
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  const std::string mesh = (dir / "sphere50.vtp").string();
  const std::string model =
      " --material neobladder --residual-ml 50 --drive straining --straining-kpa 3.5"
      " --capacity-ml 150 --no-series";
  CommandResult r = run_command(bin + "/vesica-simulate " + mesh + " -o " +
                                (dir / "first").string() + model + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json card = summary_of(dir / "first")["model_card"];
  EXPECT_EQ(card["material"]["name"], "neobladder");
  EXPECT_EQ(card["material"]["fibers"]["k1_pa"], 200.0);  // docs/simulate.md: 200 Pa
  EXPECT_EQ(card["material"]["muscle"]["contractility_pa"], 0.0);
  EXPECT_EQ(card["voiding"]["drive"], "straining");
  EXPECT_EQ(card["voiding"]["straining_kpa"], 3.5);
  EXPECT_NEAR(card["reference"]["volume_ml"].get<double>(), 50.0, 1e-9);
  EXPECT_EQ(card["level"]["started"], 1);
  const std::string history = file_text(dir / "first" / "history.csv");
  EXPECT_NE(history.find("# model card: voiding drive: abdominal straining 3.5 kPa (35.69 cmH2O)"),
            std::string::npos)
      << history.substr(0, 800);
  EXPECT_NE(history.find("# model card: material neobladder: mu 2 kPa, K 2000 kPa, k1 0.2 kPa"),
            std::string::npos)
      << history.substr(0, 800);

  const std::string again = bin + "/vesica-simulate " + mesh + " -o " + (dir / "again").string() +
                            " --no-series --model-card " +
                            (dir / "first" / "summary.json").string();
  r = run_command(again);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(file_text(dir / "again" / "history.csv"), history);

  r = run_command(again + " --mu-kpa 3 2>&1");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--mu-kpa cannot be given with --model-card"), std::string::npos)
      << r.output;
  r = run_command(bin + "/vesica-simulate " + (dir / "sphere60.vtp").string() + " -o " +
                  (dir / "other").string() + " --model-card " +
                  (dir / "first" / "summary.json").string() + " 2>&1");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("is not the mesh the model card ran on"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "other"));
}

// The contractility's earlier key still sets it, and says the key to give.
TEST(SimulateCli, TheDetrusorsEarlierKeySetsTheContractilityAndSaysItsName) {
  const fs::path dir = scratch_dir("simulate-cli-old-key");
  const std::string bin = bin_dir().string();
  CommandResult r = run_command(bin + "/vesica-surface -o " + (dir / "sphere.vtp").string() +
                                " --shape sphere --volume-ml 50 --edge-mm 8 --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = run_command(bin + "/vesica-simulate " + (dir / "sphere.vtp").string() + " -o " +
                  (dir / "out").string() +
                  " --level 0 --capacity-ml 100 --no-void --detrusor-kpa 50 2>&1");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("detrusor_kpa is the earlier name of contractility_kpa"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(summary_of(dir / "out")["model_card"]["material"]["muscle"]["contractility_pa"], 50e3);
}
