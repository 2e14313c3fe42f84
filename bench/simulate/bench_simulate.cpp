// Benchmarks of issues 6 and 7, printed as one JSON object:
//  - balloon: 5,000-triangle sphere, 20 pressure steps to 95 % of the limit pressure;
//  - cystometry: 50 → 350 ml at 50 ml/min and voiding on spheres of ≈ 2,300 and ≈ 17,000
//    triangles (neo-Hookean μ = 3 kPa, K = 1000 μ, voided by straining), no output files;
//  - lumped: the default bladder's whole cystometry (50 → 350 ml, voided by the detrusor)
//    at level 0, repeated: what one simulation of calibration's global search costs.
// The balloon and the cystometries run twice in the same process: as the code runs them
// ("seconds") and with a new factorization for every Newton increment as before issue 36
// (preconditioned reuse off: "present_code_seconds"), so that the speed-up is measured on
// the same machine at the same load, and their results side by side.
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

// The Newton settings of a row: as the code runs it, or with the factorization reuse of
// issue 36 switched off (the code before it).
NewtonOptions without_preconditioned_reuse(NewtonOptions o) {
  o.preconditioned_reuse.max_iterations = 0;
  return o;
}

// The row of `run(reuse)` with its time without the reuse beside it: run first without, so
// that the row as the code runs it never benefits from a warmer machine.
template <class Run>
nlohmann::json with_present_code(const Run& run) {
  const nlohmann::json present = run(false);
  nlohmann::json j = run(true);
  j["present_code_seconds"] = present["seconds"];
  j["speedup"] = present["seconds"].get<double>() / j["seconds"].get<double>();
  nlohmann::json results = present;
  results.erase("seconds");
  results.erase("target_seconds");
  j["present_code"] = results;
  return j;
}

nlohmann::json balloon(bool reuse) {
  const double R = 0.0229, H = 3e-3, mu = 5e3;
  WallModel wall = sphere_wall(R, H, 25);
  fix_sphere_rigid_modes(wall);
  const auto material = make_material({"neo-hookean", {{"mu", mu}, {"K", 1e3 * mu}}});
  const auto t0 = std::chrono::steady_clock::now();
  MembraneProblem problem(wall, *material, 2);
  NewtonOptions options;
  options.preconditioned_reuse.max_iterations = 8;
  NewtonSolver solver(problem, reuse ? options : without_preconditioned_reuse(options));
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

nlohmann::json cystometry(int n, double target_s, bool reuse) {
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
  // Level 1 runs without the reuse by default (it measured slower there): the row times it
  // switched on, beside the default.
  o.newton.preconditioned_reuse.max_iterations = reuse ? 8 : 0;
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
    out["balloon_5000_triangles"] = with_present_code(balloon);
  if (what == "cystometry-small" || what == "all" || what == "balloon-and-small")
    out["cystometry_2300_triangles"] =
        with_present_code([](bool reuse) { return cystometry(17, 1.0, reuse); });
  if (what == "cystometry-large" || what == "all")
    out["cystometry_17000_triangles"] =
        with_present_code([](bool reuse) { return cystometry(46, 10.0, reuse); });
  if (what == "lumped" || what == "all" || what == "balloon-and-small")
    out["lumped_default_bladder"] = lumped(20);
  std::cout << out.dump(2) << std::endl;
}
