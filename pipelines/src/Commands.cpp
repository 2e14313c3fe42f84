#include "vesica/pipelines/Commands.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>

#include <CLI/CLI.hpp>

#include "Joined.h"
#include "RunnerTerminal.h"
#include "vesica/core/Error.h"
#include "vesica/core/StageMain.h"
#include "vesica/core/Suggest.h"
#include "vesica/core/Version.h"
#include "vesica/pipelines/AcceptEdits.h"
#include "vesica/pipelines/ParameterReference.h"
#include "vesica/pipelines/Plan.h"
#include "vesica/pipelines/Runner.h"
#include "vesica/pipelines/SignalRelay.h"
#include "vesica/pipelines/SnakemakeExport.h"
#include "vesica/pipelines/Staleness.h"
#include "vesica/pipelines/StateFolder.h"
#include "vesica/pipelines/StudyReport.h"
#include "vesica/pipelines/WorkdirLock.h"

namespace fs = std::filesystem;

namespace vesica::pipelines {
namespace {

using detail::joined;

constexpr const char* kHelp = R"(vesica — CT to bladder simulation, driven by a pipeline file

Usage:
  vesica validate FILE                 check a pipeline file (exit 2 on problems)
  vesica run FILE [options]            run the stale stages in dependency order
      --only STAGE    only this stage (repeatable; runs it if stale)
      --from STAGE    rerun this stage and everything downstream
      --force         run every selected stage, stale or not
      --discard-edits STAGE  rerun STAGE although you edited its outputs (they are
                      saved under WORKDIR/.vesica/backup/ first)
      --workdir DIR   outputs go here instead of the file's workdir
      -j N            run up to N independent stages at once
      -k, --keep-going  after a failure, still run the stages that do not depend on it
      --json          no progress; print the result as JSON
  vesica status FILE [--workdir DIR] [--json]
                                       each stage: fresh, stale, missing, edited (kept)
                                       or failed, and why; exit 1 when any would run
  vesica reset FILE STAGE... [--workdir DIR] [-j N] [--json]
                                       regenerate edited outputs: run --discard-edits
  vesica accept FILE STAGE... [--workdir DIR]
                                       make the edited files the stages' own outputs
  vesica export --snakemake FILE [--workdir DIR] > Snakefile
                                       the same pipeline as a Snakemake workflow
  vesica parameters [TOOL] [--json]    every stage parameter: key, unit, default, range
                                       (docs/parameters.md is this output)
  vesica phantom OUT_DIR [args...]     synthetic CT or MR (--modality mr): runs
                                       vesica-phantom -o OUT_DIR args...
  vesica help | --version

A file you edit in a workdir (a label map in Slicer, a surface in MeshLab, a mesh in
Gmsh) is kept: its stage does not run again, the stages that read it do.
Stage executables vesica-<tool> are looked up beside this program.
See docs/pipeline-file.md for the file format and the staleness rules.
)";

struct Loaded {
  Plan plan;
  int exit_code = 0;
};

// Loads and checks the file; prints FILE:LINE:COL problems and sets exit code 2.
Loaded load(const std::string& file, const std::string& workdir) {
  Diagnostics d;
  const PipelineSpec spec = load_pipeline_file(file, d);
  Loaded l;
  // The plan is built even after file problems, so that one pass reports them all.
  l.plan = build_plan(spec, {workdir, own_bin_dir()}, d);
  if (!d.empty()) {
    std::fputs(d.format(file).c_str(), stderr);
    l.exit_code = 2;
  }
  return l;
}

int parse(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ExtrasError& e) {
    std::fprintf(stderr, "vesica %s: usage error: %s (see vesica help)\n", app.get_name().c_str(),
                 unknown_options_message(app, e.what()).c_str());
    return 2;
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::fprintf(stderr, "vesica %s: usage error: %s (see vesica help)\n", app.get_name().c_str(),
                 e.what());
    return 2;
  }
  return -1;
}

int validate(int argc, char** argv) {
  CLI::App app("Check a pipeline file", "validate");
  std::string file, workdir;
  app.add_option("file", file, "Pipeline file")->required();
  app.add_option("--workdir", workdir, "Workdir to check inputs against");
  if (int rc = parse(app, argc, argv); rc >= 0) return rc;
  Loaded l = load(file, workdir);
  if (l.exit_code) return l.exit_code;
  std::string unchecked;
  for (const auto& tool : l.plan.unchecked_tools)
    unchecked += (unchecked.empty() ? "" : ", ") + tool;
  std::printf("%s: ok (%zu stages)%s\n", file.c_str(), l.plan.stages.size(),
              unchecked.empty()
                  ? ""
                  : ("; params of " + unchecked + " not checked (no parameter table yet)").c_str());
  return 0;
}

int parameters(int argc, char** argv) {
  CLI::App app("Print the stages' parameter tables", "parameters");
  std::string tool;
  bool json = false;
  app.add_option("tool", tool, "Only this stage tool");
  app.add_flag("--json", json, "JSON instead of Markdown");
  if (int rc = parse(app, argc, argv); rc >= 0) return rc;
  if (json)
    std::cout << parameter_reference_json(tool).dump(2) << "\n";
  else
    std::cout << parameter_reference_markdown(tool);
  return 0;
}

// "kept your edits: bladder.ply (surface); ..." and how to undo or adopt them.
std::string kept_edits_line(const std::vector<std::string>& files, const Plan& plan) {
  return "kept your edits: " + joined(files) +
         "; `vesica reset` regenerates a stage's outputs (yours are saved in " +
         (plan.workdir / state::kFolder / "backup").string() +
         "), `vesica accept` makes yours its own";
}

int status(int argc, char** argv) {
  CLI::App app("Show which stages are fresh", "status");
  std::string file, workdir;
  bool json = false;
  app.add_option("file", file, "Pipeline file")->required();
  app.add_option("--workdir", workdir, "Outputs folder");
  app.add_flag("--json", json, "JSON instead of a table");
  if (int rc = parse(app, argc, argv); rc >= 0) return rc;
  Loaded l = load(file, workdir);
  if (l.exit_code) return l.exit_code;
  const auto st = assess(l.plan);
  const bool any_to_run =
      std::any_of(st.begin(), st.end(), [](const StageStatus& s) { return s.will_run(); });
  if (json) {
    nlohmann::json j = nlohmann::json::array();
    for (std::size_t i = 0; i < st.size(); ++i) {
      nlohmann::json stage = {{"stage", l.plan.stages[i].id},
                              {"state", to_string(st[i].state)},
                              {"reason", st[i].reason}};
      if (!st[i].edited.empty()) stage["edited"] = st[i].edited;
      j.push_back(stage);
    }
    std::cout << j.dump(2) << "\n";
    return any_to_run ? 1 : 0;
  }
  std::size_t width = 5;
  for (const auto& s : l.plan.stages) width = std::max(width, s.id.size());
  std::printf("%-*s  %s\n", static_cast<int>(width), "STAGE", "STATE");
  std::vector<std::string> kept;
  for (std::size_t i = 0; i < st.size(); ++i) {
    std::printf("%-*s  %s\n", static_cast<int>(width), l.plan.stages[i].id.c_str(),
                st[i].line().c_str());
    for (const auto& f : st[i].edited) kept.push_back(f + " (" + l.plan.stages[i].id + ")");
  }
  if (!kept.empty()) std::printf("%s\n", kept_edits_line(kept, l.plan).c_str());
  return any_to_run ? 1 : 0;
}

// A study with simulations gets its table and page after every run that changed something (or lost
// them), so a run where everything is fresh writes nothing. Returns whether they were written.
bool update_study_outputs(const Plan& plan, const RunResult& r) {
  const auto has = [&](auto predicate) {
    return std::any_of(plan.stages.begin(), plan.stages.end(), predicate);
  };
  if (!has([](const PlannedStage& s) { return !s.variant.empty(); }) ||
      !has([](const PlannedStage& s) { return s.tool == "simulate"; }))
    return false;
  const bool missing =
      !fs::exists(plan.workdir / "study.csv") || !fs::exists(plan.workdir / "study.html");
  if (r.ran().empty() && r.ok && !missing) return false;
  const StudyReport report = StudyReport::collect(plan, &r);
  write_study_outputs(plan, report);
  return true;
}

// Runs the plan under the workdir's lock; shared by `run` and `reset`.
int execute(const Loaded& l, RunOptions options, bool json) {
  detail::RunnerTerminal terminal(::isatty(STDERR_FILENO) != 0, !json);
  // Stages show their progress only on a terminal; theirs is the runner's pipe, so the
  // runner asks for it and draws it, or logs a line per step (vesica/core/Progress.h).
  if (terminal.shows_progress()) ::setenv("VESICA_PROGRESS", "1", 1);
  options.capture = json;
  if (!json) {
    options.progress = [&](const std::string& line) { terminal.line(line); };
    options.progress_line = [&](const std::string& text) { terminal.progress(text); };
  }
  const WorkdirLock lock(l.plan.workdir, [&](long pid) {
    if (!json)
      terminal.line("vesica: waiting for PID " + std::to_string(pid) + ", which is working in " +
                    l.plan.workdir.string() + " (" + state::lock_path() + ")");
  });
  const RunResult r = run_plan(l.plan, options);
  terminal.clear();
  if (update_study_outputs(l.plan, r) && !json)
    terminal.line("vesica: study table and page: " + (l.plan.workdir / "study.csv").string() +
                  ", " + (l.plan.workdir / "study.html").string());
  if (json) std::cout << r.to_json().dump(2) << "\n";
  if (!json && !r.kept_files().empty())
    terminal.line("vesica: " + kept_edits_line(r.kept_files(), l.plan));
  if (r.interrupted_by) {
    std::vector<std::string> stopped;
    for (const auto& s : r.stages)
      if (s.action == "interrupted") stopped.push_back(s.id);
    if (!json)
      terminal.line(std::string("vesica: interrupted by ") + signal_name(r.interrupted_by) + ": " +
                    (stopped.empty() ? "no stage was running"
                                     : joined(stopped) + " stopped and will run again") +
                    "; " + std::to_string(r.ran().size()) + " stages finished before");
    return 128 + r.interrupted_by;
  }
  if (!r.ok) {
    const auto& failed = r.stages[static_cast<std::size_t>(l.plan.index_of(r.failed_stage))];
    std::fprintf(stderr, "vesica: stage '%s' failed (exit %d): %s\n", r.failed_stage.c_str(),
                 failed.exit_code, r.failure_line.c_str());
    return 1;
  }
  if (!json) {
    const std::size_t ran = r.ran().size();
    const auto kept = static_cast<std::size_t>(
        std::count_if(r.stages.begin(), r.stages.end(),
                      [](const StageOutcome& s) { return s.action == "kept"; }));
    if (ran == 0)
      terminal.line("vesica: nothing to do, " + std::to_string(r.stages.size() - kept) +
                    " stages are fresh" +
                    (kept ? ", " + std::to_string(kept) + " kept with your edits" : ""));
    else
      terminal.line("vesica: " + std::to_string(ran) + " of " + std::to_string(r.stages.size()) +
                    " stages ran; outputs in " + l.plan.workdir.string());
  }
  return 0;
}

// What `run` and `reset` share: the file, the workdir, -j and --json.
struct Execution {
  std::string file, workdir;
  bool json = false;
  RunOptions options;

  void add_to(CLI::App& app) {
    app.add_option("file", file, "Pipeline file")->required();
    app.add_option("--workdir", workdir, "Outputs folder");
    app.add_option("-j,--jobs", options.jobs, "Stages run at once")->check(CLI::PositiveNumber);
    app.add_flag("--json", json, "Print the result as JSON, no progress");
  }
  int operator()() const {
    const Loaded l = load(file, workdir);
    return l.exit_code ? l.exit_code : execute(l, options, json);
  }
};

int run(int argc, char** argv) {
  CLI::App app("Run the stale stages", "run");
  Execution e;
  e.add_to(app);
  app.add_option("--only", e.options.only, "Only these stages");
  app.add_option("--from", e.options.from, "Rerun from these stages on");
  app.add_flag("--force", e.options.force, "Run every selected stage");
  app.add_option("--discard-edits", e.options.discard_edits,
                 "Rerun these stages although their outputs were edited (saved first)");
  app.add_flag("-k,--keep-going", e.options.keep_going,
               "After a failure, run the stages that do not depend on it");
  if (int rc = parse(app, argc, argv); rc >= 0) return rc;
  return e();
}

int reset(int argc, char** argv) {
  CLI::App app("Regenerate the outputs of stages whose outputs were edited", "reset");
  Execution e;
  e.add_to(app);
  app.add_option("stages", e.options.discard_edits, "Stages to regenerate")->required();
  if (int rc = parse(app, argc, argv); rc >= 0) return rc;
  return e();
}

int accept(int argc, char** argv) {
  CLI::App app("Make the edited outputs of stages their own", "accept");
  std::string file, workdir;
  std::vector<std::string> stages;
  app.add_option("file", file, "Pipeline file")->required();
  app.add_option("stages", stages, "Stages whose edited outputs to accept")->required();
  app.add_option("--workdir", workdir, "Outputs folder");
  if (int rc = parse(app, argc, argv); rc >= 0) return rc;
  Loaded l = load(file, workdir);
  if (l.exit_code) return l.exit_code;
  const WorkdirLock lock(l.plan.workdir, [&](long pid) {
    std::fprintf(stderr, "vesica: waiting for PID %ld, which is working in %s\n", pid,
                 l.plan.workdir.c_str());
  });
  for (const auto& name : stages)
    for (std::size_t i : l.plan.named(name)) {
      const std::string& id = l.plan.stages[i].id;
      const std::vector<std::string> files = accept_edits(l.plan, i);
      if (files.empty())
        std::fprintf(stderr, "vesica: %s: nothing to accept, its outputs are as it wrote them\n",
                     id.c_str());
      else
        std::fprintf(stderr,
                     "vesica: %s: %s accepted as its output; the stages that read it run next "
                     "time\n",
                     id.c_str(), joined(files).c_str());
    }
  return 0;
}

int export_workflow(int argc, char** argv) {
  CLI::App app("Write the pipeline as a workflow for another engine", "export");
  std::string file, workdir;
  bool snakemake = false;
  app.add_option("file", file, "Pipeline file")->required();
  app.add_flag("--snakemake", snakemake, "Snakemake workflow (Snakefile) on stdout")->required();
  app.add_option("--workdir", workdir, "Outputs folder");
  if (int rc = parse(app, argc, argv); rc >= 0) return rc;
  Loaded l = load(file, workdir);
  if (l.exit_code) return l.exit_code;
  std::cout << snakemake_workflow(l.plan);
  return 0;
}

// Replaces this process with vesica-phantom, so its output and exit code are the user's.
int phantom(int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') {
    std::fputs("usage: vesica phantom OUT_DIR [vesica-phantom options...]\n", stderr);
    return 2;
  }
  const fs::path exe = own_bin_dir() / "vesica-phantom";
  std::vector<std::string> args = {exe.string(), "-o", argv[1]};
  for (int i = 2; i < argc; ++i) args.emplace_back(argv[i]);
  std::vector<char*> c_args;
  c_args.reserve(args.size() + 1);
  for (auto& a : args) c_args.push_back(a.data());
  c_args.push_back(nullptr);
  ::execv(c_args[0], c_args.data());
  std::fprintf(stderr, "vesica: error: %s: cannot be started (build vesica-phantom first)\n",
               exe.c_str());
  return 1;
}

}  // namespace

int vesica_main(int argc, char** argv) {
  const std::vector<std::string> commands = {"validate", "run",     "status", "reset",     "accept",
                                             "export",   "phantom", "help",   "parameters"};
  if (argc < 2) {
    std::fputs(kHelp, stderr);
    return 2;
  }
  const std::string command = argv[1];
  try {
    if (command == "help" || command == "--help" || command == "-h") {
      std::fputs(kHelp, stdout);
      return 0;
    }
    if (command == "--version") {
      std::printf("%s\n", kVersionString);
      return 0;
    }
    if (command == "validate") return validate(argc - 1, argv + 1);
    if (command == "run") return run(argc - 1, argv + 1);
    if (command == "status") return status(argc - 1, argv + 1);
    if (command == "reset") return reset(argc - 1, argv + 1);
    if (command == "accept") return accept(argc - 1, argv + 1);
    if (command == "export") return export_workflow(argc - 1, argv + 1);
    if (command == "phantom") return phantom(argc - 1, argv + 1);
    if (command == "parameters") return parameters(argc - 1, argv + 1);
    std::fprintf(stderr, "vesica: unknown command '%s'%s (see vesica help)\n", command.c_str(),
                 did_you_mean(command, commands).c_str());
    return 2;
  } catch (const Error& e) {
    std::fprintf(stderr, "vesica: error: %s\n", e.what());
    return e.exit_code();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vesica: error: %s\n", e.what());
    return 1;
  }
}

}  // namespace vesica::pipelines
