#pragma once
// The 3-node membrane element, total Lagrangian (docs/physics.md §1). One Gauss point: the
// shape-function gradients are constant over the triangle.
#include <array>

#include <Eigen/Dense>

#include "vesica/simulate/materials/Material.h"
#include "vesica/simulate/wall/WallModel.h"
#include "vesica/simulate/wall/WallStress.h"
#include "wall/PlaneStress.h"

namespace vesica::simulate {

using Vector9 = Eigen::Matrix<double, 9, 1>;
using Matrix9 = Eigen::Matrix<double, 9, 9>;

// Reference geometry: local orthonormal frame e1 along edge 1→2, n0 the unit normal,
// e2 = n0 × e1; dN(α, a) = ∂N_a/∂s_α in that frame (1/m); area A0 (m²); thickness H (m).
struct MembraneGeometry {
  Eigen::Matrix3d frame;  // rows e1, e2, n0
  Eigen::Matrix<double, 2, 3> dN;
  double area0 = 0.0;
  double H = 0.0;
};

// X: reference node positions (m). Throws std::invalid_argument for a degenerate triangle.
MembraneGeometry membrane_geometry(const std::array<Eigen::Vector3d, 3>& X, double H);

// The two fiber directions of element e in its frame (docs/physics.md §2.4): the mesh's
// fiber1, fiber2 rotated into the frame and projected into its plane, else (no fibers,
// or one normal to the element) the frame's own e1, e2. Unit, in-plane.
std::array<Eigen::Vector3d, 2> element_fibers(const MembraneGeometry& geometry,
                                              const WallModel& wall, std::size_t e);

// What one element gives at the current positions x (m). With tension_field the stress is
// the wrinkling membrane's (TensionField.h; wrinkle_regularisation its share ε of the plain
// law), else the plain plane-stress law's.
struct MembraneResponse {
  Vector9 f_int;  // internal nodal forces f_a = H A0 S_αβ g_α ∂N_a/∂s_β (N)
  Matrix9 K;  // material (𝔻_mem) + geometric (S_αβ ∂N_a/∂s_α ∂N_b/∂s_β I₃) (N/m)
  Eigen::Matrix<double, 3, 2> g;  // covariant vectors g_α = Σ x_a ∂N_a/∂s_α
  PlaneStressState stress;
};

MembraneResponse membrane_response(const MembraneGeometry& geometry,
                                   const std::array<Eigen::Vector3d, 3>& x,
                                   const Material& material, const MaterialPoint& point,
                                   double J2_guess, const double* history_old, double* history_new,
                                   bool tension_field = false, double wrinkle_regularisation = 0.0);

// Cauchy stress and thickness of a response, for output (WallStress.h).
MembraneStressOutput membrane_stress_output(const MembraneGeometry& geometry,
                                            const MembraneResponse& response);

}  // namespace vesica::simulate
