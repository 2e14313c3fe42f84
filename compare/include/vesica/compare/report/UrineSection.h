#pragma once
// The urine on the plane through the outlet's axis, cut from one frame of a level-2 fluid
// series (fluid.pvd; docs/navier-stokes.md §4): the tetrahedra's sections in 3-D (mm), the
// urine speed |u| (m/s) at each of their corners, interpolated linearly along the cut tet
// edges as the P1 velocity is. The plane holds the outlet's axis (the frame's
// outlet_centroid_mm and outlet_axis) and is as close to sagittal (normal ⟂ LPS x) as the
// axis allows. The report draws it twice: flat as the jet picture (FluidJetPicture.h) and
// inside the interactive wall (WallViewer.h).
#include <filesystem>
#include <vector>

#include <Eigen/Core>

namespace vesica::compare {

struct UrineSection {
  Eigen::Vector3d origin{0, 0, 0};  // the outlet's centroid, mm
  Eigen::Vector3d along{0, 0, 1};   // the outlet axis, towards the urethra
  Eigen::Vector3d across{1, 0, 0};  // in the plane, ⟂ along
  Eigen::Vector3d normal{0, 1, 0};  // of the plane
  std::vector<Eigen::Vector3d> points_mm;
  std::vector<double> speed_m_s;          // at each point
  std::vector<std::vector<int>> polygons;  // each tet's section: a triangle or a quad
  double max_speed_m_s = 0.0;              // over the whole frame, not only the plane
};

// Throws vesica::Error naming the file when it cannot be read, lacks velocity_mm_s on its
// nodes or the outlet's field data, holds a non-finite speed, or the plane cuts nothing.
UrineSection urine_section(const std::filesystem::path& vtu);

}  // namespace vesica::compare
