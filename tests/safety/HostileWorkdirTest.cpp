// A workdir another user (or an accident) has prepared (issue 37): a lock or state folder
// planted as a link, a user's files where a stage writes beside its output, an export
// aimed outside the workdir, a DICOM slice named by its UID, a full disk under the phantom.
// Each test names what the user keeps.
#include <unistd.h>

#include <map>

#include <nlohmann/json.hpp>

#include "HostileSupport.h"

namespace fs = std::filesystem;
using namespace vesica::test;

namespace {

// A quick pipeline: a sphere surface (.ply, with its region sidecar) and its meshes
// (.msh, with the .vtu beside it).
fs::path sphere_pipeline(const fs::path& dir, const std::string& extra_stages = "") {
  write_file(dir / "p.yaml",
             "workdir: out\nstages:\n"
             "  surface: {output: s.ply, params: {shape: sphere, volume_ml: 100, edge_mm: 8}}\n"
             "  mesh: {input: s.ply, output: s.msh}\n" +
                 extra_stages);
  return dir / "p.yaml";
}

std::string run_vesica(const std::string& args) {
  return tool("vesica") + " " + args;
}

// The files under .vesica/backup of `stage` (any time stamp), by name.
std::map<std::string, std::string> backups(const fs::path& workdir, const std::string& stage) {
  std::map<std::string, std::string> files;
  const fs::path root = workdir / ".vesica/backup" / stage;
  if (!fs::exists(root)) return files;
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.is_regular_file()) files[e.path().filename().string()] = read_file(e.path());
  return files;
}

}  // namespace

TEST(HostileWorkdir, ALockThatIsALinkLeavesItsTargetUntouched) {
  const fs::path dir = fresh_dir("hostile-lock");
  const fs::path file = sphere_pipeline(dir);
  fs::create_directories(dir / "out/.vesica");
  write_file(dir / "notes.txt", "a user's notes");
  // A symbolic link, then a second name of the user's file (a hard link): no lock of
  // vesica's either.
  for (const bool hard : {false, true}) {
    fs::remove(dir / "out/.vesica/lock");
    if (hard)
      fs::create_hard_link(dir / "notes.txt", dir / "out/.vesica/lock");
    else
      fs::create_symlink(dir / "notes.txt", dir / "out/.vesica/lock");
    const auto r = run_measured(run_vesica("run '" + file.string() + "'"), 60);
    EXPECT_REFUSED_IN_ONE_LINE(r, "lock");
    EXPECT_EQ(read_file(dir / "notes.txt"), "a user's notes") << (hard ? "hard link" : "link");
  }
}

TEST(HostileWorkdir, AStateFolderThatIsALinkIsNotWrittenThrough) {
  const fs::path dir = fresh_dir("hostile-state-link");
  const fs::path file = sphere_pipeline(dir);
  fs::create_directories(dir / "out");
  fs::create_directories(dir / "mine");
  write_file(dir / "mine/lock", "the user's");
  fs::create_directory_symlink(dir / "mine", dir / "out/.vesica");
  const auto r = run_measured(run_vesica("run '" + file.string() + "'"), 60);
  EXPECT_REFUSED_IN_ONE_LINE(r, ".vesica");
  EXPECT_EQ(read_file(dir / "mine/lock"), "the user's");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir / "mine"), {}), 1);
}

TEST(HostileWorkdir, AUsersFilesWhereAStageWritesBesideItsOutputAreSavedFirst) {
  const fs::path dir = fresh_dir("hostile-side-outputs");
  const fs::path file = sphere_pipeline(dir);
  fs::create_directories(dir / "out");
  write_file(dir / "out/s.ply.regions.json", "my region notes");
  write_file(dir / "out/s.vtu", "my ParaView state");
  const auto r = run_measured(run_vesica("run '" + file.string() + "'"), 300);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(backups(dir / "out", "surface")["s.ply.regions.json"], "my region notes");
  EXPECT_EQ(backups(dir / "out", "mesh")["s.vtu"], "my ParaView state");
  // Nothing of vesica's own is saved on the next run: those files are the stages' now.
  const auto again = run_measured(run_vesica("run '" + file.string() + "' --force"), 300);
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(backups(dir / "out", "mesh").size(), 1u);
}

TEST(HostileWorkdir, AnotherStagesOutputAtASideOutputsPlaceIsRefusedByValidate) {
  const fs::path dir = fresh_dir("hostile-side-collision");
  const fs::path file = sphere_pipeline(
      dir, "  other: {tool: surface, output: s.vtu, params: {shape: sphere, volume_ml: 80}}\n");
  const auto v = run_measured(run_vesica("validate '" + file.string() + "'"), 30);
  EXPECT_EQ(v.exit_code, 2) << v.output;
  EXPECT_NE(v.output.find("collides with"), std::string::npos) << v.output;
}

TEST(HostileWorkdir, AFebioExportOutsideTheWorkdirIsRefusedAndOneInsideSurvivesReruns) {
  const fs::path dir = fresh_dir("hostile-export-feb");
  const std::string simulate =
      "  simulate: {input: s.msh, output: sim, params: {capacity_ml: 120, no_void: true, "
      "no_series: true, febio_approximate: true, export_feb: ";  // the file matters, not the law
  write_file(dir / "outside.yaml",
             "workdir: out\nstages:\n"
             "  mesh: {input: s.ply, output: s.msh}\n" +
                 simulate + "../wall.feb}}\n");
  fs::create_directories(dir / "out");
  write_file(dir / "out/s.ply", "");
  const auto v = run_measured(run_vesica("validate '" + (dir / "outside.yaml").string() + "'"), 30);
  EXPECT_EQ(v.exit_code, 2) << v.output;
  EXPECT_NE(v.output.find("export_feb of stage 'simulate' must stay inside the workdir"),
            std::string::npos)
      << v.output;
  fs::remove_all(dir / "out");
  const fs::path file = sphere_pipeline(dir, simulate + "wall.feb}}\n");
  for (const char* extra : {"", " --force"}) {
    const auto r = run_measured(run_vesica("run '" + file.string() + "'" + extra), 600);
    ASSERT_EQ(r.exit_code, 0) << extra << "\n" << r.output;
    EXPECT_NE(read_file(dir / "out/wall.feb").find("febio_spec"), std::string::npos);
  }
}

TEST(HostileWorkdir, ASliceNamedByItsUidLeavesNoUidInTheFailureStatusOrLog) {
  const fs::path dir = fresh_dir("hostile-uid");
  write_file(dir / "p.yaml",
             "workdir: out\nstages:\n"
             "  phantom: {output: ct, params: {spacing_mm: 8}}\n"
             "  segment: {input: ct, output: b.nii.gz}\n");
  const auto made = run_measured(run_vesica("run '" + (dir / "p.yaml").string() + "'"), 300);
  ASSERT_EQ(made.exit_code, 0) << made.output;
  // A PACS export names each slice by its SOP Instance UID; one of them is cut short.
  const std::string uid = "1.2.840.113619.2.55.3.2831164356.987.1268071029.320";
  fs::path victim;
  for (const auto& e : fs::directory_iterator(dir / "out/ct"))
    if (e.path().extension() == ".dcm") victim = e.path();
  ASSERT_FALSE(victim.empty());
  const std::string bytes = read_file(victim);
  fs::remove(victim);
  write_file(dir / "out/ct" / (uid + ".dcm"), bytes.substr(0, bytes.size() / 2));
  const auto run = run_measured(run_vesica("run '" + (dir / "p.yaml").string() + "' --force"), 300);
  EXPECT_NE(run.exit_code, 0) << run.output;
  const auto status = run_measured(run_vesica("status '" + (dir / "p.yaml").string() + "'"), 60);
  const std::string failure = read_file(dir / "out/.vesica/segment.failed.json");
  ASSERT_FALSE(failure.empty());
  for (const std::string& text : {run.output, status.output, failure}) {
    EXPECT_EQ(text.find("113619"), std::string::npos) << text;
    EXPECT_EQ(text.find(uid), std::string::npos) << text;
  }
  EXPECT_NE(failure.find("uid-"), std::string::npos) << failure;  // the slice still named
}

TEST(HostileWorkdir, APhantomOnAFullDiskFailsInOneLineAndLeavesNoTemporaryFolder) {
  const fs::path dir = fresh_dir("hostile-phantom-disk");
  // ulimit -f (the tools ignore SIGXFSZ): a 1 KiB file-size limit is a disk too small for
  // one slice. Also as root, which no quota stops.
  const auto r = run_measured("cd '" + dir.string() + "' && bash -c 'ulimit -f 1; exec " +
                                  tool("vesica-phantom") + " -o ct --spacing-mm 8'",
                              60);
  EXPECT_REFUSED_IN_ONE_LINE(r, "ct");
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_NE(e.path().filename().string().rfind(".tmp-", 0), 0u) << e.path();
  EXPECT_FALSE(fs::exists(dir / "ct"));
}
