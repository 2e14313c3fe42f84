#pragma once
// Plane stress for any 3-D law S(C) (docs/physics.md §1): the wall is free through its
// thickness, S33 = 0. In the element's reference frame C = [C_αβ 0; 0 C33]; C33 (the
// squared thickness stretch) is found by a local Newton iteration on S33(C33) = 0, and
// the tangent is condensed to the plane, 𝔻_mem = A - B D⁻¹ Bᵀ. The material's membrane
// overstress (its viscous branches, Material::add_membrane_overstress) is added at the
// root: it has no thickness component.
#include <Eigen/Dense>

#include "vesica/simulate/materials/Material.h"
#include "vesica/simulate/materials/Voigt.h"

namespace vesica::simulate {

// Wrinkling state of a tension-field membrane (TensionField.h); always taut otherwise.
enum class Wrinkling { taut, wrinkled, slack };

struct PlaneStressState {
  Eigen::Matrix2d S;  // in-plane S_αβ (Pa)
  Eigen::Matrix3d D;  // condensed 2 dS/dC in-plane, Voigt order 11, 22, 12 (Pa)
  double C33 = 1.0;   // squared thickness stretch
  double J2 = 1.0;    // squared volume ratio det C = C33 det C2 (the next call's guess)
  Wrinkling wrinkling = Wrinkling::taut;
};

// C2: in-plane C_αβ. J2_guess: the squared volume ratio J² = det C the iteration starts
// from, at C33 = J² / det C2 (≤ 0: 1, exact for an incompressible wall). J² changes far
// less between evaluations than C33 does (a wall stretched in the plane thins), so the
// last J² of the element is a guess within a few ulps of the root for a nearly
// incompressible wall, even when C2 has changed a lot (a new Newton iterate, the
// fictitious stretch of a wrinkled element).
// Throws std::runtime_error when the local iteration does not converge (the caller cuts
// the step back).
PlaneStressState plane_stress(const Material& material, const Eigen::Matrix2d& C2,
                              const MaterialPoint& point, double J2_guess,
                              const double* history_old, double* history_new);

// Whether S33 of a 3-D evaluation S, D at thickness stretch² c33 is zero: below 1e-13 of
// the in-plane stress scale (|S11| + |S22| + |S12| by default) or of its own round-off.
bool plane_stress_converged(const Eigen::Matrix3d& S, const Voigt6& D, double c33,
                            double stress_scale = -1.0);

// The plane-stress state of a 3-D evaluation S, D at C = [C2 0; 0 c33] with S33 = 0
// (det2 = det C2): the in-plane stress and the tangent condensed to the plane.
PlaneStressState condensed_state(const Eigen::Matrix3d& S, const Voigt6& D, double c33,
                                 double det2);

}  // namespace vesica::simulate
