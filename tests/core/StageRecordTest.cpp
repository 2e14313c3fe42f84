#include "vesica/core/StageRecord.h"

#include <fstream>

#include "TestData.h"
#include "vesica/core/ContentHash.h"

TEST(StageRecord, ManifestListsInputsOutputsAndInvocation) {
  const auto dir = vesica::test::scratch_dir("record");
  std::ofstream(dir / "in.txt") << "abc";
  std::ofstream(dir / "out.txt") << "xyz";
  const char* argv[] = {"vesica-x", "in.txt", "-o", "out.txt"};
  vesica::StageRecord rec("x", 4, argv);
  rec.parameters()["alpha"] = 2;
  rec.summary()["volume_ml"] = 12.5;
  rec.add_input(dir / "in.txt");
  rec.add_output(dir / "out.txt");
  rec.write(dir / "s.json", dir / "m.json");

  std::ifstream m(dir / "m.json");
  const auto manifest = nlohmann::json::parse(m);
  EXPECT_EQ(manifest["invocation"], nlohmann::json({"in.txt", "-o", "out.txt"}));
  EXPECT_EQ(manifest["parameters"]["alpha"], 2);
  EXPECT_EQ(manifest["inputs"][0]["hash"], vesica::content_hash(dir / "in.txt"));
  EXPECT_EQ(manifest["outputs"][0]["hash"], vesica::content_hash(dir / "out.txt"));
  EXPECT_EQ(manifest["version"], vesica::version());
  std::ifstream s(dir / "s.json");
  const auto summary = nlohmann::json::parse(s);
  EXPECT_DOUBLE_EQ(summary["volume_ml"].get<double>(), 12.5);
  EXPECT_TRUE(summary["timings_s"].contains("total"));
}
