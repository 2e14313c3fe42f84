// Benchmark of issue 25: the verification protocol "pressure-steps" (run_verification, what
// vesica-simulate --protocol pressure-steps runs, without the file I/O) on sphere phantoms
// of ≈ 2,400, 9,700 and 38,700 triangles: R 30 mm, H 3 mm, μ 5 kPa, K/μ = 2, 20 steps to
// 95 % of the limit pressure, for FEBio's K/2 (ln J)² and the Ogden term (β = 9). Prints one
// JSON object. Each case also runs with a new factorization for every Newton increment (the
// code before issue 36: "present_code_seconds"), in the same process.
// Usage: bench_verification [small|all]
#include <chrono>
#include <cmath>
#include <iostream>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "vesica/core/Units.h"
#include "vesica/simulate/verification/VerificationProtocol.h"
#include "vesica/simulate/wall/SphereMesh.h"

using namespace vesica;
using namespace vesica::simulate;

namespace {

// Limit pressures of the thin sphere (docs/physics.md §6.2).
constexpr double kLimitLogPa = 404.0, kLimitOgdenPa = 199.0;

nlohmann::json pressure_steps(int n, double beta, double limit_pa, bool reuse) {
  WallModel wall = sphere_wall(0.030, 3e-3, n);
  hold_rigid_body_modes(wall);
  VerificationSettings s;
  s.protocol = "pressure-steps";
  s.steps = 20;
  s.max_pressure_cmh2o = units::cmh2o_from_pa(0.95 * limit_pa);
  if (!reuse) s.preconditioned_reuse_iterations = 0;
  const MaterialSpec spec{"neo-hookean", {{"mu", 5e3}, {"K", 1e4}, {"beta_vol", beta}}};
  const auto t0 = std::chrono::steady_clock::now();
  const VerificationResult r = run_verification(wall, spec, s);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  int iterations = 0, foundation = 0;
  for (const StretchRow& row : r.rows) {
    iterations += row.newton_iterations;
    foundation += row.foundation_iterations;
  }
  return {{"triangles", wall.triangle_count()},
          {"beta_vol", beta},
          {"steps", r.rows.size() - 1},
          {"completed", r.completed && r.note.empty()},
          {"last_stretch", r.rows.back().stretch},
          {"newton_iterations", iterations},
          {"foundation_iterations", foundation},
          {"seconds", seconds}};
}

}  // namespace

int main(int argc, char** argv) {
  const std::string what = argc > 1 ? argv[1] : "all";
  nlohmann::json out = nlohmann::json::array();
  for (int n : {17, 35, 70}) {  // 8 n² triangles: 2,312, 9,800, 39,200
    if (what == "small" && n > 35) break;
    for (const auto& [beta, limit] : {std::pair{0.0, kLimitLogPa}, {9.0, kLimitOgdenPa}}) {
      const nlohmann::json present = pressure_steps(n, beta, limit, false);
      nlohmann::json row = pressure_steps(n, beta, limit, true);
      row["present_code_seconds"] = present["seconds"];
      row["present_code_newton_iterations"] = present["newton_iterations"];
      row["present_code_last_stretch"] = present["last_stretch"];
      row["speedup"] = present["seconds"].get<double>() / row["seconds"].get<double>();
      out.push_back(row);
    }
  }
  std::cout << nlohmann::json{{"pressure_steps", out}}.dump(2) << std::endl;
  return 0;
}
