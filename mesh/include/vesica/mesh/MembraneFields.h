#pragma once
// What turns a surface triangle into a membrane element: a wall thickness and a local
// frame of two perpendicular in-plane fiber directions (family 1 follows a user
// direction, e.g. the bladder's long axis; family 2 = normal x family 1).
#include <map>

#include <Eigen/Core>

#include "vesica/core/Regions.h"
#include "vesica/mesh/SurfaceMesh.h"

namespace vesica::mesh {

struct MembraneOptions {
  double thickness_mm = 3.0;
  std::map<Region, double> thickness_by_region_mm;  // overrides for some regions
  Eigen::Vector3d fiber_direction = Eigen::Vector3d::UnitZ();
};

struct MembraneFields {
  Eigen::VectorXd thickness_mm;  // M
  Eigen::MatrixXd fiber1;        // M x 3, unit, in the triangle's plane
  Eigen::MatrixXd fiber2;        // M x 3, unit, in plane, perpendicular to fiber1
};

// The bladder's long axis: the principal direction of largest spread of the wall
// (area-weighted covariance of the triangle centroids), a unit vector.
Eigen::Vector3d long_axis(const SurfaceMesh& surface);

// Where the direction is (nearly) normal to a triangle its projection is meaningless;
// family 1 then follows the triangle's first edge.
MembraneFields membrane_fields(const SurfaceMesh& surface, const MembraneOptions& options);

}  // namespace vesica::mesh
