// The executable as the pipeline runner calls it: parameters as --key value, --json prints
// only the summary on stdout, the manifest records the effective parameters.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <sys/wait.h>
#include <nlohmann/json.hpp>

#include "TestData.h"
#include "vesica/surface/SurfaceIO.h"

namespace vesica::test {
namespace {

namespace fs = std::filesystem;

TEST(SurfaceCli, RunnerStyleCallPrintsOnlyJson) {
  VESICA_REQUIRE_SHARED(label, "data/ct/abdomen-3mm/bladder-reference.nii.gz");
  const auto dir = scratch_dir("surface-cli");
  const std::string command = (bin_dir() / "vesica-surface").string() + " " + label.string() +
                              " -o " + (dir / "bladder.vtp").string() +
                              " --edge-mm 4 --outlet auto --fixed-radius-mm 20 --json > " +
                              (dir / "stdout.json").string();
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  std::ifstream in(dir / "stdout.json");
  const auto summary = nlohmann::json::parse(in);  // throws if anything else was printed
  EXPECT_EQ(summary["tool"], "vesica-surface");
  EXPECT_NEAR(summary["volume_ml"].get<double>(), 17744 * 27e-3, 1e-6);
  EXPECT_GT(summary["regions"]["triangle_counts"]["fixed"].get<int>(), 0);
  EXPECT_GT(summary["regions"]["triangle_counts"]["outlet"].get<int>(), 0);
  std::ifstream manifest_in(dir / ".vesica/bladder.vtp.manifest.json");
  const auto manifest = nlohmann::json::parse(manifest_in);
  EXPECT_EQ(manifest["parameters"]["edge_mm"], 4.0);
  EXPECT_EQ(manifest["parameters"]["outlet"], "auto");
  const surface::TriangleSurface s = surface::read_surface(dir / "bladder.vtp");
  EXPECT_EQ(s.F.rows(), summary["triangle_count"].get<int>());
  EXPECT_EQ(s.region.size(), s.F.rows());
}

}  // namespace
}  // namespace vesica::test
