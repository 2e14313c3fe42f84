// What vesica opens is what it means to open (issue 37): an input is a regular file of
// bounded size, never a pipe or device that blocks or never ends; a file it writes is new
// (O_EXCL, O_NOFOLLOW), so a link planted at its name is an error, never followed; helper
// programs get their arguments without a shell, in a folder only this process made; and no
// DICOM UID survives into a line vesica prints.
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <sstream>

#include "TestData.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/HelperProgram.h"
#include "vesica/core/InputFile.h"
#include "vesica/core/JsonFile.h"
#include "vesica/core/UidScrub.h"

namespace fs = std::filesystem;
using vesica::test::file_text;

namespace {

fs::path fresh(const std::string& name) {
  const fs::path dir = vesica::test::scratch_dir(name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST(HostileFiles, ANamedPipeIsRefusedWithoutBlocking) {
  const fs::path dir = fresh("hostile-fifo");
  const fs::path fifo = dir / "recording.csv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto start = std::chrono::steady_clock::now();
  try {
    vesica::require_input_file(fifo, vesica::kMaxTableFileBytes, "recording");
    FAIL() << "a FIFO was accepted";
  } catch (const vesica::Error& e) {
    EXPECT_NE(std::string(e.what()).find("named pipe"), std::string::npos) << e.what();
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
  EXPECT_TRUE(vesica::is_special_file(fifo));
  EXPECT_FALSE(vesica::is_special_file(dir));
}

TEST(HostileFiles, ADeviceThatNeverEndsIsRefused) {
  EXPECT_THROW(vesica::require_input_file("/dev/zero", vesica::kMaxTableFileBytes), vesica::Error);
  EXPECT_THROW(vesica::read_input_file("/dev/zero", vesica::kMaxTableFileBytes), vesica::Error);
  EXPECT_TRUE(vesica::is_special_file("/dev/zero"));
}

TEST(HostileFiles, AFileLargerThanItsKindIsRefusedBeforeItIsRead) {
  const fs::path dir = fresh("hostile-size");
  const fs::path big = dir / "state.json";
  std::ofstream(big) << std::string(2000, ' ');
  EXPECT_EQ(vesica::require_input_file(big, 2000), 2000u);
  try {
    vesica::read_input_file(big, 1999, "state file");
    FAIL() << "a file over its bound was read";
  } catch (const vesica::Error& e) {
    EXPECT_NE(std::string(e.what()).find("at most 1999 bytes"), std::string::npos) << e.what();
  }
}

TEST(HostileFiles, JsonNestedDeeperThanVesicaWritesIsNotParsed) {
  const fs::path dir = fresh("hostile-json");
  std::ofstream(dir / "deep.json") << std::string(100000, '[') << std::string(100000, ']');
  std::ofstream(dir / "ok.json") << R"({"a": [1, {"b": 2}]})";
  EXPECT_TRUE(vesica::read_json_file(dir / "deep.json")->is_discarded());
  EXPECT_EQ((*vesica::read_json_file(dir / "ok.json"))["a"][1]["b"], 2);
  EXPECT_FALSE(vesica::read_json_file(dir / "missing.json"));
}

TEST(HostileFiles, ALinkPlantedAtANewFileLeavesItsTargetUntouched) {
  const fs::path dir = fresh("hostile-link");
  std::ofstream(dir / "victim.txt") << "the user's";
  fs::create_symlink(dir / "victim.txt", dir / "new.txt");
  EXPECT_THROW(vesica::write_new_file(dir / "new.txt", "vesica's", dir / "new.txt"), vesica::Error);
  EXPECT_EQ(file_text(dir / "victim.txt"), "the user's");
}

TEST(HostileFiles, TemporaryNamesCannotBeGuessed) {
  // 64 random bits per name: two names for the same output never agree but in the counter.
  const std::string a = vesica::temporary_sibling("out/x.vtp").filename().string();
  const std::string b = vesica::temporary_sibling("out/x.vtp").filename().string();
  const auto random_part = [](const std::string& name) {
    const auto first = name.find('-', 5), second = name.find('-', first + 1);
    return name.substr(first + 1, second - first - 1);
  };
  EXPECT_NE(random_part(a), random_part(b));
  EXPECT_GE(random_part(a).size(), 10u);  // not a time stamp modulo 10^6
}

TEST(HostileFiles, AHelperGetsItsArgumentsWithoutAShell) {
  const vesica::TemporaryFolder dir("test");
  const std::string hostile = "a'b\"; touch " + (dir.path() / "pwned").string() + " $(id)";
  const vesica::HelperResult r =
      vesica::run_helper({"echo", hostile}, dir.path() / "log", std::chrono::seconds(10));
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.output, hostile + "\n");
  EXPECT_FALSE(fs::exists(dir.path() / "pwned"));
}

TEST(HostileFiles, AHelperLogPlantedAsALinkLeavesItsTargetUntouched) {
  const fs::path dir = fresh("hostile-helper");
  std::ofstream(dir / "victim.txt") << "the user's";
  fs::create_symlink(dir / "victim.txt", dir / "render.log");
  EXPECT_THROW(vesica::run_helper({"echo", "x"}, dir / "render.log", std::chrono::seconds(10)),
               vesica::Error);
  EXPECT_EQ(file_text(dir / "victim.txt"), "the user's");
}

TEST(HostileFiles, AHelperThatHangsIsStoppedAtItsDeadline) {
  const vesica::TemporaryFolder dir("test");
  const auto start = std::chrono::steady_clock::now();
  const vesica::HelperResult r =
      vesica::run_helper({"sleep", "60"}, dir.path() / "log", std::chrono::seconds(1));
  EXPECT_TRUE(r.timed_out);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
}

TEST(HostileFiles, ATemporaryFolderIsNewPrivateAndRemoved) {
  fs::path made;
  {
    const vesica::TemporaryFolder a("test"), b("test");
    EXPECT_NE(a.path(), b.path());
    made = a.path();
    struct stat st {};
    ASSERT_EQ(::lstat(made.c_str(), &st), 0);
    EXPECT_TRUE(S_ISDIR(st.st_mode));
    EXPECT_EQ(st.st_mode & 0777, 0700u);  // no other user can put anything in it
    std::ofstream(made / "x") << "x";
  }
  EXPECT_FALSE(fs::exists(made));
}

TEST(HostileFiles, AnErrorNamingASliceByItsUidKeepsNoUid) {
  const std::string uid = "1.2.840.113619.2.55.3.2831164356.987.1268071029.320";
  const vesica::Error e("ct/" + uid + ".dcm", "truncated or corrupt DICOM file");
  const std::string line = e.what();
  EXPECT_EQ(line.find(uid), std::string::npos) << line;
  EXPECT_EQ(line.find("113619"), std::string::npos) << line;
  EXPECT_NE(line.find("ct/uid-"), std::string::npos) << line;
  EXPECT_NE(line.find(".dcm: truncated"), std::string::npos) << line;
  // The same UID gives the same key; another gives another.
  EXPECT_EQ(vesica::without_uids(uid), vesica::without_uids(uid));
  EXPECT_NE(vesica::without_uids(uid), vesica::without_uids(uid + "1"));
  EXPECT_EQ(vesica::without_uids("2.25.329800735698586629295641978511506172918").substr(0, 4),
            "uid-");
}

TEST(HostileFiles, NumbersThatAreNoUidsStay) {
  for (const std::string text :
       {"vesica 0.3.1", "Pdet 12.5 cmH2O at 349.0 ml", "2026.11.24", "192.168.100.200",
        "slice_0001.dcm", "row 12: 1.234,5", "t = 3.14159265358979 s", "file a1.2.3.4.5.6.7.8.9"})
    EXPECT_EQ(vesica::without_uids(text), text);
}

TEST(HostileFiles, ALineOfAMegabyteIsRecognisedAtItsBound) {
  std::istringstream in("short\n" + std::string(1 << 20, 'x') + "\nnever read");
  std::string line;
  EXPECT_EQ(vesica::read_line(in, line, 1000), vesica::LineRead::Line);
  EXPECT_EQ(line, "short");
  EXPECT_EQ(vesica::read_line(in, line, 1000), vesica::LineRead::TooLong);
  EXPECT_TRUE(line.empty());
  std::istringstream last("a\nb");  // the last line without a line break
  EXPECT_EQ(vesica::read_line(last, line, 10), vesica::LineRead::Line);
  EXPECT_EQ(vesica::read_line(last, line, 10), vesica::LineRead::Line);
  EXPECT_EQ(line, "b");
  EXPECT_EQ(vesica::read_line(last, line, 10), vesica::LineRead::End);
}
