#pragma once
// Region tags on a closed surface for the later stages (codes in vesica/core/Regions.h):
// outlet (bladder neck) patch, ureter inlet patches, fixed base/trigone, elastic support.
// Where patches overlap, outlet wins over inlet, inlet over fixed, fixed over support.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "vesica/surface/TriangleSurface.h"

namespace vesica::surface {

struct RegionOptions {
  // Bladder neck landmark (mm, LPS); none = the most inferior vertex (smallest z in LPS).
  std::optional<Eigen::Vector3d> outlet;
  double outlet_radius_mm = 5.0;        // geodesic radius of the outlet patch
  std::vector<Eigen::Vector3d> inlets;  // ureter orifice landmarks (mm, LPS)
  double inlet_radius_mm = 3.0;
  double fixed_radius_mm = 0.0;   // fixed base: geodesic radius around the outlet (0 = none)
  double fixed_below_mm = 0.0;    // or: everything up to this height above the outlet (0 = none)
  double support_below_mm = 0.0;  // elastic support up to this height above the outlet (0 = none)
  double max_landmark_distance_mm = 20.0;  // landmarks farther from the surface are errors
};

struct RegionSummary {
  Eigen::Vector3d outlet_mm = Eigen::Vector3d::Zero();  // the outlet patch's centre vertex
  std::vector<int> triangle_counts;                     // per Regions.h code 0..5
};

// Shortest edge-path distances (mm) from one vertex: a close upper bound of geodesic
// distance on a well-shaped mesh.
Eigen::VectorXd edge_path_distances(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, int source);

// Sets surface.region. Throws vesica::Error (usage) for a landmark far from the surface.
RegionSummary assign_regions(const RegionOptions& options, TriangleSurface& surface);

}  // namespace vesica::surface
