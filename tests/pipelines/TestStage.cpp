// vesica-teststage: a tiny stage command for the runner's tests. It follows the stage
// contract (inputs, -o, --report, --manifest via vesica::StageRecord, atomic writes) and
// does something whose result is known by hand: the output is the concatenation of its
// inputs (a folder input contributes its files in name order) followed by one line
// "<label>\n". `--dir` makes the output a folder holding that text as data.txt.
// `--progress-steps N` reports N steps through vesica::Progress, 100 ms apart.
#include <fstream>
#include <sstream>
#include <thread>

#include <CLI/CLI.hpp>

#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/Progress.h"
#include "vesica/core/StageMain.h"
#include "vesica/core/StageRecord.h"
#include "vesica/core/StagedOutputs.h"

namespace fs = std::filesystem;

namespace {

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) vesica::fail(p.string(), "cannot be read");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string read_input(const fs::path& p) {
  if (!fs::exists(p)) vesica::fail(p.string(), "does not exist");
  if (!fs::is_directory(p)) return read_file(p);
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(p))
    if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::string text;
  for (const auto& f : files) text += read_file(f);
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Test stage: concatenates its inputs and appends a label", "vesica-teststage");
  vesica::CommonOptions common;
  std::vector<std::string> inputs;
  std::string output, label = "stage", aux;
  bool fail = false, fail_after_writing = false, dir = false;
  int sleep_ms = 0, progress_steps = 0;
  app.add_option("inputs", inputs, "Input files or folders");
  app.add_option("-o,--output", output, "Output file (or folder with --dir)")->required();
  app.add_option("--label", label, "Line appended to the output");
  app.add_option("--aux", aux, "One more input, appended after the positional ones");
  app.add_flag("--fail", fail, "Fail after reading the inputs, writing nothing");
  app.add_flag("--fail-after-writing", fail_after_writing,
               "Write everything, manifest included, then fail (like a simulation that stalls)");
  app.add_flag("--dir", dir, "Write a folder with data.txt instead of a file");
  app.add_option("--sleep-ms", sleep_ms, "Wait this long before writing (parallel tests)");
  app.add_option("--progress-steps", progress_steps, "Report this many steps, 100 ms apart");
  vesica::add_common_options(app, common);
  return vesica::run_stage_main(app, argc, argv, common, [&] {
    vesica::StageRecord record("teststage", argc, argv);
    record.parameters()["label"] = label;
    std::string text;
    for (const auto& in : inputs) {
      text += read_input(in);
      record.add_input(in);
    }
    if (!aux.empty()) {
      text += read_input(aux);
      record.add_input(aux);
    }
    text += label + "\n";
    if (fail) vesica::fail(output, "told to fail", "remove --fail");
    if (sleep_ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(sleep_ms));
    if (progress_steps > 0) {
      vesica::Progress progress("teststage");
      for (int step = 1; step <= progress_steps; ++step) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        progress.update("step " + std::to_string(step) + "/" + std::to_string(progress_steps),
                        static_cast<double>(step) / progress_steps);
      }
    }
    if (dir) {
      vesica::write_atomically(output, [&](const fs::path& tmp) {
        fs::create_directories(tmp);
        std::ofstream(tmp / "data.txt", std::ios::binary) << text;
      });
    } else {
      vesica::write_text_atomically(output, text);
    }
    record.add_output(output);
    record.summary()["bytes"] = text.size();
    record.write(common.report, vesica::default_manifest_path(common, output));
    if (fail_after_writing) {  // as vesica-simulate keeps a stalled run's results
      vesica::commit_staged_outputs();
      vesica::fail(output, "told to fail after writing");
    }
    return 0;
  });
}
