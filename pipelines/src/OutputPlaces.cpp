#include "OutputPlaces.h"

#include <set>

namespace fs = std::filesystem;

namespace vesica::pipelines::detail {
namespace {

// "a/b/" -> "a/b": the same folder.
fs::path folder_form(fs::path p) {
  p = p.lexically_normal();
  while (!p.has_filename() && p.has_parent_path() && p != p.root_path()) p = p.parent_path();
  return p;
}

bool holds(const fs::path& folder_given, const fs::path& path_given) {
  const fs::path folder = folder_form(folder_given), path = folder_form(path_given);
  auto f = folder.begin();
  auto p = path.begin();
  for (; f != folder.end(); ++f, ++p)
    if (p == path.end() || *f != *p) return false;
  return true;
}

// What must survive every run, with how a message names it.
std::vector<std::pair<fs::path, std::string>> protected_paths(const Plan& plan,
                                                              const PipelineSpec& spec,
                                                              const PlannedStage& stage) {
  std::vector<std::pair<fs::path, std::string>> kept = {
      {plan.workdir, "the workdir"}, {spec.file.lexically_normal(), "the pipeline file"}};
  for (const ExternalInput& e : spec.externals)
    kept.emplace_back((spec.file.parent_path() / e.path).lexically_normal(),
                      "the external input '" + e.name + "'");
  for (const std::string& input : stage.inputs)
    kept.emplace_back(plan.in_workdir(input), "its input '" + input + "'");
  return kept;
}

}  // namespace

void check_output_places(const Plan& plan, const PipelineSpec& spec, Diagnostics& diagnostics) {
  std::set<std::string> reported;  // a study's copies of one stage share its line
  for (const PlannedStage& stage : plan.stages) {
    const StageSpec* s = spec.find_stage(stage.stage);
    if (!s || stage.output.empty()) continue;
    const fs::path output = plan.in_workdir(stage.output);
    for (const auto& [path, what] : protected_paths(plan, spec, stage))
      if (holds(output, path) && reported.insert(stage.stage + what).second)
        diagnostics.add(s->output.pos,
                        "output '" + s->output.text + "' of stage '" + stage.stage +
                            (folder_form(output) == folder_form(path) ? "' is " : "' holds ") +
                            what + "; vesica never replaces it");
  }
}

}  // namespace vesica::pipelines::detail
