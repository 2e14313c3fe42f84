#pragma once
// What the runner executes: every stage (and every study copy of a stage) with its exact
// argument list, its paths relative to the workdir and the stages it depends on, in an
// order where each stage comes after its dependencies.
#include <filesystem>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "vesica/pipelines/Diagnostics.h"
#include "vesica/pipelines/PathIndex.h"
#include "vesica/pipelines/PipelineFile.h"

namespace vesica::pipelines {

struct PlannedStage {
  std::string id;       // "surface", or "surface@variant" for a study copy
  std::string stage;    // the stage's name in the file
  std::string variant;  // empty when shared by every run
  // A copy at one end of the study's uncertainty: the end, and the run it bounds ("" for
  // the shared run). Empty otherwise.
  std::string bound;
  std::string bound_of;
  std::string tool;
  std::filesystem::path executable;
  std::vector<std::string> argv;    // arguments after the program, exactly as passed
  std::vector<std::string> inputs;  // relative to the workdir (or absolute)
  std::string output;               // relative to the workdir
  // Files written besides the output: the tool's declared side outputs and the files its
  // parameters name (export_feb), relative to the workdir; backed up like the output.
  std::vector<std::string> side_outputs;
  std::string report;
  std::string manifest;
  std::vector<Param> params;
  std::vector<std::size_t> deps;  // indices into Plan::stages
};

struct Plan {
  std::string name;
  std::filesystem::path file;
  std::filesystem::path workdir;  // absolute
  std::vector<PlannedStage> stages;
  std::vector<std::string> unchecked_tools;  // tools without a parameter table: params unchecked
  std::string question;                      // the study's design question (study.csv/.html)
  std::vector<StudyLimit> limits;            // and what answers it "pass"

  // Index of the stage with this id, or -1.
  long index_of(const std::string& id) const;
  // The stages a user means by `name`: the stage with that id, or every study copy of the
  // stage with that name. Throws vesica::Error (usage) with a suggestion when none.
  std::vector<std::size_t> named(const std::string& name) const;
  // Index of the stage that writes `path` (or the folder containing it, a side output, or
  // the report), or -1; O(log n) after the first call.
  long producer_of(const std::string& path) const;
  // Every stage downstream of `index` (not including it).
  std::vector<std::size_t> downstream_of(std::size_t index) const;
  std::filesystem::path in_workdir(const std::string& path) const;

 private:
  struct Producers {
    PathIndex outputs;
    std::unordered_map<std::string, long> reports;
  };
  mutable std::shared_ptr<Producers> producers_;  // built by producer_of for `indexed_` stages
  mutable std::size_t indexed_ = 0;
};

struct PlanOptions {
  std::filesystem::path workdir_override;  // empty: the file's `workdir`, or for a pipeline
                                           // installed with vesica ./<pipeline name>
  std::filesystem::path bin_dir;           // where vesica-<tool> executables live
};

// Checks parameters (ParameterCheck.h), tools, paths, external inputs, duplicate outputs and
// cycles; expands the study.
// On problems the diagnostics are filled and the plan should not be run.
Plan build_plan(const PipelineSpec& spec, const PlanOptions& options, Diagnostics& diagnostics);

// The stage tools vesica ships; any other `vesica-<tool>` found in bin_dir is accepted too
// (the tests register their own stage commands that way).
const std::vector<std::string>& builtin_tools();

// Folder of the running executable (/proc/self/exe).
std::filesystem::path own_bin_dir();

// Normalised generic form without a trailing slash: "a/./b/" -> "a/b".
std::string normal_path(const std::string& path);

}  // namespace vesica::pipelines
