#pragma once
// Wrinkling of the membrane (physics.md §1): a membrane cannot carry compression, it
// wrinkles. The tension-field modification keeps only the tensile part of the in-plane
// stress: with the principal values s1 ≥ s2 of S (their signs are those of the Cauchy
// principal stresses, by congruence):
//  - taut (s2 ≥ 0): unchanged;
//  - wrinkled (s1 > 0 > s2): uniaxial tension S = s1 v1 v1ᵀ along the tensile direction,
//    tangent (v1ᵀ 𝔻 v1) m mᵀ (the stiffness along v1 only; symmetric, positive);
//  - slack (s1 ≤ 0): S = 0, 𝔻 = 0.
// A simple stress-based criterion: the tensile value keeps its biaxial magnitude (no
// relaxation of the lateral contraction), and the tangent ignores the turning of v1, so
// Newton converges linearly where elements wrinkle; in exchange the wall has no negative
// stiffness, which is what made the collapsing wall's steps wander.
#include "vesica/simulate/PlaneStress.h"

namespace vesica::simulate {

// Applies the modification to S and D in place; returns true when it changed them.
bool relax_compression(PlaneStressState& state);

}  // namespace vesica::simulate
