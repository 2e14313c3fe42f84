#pragma once
// The common frame of every vesica executable: shared options (--report, --manifest,
// --json, --verbose), and one place that turns any error into a single line on stderr
// and an exit code: 0 success, 1 failure, 2 usage.
#include <functional>
#include <string>

// CLI11's App by reference only: the executables that build one include <CLI/CLI.hpp>
// themselves, and the libraries including this header do not parse CLI11.
namespace CLI {
class App;
}  // namespace CLI

namespace vesica {

struct CommonOptions {
  std::string report;    // summary JSON path
  std::string manifest;  // manifest JSON path
  bool json = false;     // print the summary JSON on stdout, nothing else
  bool verbose = false;
};

void add_common_options(CLI::App& app, CommonOptions& options);

// Parses argv into app, applies --json/--verbose to logging and progress, then runs body.
// Returns the process exit code.
int run_stage_main(CLI::App& app, int argc, char** argv, const CommonOptions& options,
                   const std::function<int()>& body);

// "unknown option --mu (did you mean --mu-kpa?)" for every unexpected long option left in
// app after a parse that threw CLI11's ExtrasError; `fallback` (CLI11's own text) when the
// extras are stray values only. Shared by the stage tools and the runner's commands.
std::string unknown_options_message(const CLI::App& app, const std::string& fallback);

// Manifest default: in the folder .vesica/ beside the report when one is given
// (.vesica/<report stem>.manifest.json), else beside the main output
// (.vesica/<output name>.manifest.json).
std::string default_manifest_path(const CommonOptions& options, const std::string& output);

}  // namespace vesica
