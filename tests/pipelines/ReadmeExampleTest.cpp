// The README's worked example and its "Edit and rerun" section, run as a user types them:
// the commands are read from README.md's code blocks, in order, with the build's bin/ on
// PATH, in a fresh folder where pipelines/ is the repository's. The MeshLab step, a
// comment in the README, is done here the way MeshLab saves. Each part leaves only the
// files the README names, and every claim the comments make is checked.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <set>

#include "PipelineTestSupport.h"
#include "ToolEdits.h"
#include "vesica/core/ContentHash.h"
#include "vesica/io/VtuFile.h"

namespace fs = std::filesystem;
using namespace vesica::test;

namespace {

// The lines of the first ```sh block after `heading` (and after `after`, when given), and
// the prose that follows the block up to the next block or heading.
struct Snippet {
  std::vector<std::string> lines;
  std::string prose;
};

Snippet snippet(const std::string& heading, const std::string& after = "") {
  const std::string readme = slurp(source_dir() / "README.md");
  std::size_t at = readme.find("\n" + heading + "\n");
  if (at == std::string::npos) return {};
  if (!after.empty()) at = readme.find(after, at);
  const std::size_t open = readme.find("```sh\n", at);
  const std::size_t close = readme.find("\n```\n", open);
  if (open == std::string::npos || close == std::string::npos) return {};
  Snippet s;
  std::istringstream block(readme.substr(open + 6, close - open - 6));
  for (std::string line; std::getline(block, line);) s.lines.push_back(line);
  const std::size_t end = std::min(readme.find("```", close + 5), readme.find("\n#", close + 5));
  s.prose = readme.substr(close + 5, end - close - 5);
  return s;
}

// Runs one README line in `dir` with bin/ first on PATH (its output captured beside `dir`).
CommandResult type(const std::string& line, const fs::path& dir) {
  // The line on a line of its own: its trailing comment must not swallow the redirections.
  return run_command("cd " + quoted(dir.string()) + " && export PATH=" +
                         quoted(bin_dir().string()) + ":\"$PATH\" && {\n" + line + "\n}",
                     dir.parent_path());
}

// The names in backquotes of `prose`, as top-level entries of a folder ("phantom/dicom" is
// "phantom", "sim/" is "sim").
std::set<std::string> named_in(const std::string& prose) {
  std::set<std::string> names;
  const std::regex quoted_name("`([^`]+)`");
  for (auto it = std::sregex_iterator(prose.begin(), prose.end(), quoted_name);
       it != std::sregex_iterator(); ++it) {
    const std::string name = (*it)[1];
    names.insert(name.substr(0, name.find('/')));
  }
  return names;
}

std::set<std::string> entries(const fs::path& dir) {
  std::set<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.insert(e.path().filename());
  return out;
}

// A user's empty folder, where `pipelines/` is the repository's (the README's commands
// name pipelines/demo.yaml and pipelines/data/).
fs::path user_folder(const std::string& name) {
  fs::path dir = scratch_dir(name) / "home";
  fs::create_directories(dir);
  fs::create_directory_symlink(source_dir() / "pipelines", dir / "pipelines");
  return dir;
}

// How many of `bins` equal parts of the colour bar [lo, hi] hold at least 2 % of the wall's
// triangles (the outlet, region 2, left out), by their σ1 = the larger of
// cauchy_principal_kpa: the colours the picture can show.
int occupied_colour_bins(const vesica::io::VtuGrid& frame, double lo, double hi, int bins) {
  const vesica::io::VtuArray* stress = frame.cell_array("cauchy_principal_kpa");
  const vesica::io::VtuArray* region = frame.cell_array("region");
  if (!stress || !(hi > lo)) return 0;
  std::vector<int> count(static_cast<std::size_t>(bins), 0);
  int wall = 0;
  for (Eigen::Index t = 0; t < frame.triangles.rows(); ++t) {
    const auto at = [&](const vesica::io::VtuArray* a, int c) {
      return a->values[static_cast<std::size_t>(t * a->components + c)];
    };
    if (region && static_cast<int>(at(region, 0)) == 2) continue;
    const double sigma1 = std::max(at(stress, 0), at(stress, stress->components > 1 ? 1 : 0));
    const int bin = static_cast<int>(std::floor((sigma1 - lo) / (hi - lo) * bins));
    ++count[static_cast<std::size_t>(std::clamp(bin, 0, bins - 1))];
    ++wall;
  }
  return static_cast<int>(
      std::count_if(count.begin(), count.end(), [&](int n) { return n >= 0.02 * wall; }));
}

}  // namespace

// The block as one shell script, as typed: from the checkout (its `DATA=$PWD/...` line),
// then into ~/vesica-example, a folder outside it (HOME is the test's own). `make` is the
// build's and PATH the build's bin/.
TEST(ReadmeExample, TheStageCommandsRunFromAFolderOutsideTheCheckout) {
  const fs::path home = scratch_dir("readme-stages") / "home";
  fs::remove_all(home);
  fs::create_directories(home);
  const Snippet s = snippet("## Worked example");
  ASSERT_GE(s.lines.size(), 8u);
  std::string script = "set -e\ncd " + quoted(source_dir().string()) + "\n";
  for (const auto& line : s.lines) {
    if (line.rfind("make ", 0) == 0) continue;
    script += line.rfind("export PATH", 0) == 0
                  ? "export PATH=" + quoted(bin_dir().string()) + ":\"$PATH\"\n"
                  : line + "\n";
  }
  ASSERT_NE(script.find("cd ~/vesica-example"), std::string::npos) << script;
  write_text(home.parent_path() / "example.sh", script);
  const CommandResult r = run_command("HOME=" + quoted(home.string()) + " sh " +
                                          quoted((home.parent_path() / "example.sh").string()),
                                      home.parent_path());
  ASSERT_EQ(r.exit_code, 0) << script << "\n" << r.err;
  const fs::path dir = home / "vesica-example";
  std::set<std::string> named = named_in(s.prose.substr(0, s.prose.find("Each command")));
  EXPECT_EQ(entries(dir), named);
  EXPECT_TRUE(fs::exists(dir / ".vesica/bladder.ply.manifest.json"));
  EXPECT_TRUE(fs::exists(dir / "report/index.html"));
}

TEST(ReadmeExample, ThePipelineRunAndItsEditAndRerunWorkAsWritten) {
  const fs::path dir = user_folder("readme-edit");
  const Snippet run = snippet("## Worked example", "The same run as a pipeline file");
  ASSERT_EQ(run.lines.size(), 3u);
  for (const auto& line : run.lines) {
    const CommandResult r = type(line, dir);
    ASSERT_EQ(r.exit_code, 0) << line << "\n" << r.err;
  }
  EXPECT_NE(type(run.lines[1], dir).err.find("nothing to do, 6 stages are fresh"),
            std::string::npos);
  const std::size_t names = run.prose.find("names (");
  EXPECT_EQ(entries(dir / "out"),
            named_in(run.prose.substr(names, run.prose.find(": the stages'") - names)));
  EXPECT_EQ(entries(dir / "out/phantom"), std::set<std::string>{"dicom"});
  // The report's stress picture is not one colour: its frame's wall spreads over at least
  // four of eight equal parts of the colour bar it was drawn with.
  const auto facts = nlohmann::json::parse(slurp(dir / "out/report/wall-stress.json"));
  const vesica::io::VtuGrid frame =
      vesica::io::read_vtu(dir / "out/sim/series" / facts["frame"].get<std::string>());
  EXPECT_GE(occupied_colour_bins(frame, facts["colour_bar_kpa"][0].get<double>(),
                                 facts["colour_bar_kpa"][1].get<double>(), 8),
            4)
      << facts.dump();

  const Snippet edit = snippet("## Edit and rerun");
  ASSERT_EQ(edit.lines.size(), 5u);
  const fs::path ply = dir / "out/bladder.ply";
  const std::string generated = vesica::content_hash(ply);
  ASSERT_EQ(edit.lines[0].rfind("# MeshLab:", 0), 0u) << edit.lines[0];
  subdivide_in_meshlab(ply);
  const std::string saved = vesica::content_hash(ply);

  CommandResult r = type(edit.lines[1], dir);  // status
  EXPECT_EQ(r.exit_code, 1);                   // mesh, simulate and compare will run
  EXPECT_NE(r.out.find("surface   edited (kept): bladder.ply"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("mesh      stale: input bladder.ply changed"), std::string::npos) << r.out;
  r = type(edit.lines[2], dir);  // run
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("kept your edits: bladder.ply"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("3 of 6 stages ran"), std::string::npos) << r.err;
  EXPECT_EQ(vesica::content_hash(ply), saved);
  r = type(edit.lines[3], dir);  // run again
  EXPECT_NE(r.err.find("nothing to do, 5 stages are fresh, 1 kept with your edits"),
            std::string::npos)
      << r.err;
  r = type(edit.lines[4], dir);  // reset
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(vesica::content_hash(ply), generated);
  std::vector<fs::path> backups;
  for (const auto& e : fs::directory_iterator(dir / "out/.vesica/backup/surface"))
    backups.push_back(e.path());
  ASSERT_EQ(backups.size(), 1u);
  EXPECT_EQ(vesica::content_hash(backups[0] / "bladder.ply"), saved);
}
