#pragma once
// Shape quality of the moving urine tetrahedra (docs/navier-stokes.md §1): the ALE mesh is
// remeshed when it drops too far. Radius ratio ρ = 3 r_in / r_circ: 1 for the regular
// tetrahedron, 0 for a flat one; negative for an inverted one (signed volume).
#include <array>
#include <vector>

#include <Eigen/Dense>

namespace vesica::simulate::fluid {

// Radius ratio of the tetrahedron (a, b, c, d), with the sign of its volume
// (b − a)·((c − a)×(d − a)).
double radius_ratio(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                    const Eigen::Vector3d& d);

// Smallest radius ratio over the tetrahedra at positions x, each signed relative to its
// orientation at positions x_reference (so an inverted element is negative).
double min_radius_ratio(const std::vector<Eigen::Vector3d>& x,
                        const std::vector<Eigen::Vector3d>& x_reference,
                        const std::vector<std::array<int, 4>>& tets);

}  // namespace vesica::simulate::fluid
