#pragma once
// What a simulated cystometry does (ProtocolSettings: the clinical protocol and the
// patient's surroundings, in the clinical units of a urodynamic report) and how it is
// computed (RunOptions: the cavity model, step sizes, Newton, outputs). One set of
// defaults for both levels; the level-2 (Navier–Stokes) extras are in RunOptions::level2.
#include <filesystem>
#include <functional>
#include <string>

#include "vesica/simulate/protocol/PressureTrace.h"
#include "vesica/simulate/solver/NewtonOptions.h"
#include "vesica/simulate/wall/WallLoading.h"

namespace vesica::simulate {

// What empties the bladder (docs/physics.md §7.2): the detrusor's contraction (the
// physiological void) or abdominal straining (a neobladder, or a detrusor that cannot).
enum class VoidingDrive { Detrusor, Straining };

struct ProtocolSettings {
  // Filling (docs/physics.md §7)
  double start_ml = 50.0;
  double capacity_ml = 350.0;
  // Filling also ends once Pdet reaches this (0: only at capacity_ml): a what-if study
  // fills a pouch to its pressure limit, its capacity then read from the history.
  double fill_limit_cmh2o = 0.0;
  double fill_rate_ml_min = 50.0;
  double hold_s = 0.0;
  double pabd_cmh2o = 0.0;  // resting abdominal pressure on the outer wall
  // Voiding (docs/physics.md §7.2): from the end of filling the drive is activated along
  // a(t) = 1 − exp(−t/onset) for the plateau, then fades as exp(−(t − plateau)/fade);
  // the detrusor's active stress is the wall material's (tone + a · contractility), the
  // straining adds a · straining_kpa to Pabd.
  bool void_after_fill = true;
  VoidingDrive drive = VoidingDrive::Detrusor;
  double straining_kpa = 4.0;  // extra abdominal pressure at full straining
  // The abdominal pressure while voiding as recorded (time from the start of voiding):
  // replaces pabd_cmh2o from the end of filling on, whatever the drive. A woman who strains
  // while her detrusor voids raises Pves by her Pabd, and the model's Pdet stays the
  // detrusor's. Empty: the resting pabd_cmh2o.
  PressureTrace voiding_pabd;
  double activation_delay_s = 0.0;  // latency from the end of filling to the drive's onset
  double activation_onset_s = 4.0;  // docs/physics.md §12: a detrusor recruited over seconds
  double activation_plateau_s = 60.0;
  double activation_fade_s = 5.0;
  // The urethra (docs/physics.md §5): opens at p_open, passes Q with
  // Pves − p_close = (R1 q + R2 q²), Q = φ q, φ the collapsible lumen's open fraction
  // (half open urethra_half_open_cmh2o above p_close; 0 = rigid), and closes at p_close.
  double p_open_cmh2o = 20.0;
  double p_close_cmh2o = 10.0;
  double r1_cmh2o_s_per_ml = 0.2;
  double r2_cmh2o_s2_per_ml2 = 0.02;
  double urethra_half_open_cmh2o = 5.0;
  // The sphincter's recovery as the bladder empties (docs/physics.md §5): the closing
  // pressure rises from p_close at the opening back to p_open when empty, half-way once
  // this fraction of the urine the urethra opened on is voided (0.5: linearly), so that the
  // flow tails off against a still contracting detrusor. 1: it stays at p_close.
  double urethra_recovery_half = 1.0;
  double stop_flow_ml_s = 1.0;  // voiding ends when the flow falls below this
  double max_void_s = 120.0;
  // Environment
  Posture posture = Posture::Supine;
  bool gravity = true;            // hydrostatic urine pressure and wall weight
  double urine_density = 1000.0;  // kg/m³
  // Abdominal contents as a fluid at the same reference height: with the urine's density
  // the transmural pressure has no hydrostatic gradient (Pabd is measured beside Pves);
  // 0 = a bladder in air, whose low-pressure top is then in compression.
  double abdominal_density = 1000.0;  // kg/m³
  bool wall_weight = false;           // the wall's own weight (buoyant in the abdomen)
  double wall_density = 920.0;        // kg/m³
  double support_kpa_per_mm = 0.0;    // springs on the support region (kPa per mm)
  // Viscous drag of the perivesical tissue on the wall (Pa·s/m): the drag pressure c·v is
  // about 0.004 cmH2O at 50 ml/min, but it gives the slack wall of a scaled-down patient
  // shape (excess area, no stiffness against unfolding) a unique position at every step.
  double wall_drag_pa_s_per_m = 1e4;
  // Tension-field wall (docs/physics.md §1): the membrane wrinkles instead of carrying
  // compression, as a wall without bending stiffness must; false = the plain plane-stress
  // law, compression included (which makes the slack collapse below the reference volume
  // at the end of voiding slow and fragile).
  bool wrinkling = true;
  // The share ε of the plain law's stress and stiffness a wrinkled or slack element keeps
  // (docs/physics.md §1.6): a wall a few millimetres thick carries some compression before
  // it buckles, and the crumpling wall near empty keeps a unique, stable shape.
  double wrinkle_regularisation = 0.1;
  static constexpr double kMaxWrinkleRegularisation = 0.5;  // the parameter's range: [0, this]
  // Prestress reference: the imaged geometry is in equilibrium at this pressure.
  double image_pressure_cmh2o = 10.0;
};

// How level 2 solves the linear system of each coupled Newton iteration
// (docs/navier-stokes.md §7): a fresh sparse LU every time, or GMRES preconditioned by the
// LU of an earlier Jacobian (Newton–Krylov, factorizations reused across steps).
enum class Level2LinearSolver { Direct, Krylov };

// Level 2: the urine as a Navier–Stokes flow on the tetrahedra of vesica-mesh --fluid,
// solved together with the wall (docs/navier-stokes.md).
struct Level2Options {
  // Time step while filling and holding (s); 0: the protocol's adaptive step (from half of
  // RunOptions::max_fill_step_ml's time, growing after easy steps): the slow filling's urine
  // is nearly steady, and backward Euler follows it in large steps.
  double fill_dt_s = 1.0;
  // Time step while voiding (s); 0: the protocol's adaptive step, from the flow's and the
  // volume's change per step and the Newton iterations, within [void_dt_min_s, void_dt_max_s].
  double void_dt_s = 0.0;
  double void_dt_min_s = 0.01, void_dt_max_s = 0.5;
  double urine_viscosity = 1e-3;  // Pa·s
  Level2LinearSolver linear_solver = Level2LinearSolver::Krylov;
  // The urine's tetrahedra are rebuilt once their smallest radius ratio falls below this
  // (tetrahedra built below it already: once they have lost half their quality).
  double remesh_radius_ratio = 0.1;
  // The coupled wall–urine Newton (increment tests, 40 iterations, no line search).
  NewtonOptions newton = coupled_newton_options();
};

struct RunOptions {
  // 0: the lumped (0-D) bladder, a sphere of the wall's reference volume and mean
  // thickness with the same material, activation and urethra (milliseconds; for fast
  // calibration); 1: the urine as an enclosed volume with a hydrostatic pressure
  // (seconds); 2: the urine as a Navier–Stokes flow on its tetrahedra (minutes; needs them,
  // see run_cystometry).
  int level = 1;
  std::filesystem::path output_dir;  // empty: write no files (calibration)
  bool filling_only = false;         // stop at capacity (and hold)
  bool write_series = true;          // series.pvd + series/*.vtu when output_dir is set
  // Frames while filling; while voiding every 1 s (level 1) or 0.5 s (level 2).
  double series_interval_s = 10.0;
  // Largest volume increment of a settling step (both levels) and of a level-1 filling
  // step, whose steps then grow from half of it while Newton converges easily.
  double max_fill_step_ml = 10.0;
  double max_void_step_s = 0.5;    // level 1: longest voiding step (time resolution of the flow)
  double max_void_step_ml = 10.0;  // level 1: largest volume voided by one step of a taut wall
  int threads = 2;
  // Level 1: Bossak–Newmark dynamics of the wall (docs/physics.md §3) instead of
  // quasi-static steps; α_B ∈ [-1/3, 0] (0: no numerical damping).
  bool dynamic = false;
  double bossak_alpha = -0.1;
  // The fallback, off by default: a voiding step the running level cannot take, after its
  // cut-backs and with the urethra open, hands the rest of the voiding to the level below
  // (2 → 1 → 0; docs/simulate.md, "Levels and their hand-overs"). false: voiding ends
  // there, with a note, so that the wall's own void is what the results show.
  bool hand_over = false;
  ReferenceState reference = ReferenceState::Scale;
  // The wall-and-cavity Newton of level 1 (and of level 2's settling to the start volume).
  // Chord iterations while the residual falls tenfold per iteration: fewer factorizations
  // of the indefinite tangent, the same results to the Newton tolerance. Up to 25
  // iterations before a step is cut back: on a slack, wrinkling wall Newton converges only
  // linearly (elements switch between slack and taut), and a step cut back earlier wastes
  // all its iterations; but one whose residual has stopped falling (no halving in 8
  // iterations) is cut back at once, since it mostly fails after all its iterations, or
  // converges after many, where the shorter step takes a few. Converged at a residual of
  // 1e-7 of the gross pressure force and a last increment of 1e-6 of the wall's size
  // (sub-micrometre on a bladder): the defaults' extra digits cost many iterations of the
  // slack collapse at the end of voiding and change no reported result. No preconditioned reuse
  // (NewtonOptions.h): on a wrinkling wall GMRES misses its tolerance too often for it to pay
  // (docs/simulate.md).
  NewtonOptions newton = [] {
    NewtonOptions o;
    o.reuse_tangent_ratio = 0.1;
    o.max_iterations = 25;
    o.residual_tolerance = 1e-7;
    o.increment_tolerance = 1e-6;
    o.stagnation_factor = 0.5;
    return o;
  }();
  // Called after every step with what is being done ("filling 120 ml") and the fraction
  // of the protocol done (filling up to 0.8, voiding after); the executable draws it.
  std::function<void(const std::string& step, double fraction)> on_progress;
  Level2Options level2;
  // Checkpoints of a long run (docs/simulate.md, "Checkpoint and resume"): written to
  // `file` (empty: none) every interval_min minutes of compute and when SIGTERM or SIGINT arrives,
  // with `identity` (JSON text: the inputs' hashes and the parameters), which a resumed run
  // must match; resume: continue from the file instead of from the start.
  struct Checkpoints {
    std::filesystem::path file;
    double interval_min = 5.0;
    std::string identity;
    bool resume = false;
  } checkpoints;
};

}  // namespace vesica::simulate
