#pragma once
// Urine as an incompressible Newtonian fluid (docs/physics.md §4). SI units.
#include <Eigen/Dense>

namespace vesica::simulate::fluid {

struct FluidProperties {
  double density = 1000.0;                   // ρ, kg/m³
  double viscosity = 1e-3;                   // μ, Pa·s
  Eigen::Vector3d gravity{0.0, 0.0, -9.81};  // g, m/s² (body force ρ g)
};

}  // namespace vesica::simulate::fluid
