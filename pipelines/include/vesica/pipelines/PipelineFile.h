#pragma once
// The pipeline file as written (YAML): stages with their inputs, outputs and parameters,
// named external inputs and an optional study. Positions are kept for error messages.
// Loading never throws: every problem goes to a Diagnostics list.
#include <filesystem>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "vesica/pipelines/Diagnostics.h"

namespace vesica::pipelines {

// A path as written: relative to the workdir, or "${inputs.name}" for an external input.
struct PathRef {
  std::string text;
  SourcePos pos;
};

// One `--key value` of a stage. `key` is the pipeline-file spelling (underscores).
struct Param {
  enum class Kind { Value, Flag, Omitted };  // Flag: `true`; Omitted: `false`
  std::string key;
  Kind kind = Kind::Value;
  std::string value;  // lists are already joined as a,b,c
  SourcePos pos;      // of the value
  SourcePos key_pos;  // of the key (for a study: of its `stage.param` key)
};

struct StageSpec {
  std::string name;
  std::string tool;  // defaults to the stage name
  SourcePos pos;
  SourcePos tool_pos;
  std::vector<PathRef> positional;                     // `input`
  std::vector<std::pair<std::string, PathRef>> named;  // `inputs` (map order kept)
  PathRef output;
  PathRef report;    // empty: default beside the output
  PathRef manifest;  // empty: default beside the output
  std::vector<Param> params;
};

struct ExternalInput {
  std::string name;
  std::string path;  // as written, relative to the pipeline file
  SourcePos pos;
};

// `study: matrix:` one axis: `stage.param: [values]`.
struct MatrixAxis {
  std::string stage;
  std::vector<Param> values;  // same key, one entry per value
  SourcePos pos;
};

// A parameter set on one stage by a study run.
struct Override {
  std::string stage;
  Param param;
};

struct Variant {
  std::string name;
  std::vector<Override> overrides;
  SourcePos pos;
};

// `study: limits:` one bound on a read-out (StudyMetrics.h): `pdet_at_500ml_cmh2o: {max: 40}`.
struct StudyLimit {
  std::string metric;
  std::optional<double> min, max;
  SourcePos pos;
};

struct StudySpec {
  // A study larger than this is refused unless the file raises `max_runs`: a few lines of
  // matrix multiply into more runs than a machine can hold (9 axes of 10 values: 10^9).
  static constexpr long long kDefaultMaxRuns = 1000;

  std::vector<MatrixAxis> matrix;
  std::vector<Variant> variants;
  // `study: uncertainty:` named ends of the model's uncertain ranges (`soft`, `stiff`), each
  // a set of stage.param values like a variant's: every run is also run once per end, its
  // own values changed by the end's, and the page draws the ends as bands around it.
  std::vector<Variant> uncertainty;
  std::string question;            // `study: question:` the design question, in words
  std::vector<StudyLimit> limits;  // what a variant must meet to answer it "pass"
  long long max_runs = kDefaultMaxRuns;
  SourcePos max_runs_pos;
  SourcePos pos;
  bool present() const { return !matrix.empty() || !variants.empty() || !uncertainty.empty(); }
};

struct PipelineSpec {
  std::filesystem::path file;  // absolute
  std::string name;
  std::string workdir = ".";  // relative to the file's folder
  SourcePos workdir_pos;
  std::vector<ExternalInput> externals;
  std::vector<StageSpec> stages;  // file order
  StudySpec study;

  // By name, in O(1): a file of many stages is checked in time linear in its size.
  const StageSpec* find_stage(const std::string& name) const;

 private:
  mutable std::unordered_map<std::string, std::size_t> stage_index_;  // built on first use
  mutable std::size_t indexed_ = 0;                                   // stages in the index
};

PipelineSpec load_pipeline_file(const std::filesystem::path& file, Diagnostics& diagnostics);
// Same, from text (tests); `file` only names the source.
PipelineSpec parse_pipeline_text(const std::string& text, const std::filesystem::path& file,
                                 Diagnostics& diagnostics);

}  // namespace vesica::pipelines
