#pragma once
// Small helpers shared by the surface tests: distances between surfaces with VTK point
// locators (independent of CGAL), running the stage into a scratch folder.
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "vesica/surface/SurfaceStage.h"

namespace vesica::test {

// Largest distance from each query point to the nearest point of a triangle set.
double max_distance_to_triangles(const Eigen::MatrixXd& points, const Eigen::MatrixXd& V,
                                 const Eigen::MatrixXi& F);

// Vertices and triangle centroids: the sample of a surface used for distances from it.
Eigen::MatrixXd surface_samples(const surface::TriangleSurface& s);

// A VTP file's "region" cell array type name ("vtkIntArray" for Int32) and its field data
// "units" value ("" when missing).
std::string vtp_region_array_class(const std::string& path);
std::string vtp_units(const std::string& path);

// Outlet-tagged triangles, and the largest height of any of their vertices above the
// surface's lowest point (LPS: smallest z).
struct OutletPatch {
  int triangles = 0;
  double max_height_mm = 0.0;
};
OutletPatch outlet_patch(const surface::TriangleSurface& s);

// Runs the stage as the executable would, with a throw-away record.
surface::TriangleSurface run_stage(const surface::SurfaceStageOptions& options,
                                   nlohmann::json* summary = nullptr);

}  // namespace vesica::test
