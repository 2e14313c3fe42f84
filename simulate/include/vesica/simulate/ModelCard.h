#pragma once
// The model card (docs/simulate.md, "The model card"): what one simulated cystometry ran,
// as a typed record that travels with its results. The wall material with every parameter
// as it ran (the named material's defaults resolved, SI), the stress-free reference and
// its volume, the protocol with its voiding drive and urethra law, the level the run
// started at and every hand-over between levels, and the mesh it ran on. vesica-simulate
// writes it into summary.json ("model_card") and the history.csv header; compare, its
// report, the study page, the Python module, the FEBio export and the checkpoint read it
// instead of guessing from a manifest or a file name; `vesica-simulate --model-card FILE`
// runs it again. JSON only at the edges: ModelCardJson.h. Its library
// (vesica_simulate_parameters) links core only, so that the runner reads a card without
// the simulator.
#include <string>
#include <vector>

#include "vesica/simulate/protocol/CystometrySettings.h"
#include "vesica/simulate/wall/WallLoading.h"

namespace vesica::simulate {

// One Maxwell branch of the wall (docs/physics.md §2.4): strength β (-) and relaxation
// time τ (s).
struct MaxwellBranchValues {
  double beta = 0.0;
  double tau_s = 0.0;
  bool operator==(const MaxwellBranchValues& o) const { return beta == o.beta && tau_s == o.tau_s; }
};

// The wall material as it ran, SI (docs/physics.md §2): the registry's name and each
// parameter of its law, given or the named material's default (docs/parameters.md, "The
// parameter catalogue").
struct MaterialCard {
  std::string name;       // bladder, neobladder, neo-hookean, maxwell, fibers
  double mu_pa = 0.0;     // shear modulus of the matrix
  double k_pa = 0.0;      // bulk modulus K
  double beta_vol = 0.0;  // Ogden volumetric exponent (0: K/2 (ln J)², §2.3)
  bool fibers = false;    // the law has the two fiber families (k1, k2 apply)
  double k1_pa = 0.0;
  double k2 = 0.0;
  std::vector<MaxwellBranchValues> branches;  // none: elastic
  // The detrusor muscle (§2.6); it acts when tone or contractility is above 0.
  double tone_pa = 0.0;
  double contractility_pa = 0.0;
  double optimal_stretch = 0.0;
  double stretch_width = 0.0;
  double hill_a = 0.0;
  double hill_vmax_per_s = 0.0;

  bool has_muscle() const { return tone_pa > 0.0 || contractility_pa > 0.0; }
};

// How the computation was set up where it changes results: the level the run started at
// (RunOptions::level), the wall's dynamics and the step limits. The rest of RunOptions
// (files, threads, progress, checkpoints) changes nothing a card describes.
struct RunNumerics {
  int level = 1;
  bool dynamic = false;
  double bossak_alpha = 0.0;
  bool hand_over = false;  // RunOptions::hand_over: the fallback down the levels allowed
  double max_fill_step_ml = 0.0;
  double max_void_step_s = 0.0;
  double max_void_step_ml = 0.0;
  double newton_reuse_tangent_ratio = 0.0;  // RunOptions::newton's chord iterations
  // Level 2 only: its time steps, the urine's viscosity and the linear solver.
  double fluid_dt_s = 0.0;
  double void_dt_s = 0.0;
  double void_dt_min_s = 0.0;
  double void_dt_max_s = 0.0;
  double urine_viscosity_pa_s = 0.0;
  Level2LinearSolver linear_solver = Level2LinearSolver::Krylov;
  double remesh_radius_ratio = 0.0;
};

// A hand-over between levels of the model (docs/simulate.md, "Levels and their
// hand-overs"): the run went on from `from` as `to` at this volume and time, and why.
// The protocol makes one where a voiding step fails after its cut-backs with the urethra
// open: level 2 to level 1 on the same wall, level 1 to its level-0 sphere-equivalent.
struct LevelHandOver {
  int from = 0;
  int to = 0;
  double volume_ml = 0.0;
  double time_s = 0.0;
  std::string reason;
};

// The mesh the wall was read from: its file, content hash and size.
struct MeshIdentity {
  std::string file;  // as given (empty: a wall built in memory)
  std::string hash;  // "sha256:..." of the file's bytes (empty: none)
  long triangles = 0;
  long nodes = 0;
  long tetrahedra = 0;        // the urine's, level 2 only
  double mean_edge_mm = 0.0;  // of the stress-free wall as it ran
};

struct ModelCard {
  MaterialCard material;
  // The stress-free reference (scaled to residual_ml, or prestressed at the protocol's
  // image_pressure_cmh2o), the thickness where the mesh gives none, and the fixed patch.
  WallOptions wall;
  double reference_volume_ml = 0.0;  // the stress-free wall's enclosed volume as it ran
  double mean_thickness_mm = 0.0;    // its thickness as it ran (the mesh's, else the option)
  // Filling, the surroundings, the voiding drive with its activation and the recorded
  // abdominal pressure, and the urethra's law.
  ProtocolSettings protocol;
  RunNumerics numerics;
  std::vector<LevelHandOver> hand_overs;  // in the order they happened
  MeshIdentity mesh;
};

// The numerics of a run's options, and back onto options.
RunNumerics numerics_of(const RunOptions& options);
void apply_numerics(const RunNumerics& numerics, RunOptions& options);

// "detrusor" or "straining".
const char* drive_name(VoidingDrive drive);
// What voided the bladder, as a reader says it, from the card alone: "detrusor
// contraction, contractility 100 kPa", "abdominal straining 4 kPa (40.8 cmH2O)", or "none:
// filling only".
std::string voiding_drive_text(const ModelCard& card);
// The card in words, one line per part, every number with its unit: the material, the
// reference, the protocol, the voiding drive, the urethra, the level and its hand-overs, the
// mesh (the history.csv header; the report and the study page say the same).
std::vector<std::string> model_card_lines(const ModelCard& card);
// The material's parameters as a reader writes them: "mu 1 kPa, K 1000 kPa, k1 0.06 kPa,
// k2 0.045, Maxwell 0.2 / 10 s, contractility 100 kPa, ...".
std::string material_text(const MaterialCard& material);
// A hand-over as a reader says it: "level 1 -> 0 at 12.3 ml, t = 456 s: <reason>".
std::string hand_over_text(const LevelHandOver& hand_over);

// The urethra's law: "collapsible" (a lumen half open urethra_half_open_cmh2o above
// closing) or "rigid" (the plain quadratic law).
const char* urethra_law_name(const ProtocolSettings& protocol);

}  // namespace vesica::simulate
