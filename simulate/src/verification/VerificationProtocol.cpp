// Pressure and volume steps of a closed wall: the verification problems of docs/physics.md
// §6 (the inflated sphere) run from the command line. SI inside; the P–λ table adds cmH2O
// and ml.
#include "vesica/simulate/verification/VerificationProtocol.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "solver/NewtonSolver.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/Regions.h"
#include "vesica/core/Units.h"
#include "vesica/simulate/materials/MaterialRegistry.h"
#include "vesica/simulate/wall/MeshReader.h"
#include "wall/MembraneProblem.h"

namespace vesica::simulate {
namespace {

// One converged state on the load path: the control value (P or V), positions and p0.
struct PathPoint {
  double control = 0.0;
  std::vector<Eigen::Vector3d> x;
  double p0 = 0.0;
};

// Starts Newton on the secant through the last two converged states (a continuation
// predictor). Without it a pressure step starts from the last shape, and the first
// iteration's move (the whole step's growth) exceeds the foundation's move limit, which
// only knows the move a volume-controlled cavity demands (NewtonOptions.h).
void predict(const PathPoint& older, const PathPoint& last, double control,
             std::vector<Eigen::Vector3d>& x, double& p0) {
  const double span = last.control - older.control;
  if (older.x.empty() || span == 0.0) return;
  const double t = std::min((control - last.control) / span, 2.0);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = last.x[i] + t * (last.x[i] - older.x[i]);
  p0 = last.p0 + t * (last.p0 - older.p0);
}

bool has_held_region(const WallModel& wall) {
  for (int r : wall.region) {
    const auto region = static_cast<Region>(r);
    if (region == Region::Outlet || region == Region::Inlet || region == Region::Fixed) return true;
  }
  return false;
}

}  // namespace

void hold_rigid_body_modes(WallModel& wall) {
  wall.fixed.assign(wall.nodes.size(), {false, false, false});
  wall.support.assign(wall.nodes.size(), false);
  const Eigen::Vector3d c = surface_centroid(wall);
  std::size_t bottom = 0, top = 0, side = 0;
  for (std::size_t i = 0; i < wall.nodes.size(); ++i) {
    const Eigen::Vector3d d = wall.nodes[i] - c;
    if (d.z() < (wall.nodes[bottom] - c).z()) bottom = i;
    if (d.z() > (wall.nodes[top] - c).z()) top = i;
    if (d.x() > (wall.nodes[side] - c).x()) side = i;
  }
  wall.fixed[bottom][0] = wall.fixed[bottom][1] = true;
  wall.fixed[top][0] = wall.fixed[top][1] = true;
  wall.fixed[side][1] = wall.fixed[side][2] = true;
}

WallModel load_verification_wall(const std::filesystem::path& path, double thickness_mm) {
  if (!(thickness_mm > 0.0)) usage_error("thickness_mm must be > 0");
  WallModel wall = read_wall(path, units::m_from_mm(thickness_mm));
  if (has_held_region(wall))
    fix_regions(wall, Eigen::Vector3d::UnitZ(), 0.0);
  else
    hold_rigid_body_modes(wall);
  return wall;
}

VerificationResult run_verification(const WallModel& wall, const MaterialSpec& spec,
                                    const VerificationSettings& s) {
  if (!is_verification(s)) usage_error("unknown verification protocol '" + s.protocol + "'");
  if (s.steps < 1) usage_error("steps must be >= 1");
  const bool by_volume = s.protocol == "volume-steps";
  const auto material = make_material(spec);
  MembraneProblem problem(wall, *material, 2);
  // Tolerances 1e-9/1e-8; each increment Newton's own, to the linear tolerance.
  NewtonOptions newton;
  newton.preconditioned_reuse.max_iterations = s.preconditioned_reuse_iterations;
  NewtonSolver solver(problem, newton);
  WallLoads loads;
  VerificationResult result;
  std::vector<Eigen::Vector3d> x = wall.nodes;
  const double V0 = enclosed_volume(wall, x);
  result.reference_volume_m3 = V0;
  result.rows.push_back({0.0, V0, 1.0, 0, 0});

  const double last =
      by_volume ? V0 * std::pow(s.max_stretch, 3) : units::pa_from_cmh2o(s.max_pressure_cmh2o);
  const double first = by_volume ? V0 : 0.0;
  const double full_step = (last - first) / s.steps;
  PathPoint older, newest{first, x, 0.0};
  double step = full_step;
  // Halvings so far; a halved step keeps its size (near a limit point a longer one fails
  // again), so the limit is located to full_step / 2^max_cutbacks.
  int cutbacks = 0;
  while (std::abs(newest.control - last) > 1e-12 * std::abs(last)) {
    const double target = full_step > 0 ? std::min(newest.control + step, last)
                                        : std::max(newest.control + step, last);
    CavityEquation cavity;
    cavity.volume_control = by_volume;
    (by_volume ? cavity.volume_base_m3 : cavity.pressure_pa) = target;
    x = newest.x;
    loads.inside.p0 = by_volume ? newest.p0 : target;
    predict(older, newest, target, x, loads.inside.p0);
    if (!by_volume) loads.inside.p0 = target;
    const NewtonReport report = solver.solve(cavity, loads, x);
    if (!report.converged) {
      if (++cutbacks > s.max_cutbacks) {
        if (by_volume) {
          result.completed = false;
          result.failure =
              "no equilibrium at V/V0 = " + std::to_string(target / V0) + ": " + report.failure;
        } else {
          result.note = "limit point: no equilibrium above " +
                        std::to_string(units::cmh2o_from_pa(newest.control)) + " cmH2O";
        }
        break;
      }
      step *= 0.5;
      continue;
    }
    problem.commit();
    const double V = solver.assembly().volume;
    result.rows.push_back(
        {loads.inside.p0, V, std::cbrt(V / V0), report.iterations, report.regularized_iterations});
    older = std::move(newest);
    newest = {target, x, loads.inside.p0};
  }
  return result;
}

void write_stretch_table(const std::filesystem::path& path, const VerificationResult& result) {
  std::ostringstream out;
  out.precision(12);
  out << "step,pressure_pa,pressure_cmh2o,volume_ml,stretch,newton_iterations,"
         "foundation_iterations\n";
  for (std::size_t i = 0; i < result.rows.size(); ++i) {
    const StretchRow& r = result.rows[i];
    out << i << ',' << r.pressure_pa << ',' << units::cmh2o_from_pa(r.pressure_pa) << ','
        << units::ml_from_m3(r.volume_m3) << ',' << r.stretch << ',' << r.newton_iterations << ','
        << r.foundation_iterations << '\n';
  }
  write_text_atomically(path, out.str());
}

}  // namespace vesica::simulate
