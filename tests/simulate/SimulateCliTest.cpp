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
       {"--mu-kpa 1e30", "--hold-s 1e30", "--k-kpa 0", "--r1 -0.1", "--detrusor-kpa -5",
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
