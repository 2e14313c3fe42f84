#pragma once
// Simulated cystometry (docs/physics.md §4, §5, §7): filling at the infusion rate to
// capacity, an optional hold, then voiding by the detrusor's contraction (or straining)
// through the urethra law, recorded as a history and summarized with the ICS numbers. One
// protocol runs over every cavity model: level 0, the lumped sphere-equivalent bladder
// (§11); level 1, the urine as an enclosed incompressible volume with a hydrostatic
// pressure solved together with the wall (bordered Newton, volume control); level 2, the
// urine as a Navier–Stokes flow on its tetrahedra, solved monolithically with the wall.
//
// This is the stable in-process API used by vesica-simulate, the calibration in compare
// and the studies:
//   WallModel wall = load_wall("bladder.vtu", WallOptions{});
//   CystometryResult r = run_cystometry(wall, {"neo-hookean", {{"mu", 5e3}, {"K", 1e4}}},
//                                       ProtocolSettings{}, RunOptions{});
// RunOptions{} writes nothing (fast repeated calls); set output_dir for files, and
// filling_only to stop at capacity. Level 2 also needs the urine tetrahedra as read
// (read_urine in MeshReader.h) and RunOptions::level = 2.
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "vesica/io/HistoryCsv.h"
#include "vesica/simulate/ModelCard.h"
#include "vesica/simulate/materials/Material.h"
#include "vesica/simulate/protocol/CystometrySettings.h"
#include "vesica/simulate/wall/WallLoading.h"
#include "vesica/simulate/wall/WallModel.h"

namespace vesica::simulate {

namespace fluid {
struct FluidMesh;
}

// One row of history.csv (clinical units, named by the suffixes); io owns the file.
using HistoryRow = io::HistoryRow;

// Thrown out of run_cystometry when SIGTERM or SIGINT stopped a run that writes checkpoints
// (RunOptions::checkpoints), after the checkpoint of the step it arrived in; what() says
// where the checkpoint is. The caller exits with 128 + signal.
struct RunInterrupted : std::runtime_error {
  RunInterrupted(int signal, const std::string& what) : std::runtime_error(what), signal(signal) {}
  int signal;
};

struct CystometryResult {
  std::vector<HistoryRow> history;
  nlohmann::json summary;          // the keys of summary.json
  bool completed = false;          // false: a step failed after cut-backs; see failure
  std::string failure;             // "step failed at t = .. s, V = .. ml: <reason>"
  std::vector<std::string> notes;  // what the user should know (e.g. no voiding drive)
  ModelCard card;                  // what ran (also the summary's "model_card")
};

// Throws vesica::Error (usage) for settings or options no run can follow (both levels).
// With the stress-free reference volume (reference_ml > 0) also for a protocol beyond the
// geometry's limits; without it (0: the wall is not read yet) only what needs no geometry,
// so that a caller can refuse bad input before reading anything.
void validate(const ProtocolSettings& settings, const RunOptions& options,
              double reference_ml = 0.0);

// Validates (validate()) before computing anything. Level 2 (options.level == 2) needs
// `urine`: the tetrahedra as read, whose nodes 0..N−1 are the imaged wall's (read_urine);
// they are mapped onto the stress-free reference wall here. A step that fails after
// cut-backs does not throw: the result holds the history so far, completed = false and
// the reason (and the files written so far when output_dir is set).
CystometryResult run_cystometry(const WallModel& wall, const MaterialSpec& material,
                                const ProtocolSettings& settings, const RunOptions& options,
                                const fluid::FluidMesh* urine = nullptr);

// The model card of a run before it runs (ModelCard.h): the material resolved, the wall's
// source and reference options, the protocol and numerics; no hand-over yet, and the
// reference volume of the wall as given (run_cystometry's card has the prestressed one).
ModelCard planned_model_card(const WallModel& wall, const MaterialSpec& material,
                             const ProtocolSettings& settings, const RunOptions& options);

// What emptied the bladder, from the summary's voiding_drive: "voided by detrusor
// contraction", "voided by abdominal straining" or "not voided".
std::string history_label(const CystometryResult& result);

// history.csv (io's text, HistoryCsv.h) after '#' comment lines (the readers skip them):
// "# vesica-simulate cystometry, <history_label>" saying which drive voided, then the
// model card in words with its units (model_card_lines), written atomically.
void write_labelled_history(const CystometryResult& result, const std::filesystem::path& csv);

}  // namespace vesica::simulate
