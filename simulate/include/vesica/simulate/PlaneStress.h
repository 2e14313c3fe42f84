#pragma once
// Plane stress for any 3-D law S(C) (physics.md §1): the wall is free through its
// thickness, S33 = 0. In the element's reference frame C = [C_αβ 0; 0 C33]; C33 (the
// squared thickness stretch) is found by a local Newton iteration on S33(C33) = 0, and
// the tangent is condensed to the plane, 𝔻_mem = A - B D⁻¹ Bᵀ.
#include <Eigen/Dense>

#include "vesica/simulate/Material.h"

namespace vesica::simulate {

struct PlaneStressState {
  Eigen::Matrix2d S;  // in-plane S_αβ (Pa)
  Eigen::Matrix3d D;  // condensed 2 dS/dC in-plane, Voigt order 11, 22, 12 (Pa)
  double C33 = 1.0;   // squared thickness stretch
};

// C2: in-plane C_αβ. C33_guess: start of the local iteration (last converged value).
// Throws std::runtime_error when the local iteration does not converge (the caller cuts
// the step back).
PlaneStressState plane_stress(const Material& material, const Eigen::Matrix2d& C2,
                              const MaterialPoint& point, double C33_guess,
                              const double* history_old, double* history_new);

}  // namespace vesica::simulate
