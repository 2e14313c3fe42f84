// Benchmarks of issues 6 and 7, printed as one JSON object:
//  - balloon: 5,000-triangle sphere, 20 pressure steps to 95 % of the limit pressure;
//  - cystometry: 50 → 350 ml at 50 ml/min and voiding on spheres of ≈ 2,300 and ≈ 17,000
//    triangles (neo-Hookean μ = 3 kPa, K = 1000 μ, voided by straining), no output files;
//  - lumped: the default bladder's whole cystometry (50 → 350 ml, voided by the detrusor)
//    at level 0, repeated: what one simulation of calibration's global search costs.
// Usage: bench_simulate [balloon|cystometry-small|cystometry-large|balloon-and-small|lumped|all]
#include <chrono>
#include <cmath>
#include <iostream>

#include <nlohmann/json.hpp>

#include "solver/NewtonSolver.h"
#include "vesica/core/Units.h"
#include "vesica/simulate/materials/MaterialRegistry.h"
#include "vesica/simulate/protocol/Cystometry.h"
#include "vesica/simulate/wall/SphereMesh.h"
#include "wall/MembraneProblem.h"

using namespace vesica;
using namespace vesica::simulate;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

nlohmann::json balloon() {
  const double R = 0.0229, H = 3e-3, mu = 5e3;
  WallModel wall = sphere_wall(R, H, 25);
  fix_sphere_rigid_modes(wall);
  const auto material = make_material({"neo-hookean", {{"mu", mu}, {"K", 1e3 * mu}}});
  const auto t0 = std::chrono::steady_clock::now();
  MembraneProblem problem(wall, *material, 2);
  NewtonSolver solver(problem);
  WallLoads loads;
  std::vector<Eigen::Vector3d> x = wall.nodes;
  const double l = std::pow(7.0, 1.0 / 6.0);
  const double Pmax = 2.0 * H / R * mu * (1.0 / l - std::pow(l, -7));
  int iterations = 0;
  bool ok = true;
  for (int s = 1; s <= 20; ++s) {
    CavityEquation c;
    c.pressure_pa = 0.95 * Pmax * s / 20;
    const NewtonReport r = solver.solve(c, loads, x);
    ok = ok && r.converged;
    iterations += r.iterations;
    problem.commit();
  }
  return {{"triangles", wall.triangle_count()}, {"steps", 20},
          {"newton_iterations", iterations},    {"converged", ok},
          {"seconds", seconds_since(t0)},       {"target_seconds", 2.0}};
}

nlohmann::json cystometry(int n, double target_s) {
  // A sphere enclosing the 50 ml residual volume with its south cap held (the base).
  const double R = std::cbrt(3.0 * units::m3_from_ml(50.0) / (4.0 * 3.14159265358979));
  WallModel wall = sphere_wall(R, 3e-3, n);
  for (std::size_t e = 0; e < wall.triangle_count(); ++e) {
    bool base = true;
    for (int v : wall.triangles[e]) base = base && wall.nodes[v].z() < -0.93 * R;
    if (base) wall.region[e] = 2;  // outlet cap
  }
  fix_regions(wall, Eigen::Vector3d(0, 0, -1), 0.0);
  ProtocolSettings p;
  p.drive = VoidingDrive::Straining;  // as the figures before the detrusor drive
  p.straining_kpa = 4.0;
  RunOptions o;
  const auto t0 = std::chrono::steady_clock::now();
  const CystometryResult r =
      run_cystometry(wall, {"neo-hookean", {{"mu", 3e3}, {"K_per_mu", 1e3}}}, p, o);
  nlohmann::json j = {{"triangles", wall.triangle_count()},
                      {"completed", r.completed},
                      {"seconds", seconds_since(t0)},
                      {"target_seconds", target_s}};
  for (const char* key : {"pdet_at_capacity_cmh2o", "qmax_ml_s", "voided_ml", "pvr_ml", "newton"})
    if (r.summary.contains(key)) j[key] = r.summary[key];
  if (!r.completed) j["failure"] = r.failure;
  return j;
}

// The default bladder (20 ml stress-free sphere) at level 0, `repeats` whole cystometries.
nlohmann::json lumped(int repeats) {
  const double R = std::cbrt(3.0 * units::m3_from_ml(20.0) / (4.0 * 3.14159265358979));
  WallModel wall = sphere_wall(R, 3e-3, 10);
  fix_sphere_rigid_modes(wall);
  RunOptions o;
  o.level = 0;
  CystometryResult r;
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < repeats; ++i)
    r = run_cystometry(wall, {"bladder", {}}, ProtocolSettings{}, o);
  nlohmann::json j = {{"repeats", repeats},
                      {"completed", r.completed},
                      {"seconds_per_cystometry", seconds_since(t0) / repeats},
                      {"target_seconds", 0.05}};
  for (const char* key : {"pdet_at_capacity_cmh2o", "qmax_ml_s", "pvr_ml", "voiding_drive"})
    if (r.summary.contains(key)) j[key] = r.summary[key];
  return j;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string what = argc > 1 ? argv[1] : "all";
  nlohmann::json out;
  if (what == "balloon" || what == "all" || what == "balloon-and-small")
    out["balloon_5000_triangles"] = balloon();
  if (what == "cystometry-small" || what == "all" || what == "balloon-and-small")
    out["cystometry_2300_triangles"] = cystometry(17, 10.0);
  if (what == "cystometry-large" || what == "all")
    out["cystometry_17000_triangles"] = cystometry(46, 60.0);
  if (what == "lumped" || what == "all" || what == "balloon-and-small")
    out["lumped_default_bladder"] = lumped(20);
  std::cout << out.dump(2) << std::endl;
}
