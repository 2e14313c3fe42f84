// An outside program on the installed vesica::simulate: inflates a neo-Hookean spherical
// balloon from its stress-free volume to twice that volume with the in-process cystometry
// API and checks the pressure against the thin-sphere solution (docs/physics.md §6),
// P = 2 μ H / R (λ⁻¹ − λ⁻⁷) with λ = (V / V0)^(1/3), incompressible wall.
// SI inside; the cystometry's history is in ml and cmH2O. Exit 0 when within 2 %.
#include <cmath>
#include <cstdio>

#include "vesica/core/Units.h"
#include "vesica/core/Version.h"
#include "vesica/simulate/protocol/Cystometry.h"
#include "vesica/simulate/wall/SphereMesh.h"

int main() {
  namespace sim = vesica::simulate;
  namespace units = vesica::units;
  const double pi = 3.14159265358979323846;
  const double radius = 0.03, thickness = 3e-3, mu = 5e3;  // m, m, Pa

  sim::WallModel wall = sim::sphere_wall(radius, thickness, 8);
  sim::fix_sphere_rigid_modes(wall);
  // The polyhedron encloses a little less than the sphere: its own volume is the reference.
  const double v0 = sim::enclosed_volume(wall, wall.nodes);
  const double r0 = std::cbrt(3.0 * v0 / (4.0 * pi));

  sim::ProtocolSettings protocol;
  protocol.start_ml = units::ml_from_m3(v0);
  protocol.capacity_ml = 2.0 * protocol.start_ml;
  protocol.void_after_fill = false;
  protocol.gravity = false;
  sim::RunOptions options;
  options.filling_only = true;
  const sim::CystometryResult result =
      sim::run_cystometry(wall, {"neo-hookean", {{"mu", mu}, {"K", 1e3 * mu}}}, protocol, options);
  if (!result.completed || result.history.empty()) {
    std::fprintf(stderr, "balloon: the cystometry failed: %s\n", result.failure.c_str());
    return 1;
  }

  const sim::HistoryRow& end = result.history.back();
  const double lambda = std::cbrt(end.volume_ml / protocol.start_ml);
  const double analytic_pa = 2.0 * mu * thickness / r0 * (1.0 / lambda - std::pow(lambda, -7.0));
  const double simulated_pa = units::pa_from_cmh2o(end.pdet_cmh2o);
  const double deviation = simulated_pa / analytic_pa - 1.0;
  std::printf("%s: balloon at %.2f ml (stretch %.4f): %.2f Pa, thin sphere %.2f Pa (%+.3f %%)\n",
              vesica::kVersionString, end.volume_ml, lambda, simulated_pa, analytic_pa,
              100.0 * deviation);
  return std::abs(deviation) < 0.02 ? 0 : 1;
}
