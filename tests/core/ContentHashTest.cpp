#include "vesica/core/ContentHash.h"

#include <fstream>

#include "TestData.h"
#include "vesica/core/Error.h"

// Known-answer tests from FIPS 180-2 (SHA-256 of "abc" and of the empty string).
TEST(ContentHash, MatchesPublishedSha256Vectors) {
  EXPECT_EQ(vesica::sha256_hex("abc"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(vesica::sha256_hex(""),
            "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

TEST(ContentHash, FileAndFolder) {
  const auto dir = vesica::test::scratch_dir("hash");
  std::ofstream(dir / "f.txt") << "abc";
  EXPECT_EQ(vesica::content_hash(dir / "f.txt"),
            "sha256:ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  std::filesystem::create_directories(dir / "d");
  std::ofstream(dir / "d" / "a") << "1";
  const std::string h1 = vesica::content_hash(dir / "d");
  std::ofstream(dir / "d" / "a") << "2";  // appends: content changes
  EXPECT_NE(vesica::content_hash(dir / "d"), h1);
  EXPECT_THROW(vesica::content_hash(dir / "missing"), vesica::Error);
}
