#pragma once
// The constitutive interface shared by every wall material (docs/physics.md §2): a 3-D law
// S(C) with its tangent, evaluated at one Gauss point. The membrane element enforces
// plane stress on top of it (PlaneStress.h), so a material never knows it is a membrane.
// Materials are built by name from a MaterialSpec through the registry
// (MaterialRegistry.h); there is no switch over material kinds anywhere.
#include <array>
#include <cstddef>
#include <limits>
#include <map>
#include <string>

#include <Eigen/Dense>

#include "vesica/simulate/materials/Voigt.h"

namespace vesica::simulate {

// A time step longer than every relaxation: the material's equilibrium response.
constexpr double kRelaxedStep = std::numeric_limits<double>::infinity();

// What a material may need about its point besides C.
struct MaterialPoint {
  // Unit fiber directions of the two families in the element's reference frame
  // (e1, e2, n0); in-plane, perpendicular.
  std::array<Eigen::Vector3d, 2> fibers{Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY()};
  // Time step of the current increment (viscoelastic and Hill updates): 0 = the
  // instantaneous response, kRelaxedStep = the relaxed one (a state held for long).
  double dt_s = 0.0;
  // Activation a(t) ∈ [0, 1] of the detrusor, from the protocol's activation curve: 0 at
  // rest (the muscle's tone only), 1 in a full voiding contraction.
  double activation = 0.0;
};

class Material {
 public:
  virtual ~Material() = default;

  // Number of history doubles a Gauss point stores (viscoelastic branches).
  virtual std::size_t history_size() const { return 0; }

  // True for an isotropic law without history and without active stress whose stress-free
  // state is C = I: such a sheet pulled to a stretch ≤ 1 in every direction carries no
  // tension, which lets the tension field (TensionField.h) recognize a slack element
  // without solving for its wrinkles.
  virtual bool isotropic_elastic() const { return false; }

  // C: right Cauchy-Green tensor (3x3, symmetric). history_old: committed state of the
  // point (history_size() doubles), history_new: written with the state that belongs to
  // this C. Outputs: S second Piola-Kirchhoff stress (Pa) and D = 2 dS/dC (Pa, Voigt).
  virtual void evaluate(const Eigen::Matrix3d& C, const MaterialPoint& point,
                        const double* history_old, double* history_new, Eigen::Matrix3d& S,
                        Voigt6& D) const = 0;

  // The wall's viscous overstress, a membrane quantity (docs/physics.md §2.5): called by the
  // plane-stress solve (PlaneStress.h) on its 3-D evaluation S, D at C = [C_αβ 0; 0 C33].
  // Adds an overstress with in-plane components only to S, and its derivative to the
  // in-plane rows of D, and writes its history. Nothing for a law without one.
  virtual void add_membrane_overstress(const Eigen::Matrix3d& /*C*/, const MaterialPoint& /*point*/,
                                       const double* /*history_old*/, double* /*history_new*/,
                                       Eigen::Matrix3d& /*S*/, Voigt6& /*D*/) const {}
};

// A material chosen by name with its parameters, as written in the pipeline file
// (SI units: Pa, s; e.g. {"neo-hookean", {{"mu", 5e3}, {"K", 1e4}}}).
struct MaterialSpec {
  std::string name = "neo-hookean";
  std::map<std::string, double> params;
};

}  // namespace vesica::simulate
