#include "wall/PrestressReference.h"

#include "solver/NewtonSolver.h"
#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "wall/MembraneProblem.h"

namespace vesica::simulate {
namespace {

// The imaged pressure applied to reference X by pressure control in a few load steps;
// returns the loaded positions or throws.
std::vector<Eigen::Vector3d> loaded_state(const WallModel& reference, const Material& material,
                                          double pressure_pa, int threads) {
  MembraneProblem problem(reference, material, threads);
  NewtonSolver solver(problem);
  WallLoads loads;
  std::vector<Eigen::Vector3d> x = reference.nodes;
  constexpr int kSteps = 8;
  for (int s = 1; s <= kSteps; ++s) {
    CavityEquation cavity;
    cavity.pressure_pa = pressure_pa * s / kSteps;
    const NewtonReport report = solver.solve(cavity, loads, x);
    if (!report.converged)
      fail("prestress", "the wall cannot carry the imaging pressure (" + report.failure + ")",
           "lower --image-pressure-cmh2o or use --reference scale");
    problem.commit();
  }
  return x;
}

}  // namespace

WallModel prestressed_reference(const WallModel& imaged, const Material& material,
                                double pressure_pa, int threads) {
  WallModel reference = imaged;
  Eigen::AlignedBox3d box;
  for (const auto& p : imaged.nodes) box.extend(p);
  const double tolerance = 1e-4 * box.diagonal().norm();
  for (int k = 0; k < 30; ++k) {
    const std::vector<Eigen::Vector3d> x = loaded_state(reference, material, pressure_pa, threads);
    double error = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i)
      error = std::max(error, (imaged.nodes[i] - x[i]).norm());
    vesica::log()->info("prestress iteration {}: max distance to the imaged wall {:.3g} mm", k,
                        error * 1e3);
    if (error < tolerance) return reference;
    for (std::size_t i = 0; i < x.size(); ++i) reference.nodes[i] += imaged.nodes[i] - x[i];
  }
  fail("prestress", "backward-displacement iteration did not converge in 30 iterations",
       "use --reference scale");
}

}  // namespace vesica::simulate
