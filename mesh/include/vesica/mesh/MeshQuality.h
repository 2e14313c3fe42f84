#pragma once
// Element quality of the membrane and fluid meshes: what decides whether the solver
// will converge and whether the mesh is accurate enough.
#include <array>

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

#include "vesica/mesh/VolumeMesh.h"

namespace vesica::mesh {

// Per-tetrahedron shape measures.
struct TetShape {
  double volume_mm3 = 0.0;
  double min_dihedral_deg = 0.0;
  double max_dihedral_deg = 0.0;
  double radius_ratio = 0.0;  // 3 r_in / R_circ: 1 for the regular tetrahedron, 0 flat
};
TetShape tet_shape(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                   const Eigen::Vector3d& d);

// Smallest interior angle of a triangle, degrees.
double triangle_min_angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                              const Eigen::Vector3d& c);

struct MeshQuality {
  double triangle_min_angle_deg = 0.0;       // over all triangles
  double triangle_mean_min_angle_deg = 0.0;  // mean of each triangle's smallest angle
  double tet_min_dihedral_deg = 0.0;
  double tet_max_dihedral_deg = 0.0;
  double tet_min_radius_ratio = 0.0;
  double tet_fraction_radius_ratio_ge_0_3 = 0.0;
  std::array<long, 10> radius_ratio_histogram{};  // bins [0,0.1), ..., [0.9,1]
  long inverted_tets = 0;                         // volume <= 0
};

MeshQuality measure_quality(const VolumeMesh& mesh);
nlohmann::json to_json(const MeshQuality& q, bool with_tets);

}  // namespace vesica::mesh
