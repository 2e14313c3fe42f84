#include "fluid/DivergenceFreeProjection.h"

#include <algorithm>
#include <stdexcept>

#include "fluid/FluidBoundary.h"
#include "fluid/FluidNewton.h"
#include "fluid/FluidProblem.h"

namespace vesica::simulate::fluid {
namespace {

// Δt_p such that ρ/Δt_p exceeds the convective ρ|u|/h and viscous μ/h² terms by this
// factor at least, so that they change the projected velocity by no more than its inverse.
constexpr double kDominance = 1e8;

struct ProjectionScales {
  double dt = 0.0;     // Δt_p (s)
  double u_max = 0.0;  // largest transferred speed (m/s)
  double h_min = 0.0;  // shortest tet edge from a first corner (m)
};

ProjectionScales projection_scales(const FluidMesh& mesh, const FluidProperties& fluid,
                                   const Eigen::VectorXd& state) {
  ProjectionScales s;
  s.h_min = INFINITY;
  for (const auto& t : mesh.tets)
    for (int a = 1; a < 4; ++a)
      s.h_min = std::min(s.h_min, (mesh.nodes[t[a]] - mesh.nodes[t[0]]).norm());
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    s.u_max =
        std::max(s.u_max, state.segment<3>(kDofsPerNode * static_cast<Eigen::Index>(i)).norm());
  const double rate =
      std::max(s.u_max / s.h_min, fluid.viscosity / (fluid.density * s.h_min * s.h_min));
  s.dt = 1.0 / (kDominance * std::max(rate, 1e-12));
  return s;
}

}  // namespace

Eigen::VectorXd divergence_free_projection(const FluidMesh& mesh, const FluidProperties& fluid,
                                           const Eigen::VectorXd& state,
                                           const std::vector<bool>& given,
                                           const std::vector<std::array<int, 3>>& open_faces) {
  FluidBoundary boundary;
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    if (given[i])
      boundary.velocity.push_back({static_cast<int>(i),
                                   {true, true, true},
                                   state.segment<3>(kDofsPerNode * static_cast<Eigen::Index>(i))});
  for (const auto& f : open_faces) boundary.pressure_faces.push_back({f, 0.0});
  // With every boundary velocity given, φ is fixed up to a constant: pin it at an interior
  // node (the first after the given ones would do; any node works).
  if (open_faces.empty()) {
    const auto free = std::find(given.begin(), given.end(), false);
    boundary.pinned_pressure_node = static_cast<int>(free - given.begin());
  }
  FluidProperties without_gravity = fluid;
  without_gravity.gravity.setZero();
  const FluidProblem problem(mesh, boundary, without_gravity);
  const auto nodes = static_cast<Eigen::Index>(mesh.nodes.size());
  Eigen::VectorXd u_star = Eigen::VectorXd::Zero(problem.dof_count());
  for (Eigen::Index i = 0; i < nodes; ++i)
    u_star.segment<3>(kDofsPerNode * i) = state.segment<3>(kDofsPerNode * i);
  Eigen::VectorXd projected = u_star;
  // The Newton tests in the projection's own scales: φ is of order ρ |u| h / Δt_p, and
  // vanishes when u* is divergence-free already, where a relative test on it cannot pass;
  // a φ error δφ moves u by Δt_p δφ / (ρ h).
  const ProjectionScales scales = projection_scales(mesh, fluid, state);
  if (scales.u_max == 0.0) return state;  // urine at rest: divergence-free already
  FluidNewtonOptions options;
  options.max_iterations = 5;
  options.velocity_floor = options.increment_tolerance * scales.u_max;
  options.pressure_floor =
      options.increment_tolerance * fluid.density * scales.u_max * scales.h_min / scales.dt;
  const FluidNewtonReport report =
      FluidNewton(problem, options).solve(u_star, 1.0 / scales.dt, projected);
  if (!report.converged)
    throw std::runtime_error("divergence-free projection failed: " + report.failure);
  Eigen::VectorXd out = state;
  for (Eigen::Index i = 0; i < nodes; ++i)
    out.segment<3>(kDofsPerNode * i) = projected.segment<3>(kDofsPerNode * i);
  return out;
}

}  // namespace vesica::simulate::fluid
