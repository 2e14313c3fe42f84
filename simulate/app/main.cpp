// vesica-simulate MESH -o OUTDIR: simulated cystometry (filling and voiding) of the
// bladder wall with the level-1 wall-urine model, or with --level 2 the Navier–Stokes
// urine on the tetrahedra. Its options are the simulate parameter table
// (SimulateParameters.h). See docs/simulate.md and docs/navier-stokes.md.
#include <filesystem>
#include <optional>

#include <CLI/CLI.hpp>

#include "ModelCardRun.h"
#include "VerificationStage.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/core/ParameterCli.h"
#include "vesica/core/Progress.h"
#include "vesica/core/StageMain.h"
#include "vesica/core/StageRecord.h"
#include "vesica/core/StagedOutputs.h"
#include "vesica/core/Units.h"
#include "vesica/simulate/ModelCardJson.h"
#include "vesica/simulate/SimulateParameters.h"
#include "vesica/simulate/SimulateSettings.h"
#include "vesica/simulate/materials/MaterialRegistry.h"
#include "vesica/simulate/protocol/CheckpointFile.h"
#include "vesica/simulate/protocol/Cystometry.h"
#include "vesica/simulate/wall/MeshReader.h"

namespace fs = std::filesystem;
using namespace vesica;
using namespace vesica::simulate;

namespace {

// What a checkpoint of this run is computed from (docs/simulate.md, "Checkpoint and
// resume"): the mesh's content, the model as its card says before the run, whether the
// series is written, and the command line without --resume, which the runner compares.
std::string checkpoint_identity(const WallModel& wall, const ModelCard& planned, bool series,
                                int argc, char** argv) {
  nlohmann::json arguments = nlohmann::json::array();
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) != "--resume") arguments.push_back(argv[i]);
  return nlohmann::json{{"inputs", {{{"path", wall.source_file}, {"hash", wall.source_hash}}}},
                        {"parameters", {{"model_card", planned}, {"series", series}}},
                        {"arguments", arguments}}
      .dump();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Cystometric filling and voiding of the bladder wall (level-1 FSI)",
               "vesica-simulate"};
  CommonOptions common;
  SimulateSettings c;
  ParameterTable table = parameter_table(c);
  std::string mesh, output, card_file;
  bool resume = false;
  app.add_option("mesh", mesh, ".vtu from vesica-mesh (or its .msh), or a surface .vtp/.stl (mm)")
      ->required();
  app.add_option("-o,--output", output, "output folder: history.csv, series.pvd, summary.json")
      ->required();
  add_parameter_options(app, table);
  app.add_option("--model-card", card_file,
                 "run the model a card describes (fit/model.json of vesica-compare --calibrate, "
                 "or a summary.json): no model parameter beside it (docs/simulate.md)")
      ->group("Parameters");
  app.add_flag("--resume", resume,
               "continue an interrupted run from its checkpoint (docs/simulate.md)");
  add_common_options(app, common);

  return run_stage_main(app, argc, argv, common, [&]() {
    StageRecord record("vesica-simulate", argc, argv);
    std::optional<ModelCard> card;
    if (!card_file.empty()) card = settings_from_card_file(card_file, app, table, c);
    ProtocolSettings& p = c.protocol;
    RunOptions& options = c.run;
    c.wall.posture = p.posture = c.posture;
    options.reference = c.wall.reference;
    options.output_dir = output;
    validate(p, options);  // before reading anything
    const MaterialSpec spec = card ? material_spec(card->material) : material_spec(c.material);
    make_material(spec);                    // reject bad parameters before reading anything
    check_febio_export(c, spec);            // and what FEBio cannot express
    if (is_verification(c.verification)) {  // issue 25: P–λ of a closed wall
      record.parameters() = table.values();
      record.parameters()["material_si"] = {{"name", spec.name}, {"params", spec.params}};
      return run_verification_stage(mesh, output, spec, c, record, common);
    }
    WallModel wall;
    {
      PhaseTimer timer(record, "read");
      wall = load_wall(mesh, c.wall);
    }
    if (card) check_card_mesh(*card, wall);
    record.add_input(mesh);
    Progress progress("simulate");  // silent with --json or off a terminal
    options.on_progress = [&](const std::string& step, double f) { progress.update(step, f); };
    record.parameters() = table.values();
    record.parameters()["material_si"] = {{"name", spec.name}, {"params", spec.params}};
    if (card) record.parameters()["model_card"] = card_file;
    if (card) record.add_input(card_file);
    options.checkpoints.file = checkpoint_path_for_manifest(default_manifest_path(common, output));
    options.checkpoints.identity = checkpoint_identity(
        wall, planned_model_card(wall, spec, p, options), options.write_series, argc, argv);
    options.checkpoints.resume = resume;
    // The output folder is written whole under a temporary name and replaces the earlier
    // one only when the run completed; a failed run's partial results are kept only where
    // they replace nothing.
    const fs::path out(output);
    const bool had_earlier = fs::exists(out);
    CystometryResult result;
    try {
      write_atomically(out, [&](const fs::path& tmp) {
        options.output_dir = tmp;
        if (options.level == 2) {
          fluid::FluidMesh urine;
          {
            PhaseTimer timer(record, "read");
            urine = read_urine(mesh);
          }
          PhaseTimer timer(record, "simulate");
          result = run_cystometry(wall, spec, p, options, &urine);
        } else {
          PhaseTimer timer(record, "simulate");
          result = run_cystometry(wall, spec, p, options);
        }
        record.summary() = result.summary;
        record.write(tmp / "summary.json", "");
        if (!result.completed && had_earlier)
          fail(mesh, result.failure, "the earlier results in " + output + " are kept");
      });
    } catch (const RunInterrupted& e) {  // the earlier output is intact
      std::fprintf(stderr, "%s\n",
                   single_line("vesica-simulate: " + std::string(e.what())).c_str());
      return 128 + e.signal;
    }
    record.add_output(out / "history.csv");
    if (options.write_series) record.add_output(out / "series.pvd");
    if (options.write_series && options.level == 2) record.add_output(out / "fluid.pvd");
    record.add_output(out / "summary.json");
    if (!result.completed) {    // no manifest: the runner reruns it next time
      commit_staged_outputs();  // nothing was there: the partial results are the user's
      fail(mesh, result.failure, "results up to that point are in " + output);
    }
    export_febio_if_asked(c, wall, result, record);           // what ran, as FEBio input
    record.write("", default_manifest_path(common, output));  // .vesica/<folder>.manifest.json
    std::error_code ec;                                       // a finished run needs no checkpoint
    fs::remove_all(options.checkpoints.file.parent_path(), ec);
    if (!common.report.empty()) record.write(common.report, "");
    if (common.json) std::cout << record.summary().dump(2) << std::endl;
    return 0;
  });
}
