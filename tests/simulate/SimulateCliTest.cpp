// vesica-simulate refuses a protocol no run can follow before reading anything, with one
// line and exit code 2, at both levels alike (one validation): with no infusion, filling
// never reaches capacity (level 2 used to step in fill() forever). The mesh is a real
// level-2 input (a 50 ml sphere with its outlet patch and urine tetrahedra), so that only
// the protocol is wrong.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
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
    EXPECT_NE(r.output.find("fill_rate_ml_min must be > 0"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out)) << "level " << level << " wrote " << out;
  }
}
