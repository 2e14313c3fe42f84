#include "vesica/core/StageMain.h"

#include <cstdio>
#include <filesystem>

#include <CLI/CLI.hpp>

#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/core/Progress.h"
#include "vesica/core/StageSafety.h"
#include "vesica/core/StagedOutputs.h"
#include "vesica/core/Suggest.h"
#include "vesica/core/UidScrub.h"
#include "vesica/core/Version.h"

namespace vesica {
namespace {

// Long option names of the app ("mu-kpa"), hidden ones left out.
std::vector<std::string> long_option_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* option : app.get_options())
    if (!option->get_group().empty())
      for (const auto& name : option->get_lnames()) names.push_back(name);
  return names;
}

}  // namespace

std::string unknown_options_message(const CLI::App& app, const std::string& fallback) {
  std::string message;
  for (const std::string& extra : app.remaining()) {
    if (extra.size() < 3 || extra.compare(0, 2, "--") != 0) continue;
    const std::string name = extra.substr(2, extra.find('=') - 2);
    const std::string match = closest_match(name, long_option_names(app));
    message += (message.empty() ? "" : "; ") + std::string("unknown option --") + name;
    if (!match.empty()) message += " (did you mean --" + match + "?)";
  }
  return message.empty() ? fallback : message;
}

void add_common_options(CLI::App& app, CommonOptions& options) {
  app.add_option("--report", options.report, "Write the stage summary (JSON) here");
  app.add_option("--manifest", options.manifest,
                 "Write the manifest (inputs, outputs, hashes, parameters) here");
  app.add_flag("--json", options.json, "Print the summary as JSON on stdout; no progress");
  app.add_flag("-v,--verbose", options.verbose, "More log detail");
  app.set_version_flag("--version", std::string(vesica::kVersionString));
}

int run_stage_main(CLI::App& app, int argc, char** argv, const CommonOptions& options,
                   const std::function<int()>& body) {
  const std::string tool = app.get_name();
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::Success&) {  // --parameters-json has printed the table
    return 0;
  } catch (const CLI::ExtrasError& e) {
    std::fprintf(stderr, "%s: usage error: %s (see %s --help)\n", tool.c_str(),
                 unknown_options_message(app, e.what()).c_str(), tool.c_str());
    return 2;
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "%s: usage error: %s (see %s --help)\n", tool.c_str(), e.what(),
                 tool.c_str());
    return 2;
  }
  set_quiet(options.json);
  configure_logging(options.json, options.verbose);
  ignore_file_size_signal();
  // The printed line, tool name included, stays within kMaxErrorLine.
  const auto error_line = [&](const char* what) {
    return single_line(without_uids(tool + ": error: " + what));
  };
  try {
    refuse_special_inputs(app);
    protect_command_line_inputs(app);
    begin_staging();  // every output replaced together, and only on success
    const int code = body();
    if (code == 0)
      commit_staged_outputs();
    else
      discard_staged_outputs();
    return code;
  } catch (const Error& e) {
    discard_staged_outputs();
    std::fprintf(stderr, "%s\n", error_line(e.what()).c_str());
    return e.exit_code();
  } catch (const std::exception& e) {
    discard_staged_outputs();
    std::fprintf(stderr, "%s\n", error_line(e.what()).c_str());
    return 1;
  }
}

std::string default_manifest_path(const CommonOptions& options, const std::string& output) {
  if (!options.manifest.empty()) return options.manifest;
  namespace fs = std::filesystem;
  // In the hidden folder .vesica/ (where `vesica run` keeps its manifests too), so that a
  // stage leaves beside its outputs only the files it was asked for.
  if (!options.report.empty()) {
    fs::path r(options.report);
    return (r.parent_path() / ".vesica" / (r.stem().string() + ".manifest.json")).string();
  }
  // "ct/" is the folder "ct": its manifest goes beside it, not inside it.
  fs::path out = fs::path(output).lexically_normal();
  if (!out.has_filename() && out.has_parent_path()) out = out.parent_path();
  return (out.parent_path() / ".vesica" / (out.filename().string() + ".manifest.json")).string();
}

}  // namespace vesica
