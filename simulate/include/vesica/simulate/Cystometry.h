#pragma once
// Simulated cystometry on the level-1 wall-urine model (physics.md §4, §5, §7): the urine
// is an enclosed incompressible fluid with a hydrostatic pressure field; its pressure at
// the reference height is solved together with the wall (bordered Newton, volume
// control), driven by the infusion and drained by the outlet law while voiding.
//
// This is the stable in-process API used by vesica-simulate, the calibration in compare
// and the studies:
//   WallModel wall = load_wall("bladder.vtu", WallOptions{});
//   CystometryResult r = run_cystometry(wall, {"neo-hookean", {{"mu", 5e3}, {"K", 1e4}}},
//                                       CystometryProtocol{}, RunOptions{});
// RunOptions{} writes nothing (fast repeated calls); set output_dir for files, and
// filling_only to stop at capacity.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "vesica/simulate/Material.h"
#include "vesica/simulate/NewtonOptions.h"
#include "vesica/simulate/WallModel.h"

namespace vesica::simulate {

enum class Posture { Supine, Sitting };
enum class ReferenceState { Scale, Prestress };

// How the imaged surface becomes the stress-free reference wall.
struct WallOptions {
  double thickness_mm = 3.0;  // where the mesh gives no thickness_mm
  ReferenceState reference = ReferenceState::Scale;
  double residual_ml = 50.0;           // Scale: stress-free volume (thesis: about 50 ml)
  double fixed_patch_radius_mm = 8.0;  // when the mesh has no outlet/inlet/fixed region
  Posture posture = Posture::Supine;   // decides "down" for the fallback fixed patch
};

// Gravity vector in LPS patient coordinates (m/s²): supine = towards posterior (+y),
// sitting = towards inferior (-z).
Eigen::Vector3d gravity_lps(Posture posture);

// Reads the mesh (MeshReader.h), makes the reference state (Scale: about the centroid to
// residual_ml) and fixes the caps (outlet, inlet), the fixed region or a base patch.
// Prestress is applied later by run_cystometry (it needs the material).
WallModel load_wall(const std::filesystem::path& path, const WallOptions& options);

struct CystometryProtocol {
  // Filling (physics.md §7)
  double start_ml = 50.0;
  double capacity_ml = 350.0;
  double fill_rate_ml_min = 50.0;
  double hold_s = 0.0;
  double pabd_cmh2o = 0.0;  // resting abdominal pressure on the outer wall
  // Voiding (physics.md §5): p_ves - p_open = R1 Q + R2 Q² for p_ves > p_open, else Q = 0
  bool void_after_fill = true;
  double p_open_cmh2o = 20.0;
  double r1_cmh2o_s_per_ml = 0.2;
  double r2_cmh2o_s2_per_ml2 = 0.05;
  double detrusor_kpa = 0.0;       // peak active fiber stress T_a
  double straining_kpa = 0.0;      // extra abdominal pressure while voiding
  double activation_ramp_s = 2.0;  // ramp of detrusor activation and straining
  double stop_flow_ml_s = 1.0;     // voiding ends when the flow falls below this
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
  // Tension-field wall (TensionField.h): the membrane wrinkles instead of carrying
  // compression, as a wall without bending stiffness must; false = the plain plane-stress
  // law, compression included (which makes the slack collapse below the reference volume
  // at the end of voiding slow and fragile).
  bool wrinkling = true;
  // Prestress reference: the imaged geometry is in equilibrium at this pressure.
  double image_pressure_cmh2o = 10.0;
};

struct RunOptions {
  std::filesystem::path output_dir;  // empty: write no files (calibration)
  bool filling_only = false;         // stop at capacity (and hold)
  bool write_series = true;          // series.pvd + series/*.vtu when output_dir is set
  double series_interval_s = 10.0;   // during filling; voiding frames every 1 s
  double max_fill_step_ml = 10.0;    // largest volume increment of a filling step
  double max_void_step_s = 0.5;      // longest voiding step (time resolution of the flow)
  double max_void_step_ml = 10.0;    // largest volume voided by one step of a taut wall
  int threads = 2;
  // Bossak–Newmark dynamics of the wall (physics.md §3) instead of quasi-static steps;
  // α_B ∈ [-1/3, 0] (0: no numerical damping).
  bool dynamic = false;
  double bossak_alpha = -0.1;
  ReferenceState reference = ReferenceState::Scale;
  // Chord iterations while the residual falls tenfold per iteration: 515 -> 407
  // factorizations on the 2,312-triangle sphere, same results to the Newton tolerance.
  // Up to 25 iterations before a step is cut back: on a slack, wrinkling wall Newton
  // converges only linearly (elements switch between slack and taut), and an attempt cut
  // at 15 wasted all its iterations (16,928-triangle sphere: 21 cut-backs and 1,329
  // factorizations with 15, 5 and 1,014 with 25).
  // Converged at a residual of 1e-7 of the gross pressure force (4e-4 Pa, 4e-6 cmH2O, of
  // a 4 kPa straining pressure) and a last increment of 1e-6 of the wall's size (0.08 µm
  // on a 50 ml sphere): the defaults' extra digits (1e-9, 1e-8) cost a fifth of the
  // slack collapse's iterations and changed no result beyond its seventh digit
  // (16,928-triangle sphere: 1,013 → 879 iterations; PVR 1.7920620 → 1.7920623 ml).
  NewtonOptions newton = [] {
    NewtonOptions o;
    o.reuse_tangent_ratio = 0.1;
    o.max_iterations = 25;
    o.residual_tolerance = 1e-7;
    o.increment_tolerance = 1e-6;
    return o;
  }();
  // Called after every step with what is being done ("filling 120 ml") and the fraction
  // of the protocol done (filling up to 0.8, voiding after); the executable draws it.
  std::function<void(const std::string& step, double fraction)> on_progress;
};

struct HistoryRow {
  double time_s = 0.0;
  double infused_ml = 0.0;
  double volume_ml = 0.0;
  double pves_cmh2o = 0.0;
  double pabd_cmh2o = 0.0;
  double pdet_cmh2o = 0.0;
  double flow_ml_s = 0.0;
  double voided_ml = 0.0;
};

struct CystometryResult {
  std::vector<HistoryRow> history;
  nlohmann::json summary;          // the keys of summary.json
  bool completed = false;          // false: a step failed after cut-backs; see failure
  std::string failure;             // "step failed at t = .. s, V = .. ml: <reason>"
  std::vector<std::string> notes;  // what the user should know (e.g. no voiding drive)
};

// Throws vesica::Error (usage) for an invalid protocol or one above the geometry's
// limits, before computing anything. A step that fails after cut-backs does not throw:
// the result holds the history so far, completed = false and the reason (and files
// written so far when output_dir is set).
CystometryResult run_cystometry(const WallModel& wall, const MaterialSpec& material,
                                const CystometryProtocol& protocol, const RunOptions& options);

// history.csv text: time_s,infused_ml,volume_ml,pves_cmh2o,pabd_cmh2o,pdet_cmh2o,
// flow_ml_s,voided_ml
std::string history_csv(const std::vector<HistoryRow>& history);

}  // namespace vesica::simulate
