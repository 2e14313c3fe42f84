#pragma once
// Tension-field (wrinkling) membrane, docs/physics.md §1: a membrane has no bending stiffness,
// so it cannot carry compression; where the plane-stress law gives a compressive principal
// stress the real wall wrinkles (or goes slack) instead. The relaxed energy
//   W*(C) = min over β ≥ 0 and unit m of W(C + β m mᵀ)
// treats the wrinkles as a fictitious extra stretch β along the wrinkle direction m (a
// smooth sheet as long as the wrinkled one is wide). Its stress S* = S(C*) at the minimiser
// C* = C + β m mᵀ satisfies S* m = 0: tension along t ⊥ m only. The state is
//   taut:     S(C) has no negative principal stress → S* = S(C);
//   wrinkled: a minimiser with β > 0 and tension tᵀ S* t > 0 → S* = S(C*);
//   slack:    no tension in any direction → S* = 0, 𝔻* = 0.
// The tangent 𝔻* = dS*/dC follows by differentiating S(C*) m = 0 (two equations in β and
// the angle of m) implicitly, so Newton stays quadratic through wrinkling. Works for any
// material of the registry (it only calls plane_stress()).
#include <Eigen/Dense>

#include "vesica/simulate/materials/Material.h"
#include "wall/PlaneStress.h"

namespace vesica::simulate {

// Same contract as plane_stress(); the result's `wrinkling` says which state was found.
// Throws std::runtime_error when the wrinkle iteration does not converge (the caller cuts
// the step back).
PlaneStressState tension_field_stress(const Material& material, const Eigen::Matrix2d& C2,
                                      const MaterialPoint& point, double J2_guess,
                                      const double* history_old, double* history_new);

// The tension field of a wall that is not quite a membrane (docs/physics.md §1.6): a wrinkled
// or slack element keeps the share ε (`wrinkle_regularisation`) of the plain law's stress
// and tangent, S = (1 − ε) S* + ε S(C), the compression a wall of finite thickness carries
// before it buckles. A taut element is unchanged; ε = 0 is tension_field_stress(). The
// history written is the relaxed state's (the plain share's is discarded).
PlaneStressState regularised_tension_field_stress(const Material& material,
                                                  const Eigen::Matrix2d& C2,
                                                  const MaterialPoint& point, double J2_guess,
                                                  const double* history_old, double* history_new,
                                                  double epsilon);

}  // namespace vesica::simulate
