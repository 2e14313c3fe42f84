#pragma once
// The stress state of one wall triangle for output (series.pvd, the summary's maximum wall
// stress): principal Cauchy stresses, current thickness and principal stretches. SI units.
namespace vesica::simulate {

// Cauchy stress and thickness of an element, σ = (1/J) g S gᵀ, J = h A/(H A0)
// (docs/physics.md §1).
struct MembraneStressOutput {
  double sigma1 = 0.0, sigma2 = 0.0;      // principal Cauchy stresses, σ1 ≥ σ2 (Pa)
  double thickness = 0.0;                 // h = H √C33 (m)
  double stretch1 = 1.0, stretch2 = 1.0;  // principal in-plane stretches
};

}  // namespace vesica::simulate
