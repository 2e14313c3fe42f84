#pragma once
// Follower pressure on one triangle of the closed wall (docs/physics.md §4), linear in space:
// p(x) = p0 + ρ g·(x - x_ref) with g the gravity vector (pointing down), which is
// docs/physics.md's p0 + ρ g (x_ref - x) written with an upward g: p grows with depth.
// The consistent nodal forces of a linear p over a flat triangle with area vector
// n A = (x2-x1)×(x3-x1)/2 are f_a = (x2-x1)×(x3-x1) (p_a + p1 + p2 + p3) / 24.
#include <array>

#include <Eigen/Dense>

namespace vesica::simulate {

struct HydrostaticPressure {
  double p0 = 0.0;                                    // pressure at x_ref (Pa)
  double rho = 0.0;                                   // fluid density (kg/m³); 0 = uniform
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  // m/s², pointing down
  Eigen::Vector3d x_ref = Eigen::Vector3d::Zero();    // m
  double at(const Eigen::Vector3d& x) const { return p0 + rho * gravity.dot(x - x_ref); }
};

struct PressureResponse {
  Eigen::Matrix<double, 9, 1> f;      // external nodal forces (N), pushing along +normal
  Eigen::Matrix<double, 9, 9> dfdx;   // ∂f/∂x (N/m), not symmetric
  Eigen::Matrix<double, 9, 1> dfdp0;  // ∂f/∂p0 (m²)
};

// x: current node positions (m), ordered so that the normal points out of the cavity.
// outside: the abdominal pressure on the outer face (hydrostatic too), subtracted; only
// inside.p0 is an unknown (dfdp0).
PressureResponse pressure_response(const std::array<Eigen::Vector3d, 3>& x,
                                   const HydrostaticPressure& inside,
                                   const HydrostaticPressure& outside);

// ∂V/∂x_a of the triangle's share V = x1·(x2×x3)/6 of the enclosed volume (m²).
Eigen::Matrix<double, 9, 1> volume_gradient(const std::array<Eigen::Vector3d, 3>& x);
double signed_volume(const std::array<Eigen::Vector3d, 3>& x);

}  // namespace vesica::simulate
