#pragma once
// The bladder wall as the FEM sees it: a closed, outward-oriented triangle surface in
// SI units with region tags (core/Regions.h), reference thickness and fiber directions.
#include <array>
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace vesica::simulate {

enum class Posture { Supine, Sitting };
enum class ReferenceState { Scale, Prestress };

// How the imaged surface becomes the stress-free reference wall (load_wall, WallLoading.h).
struct WallOptions {
  double thickness_mm = 3.0;  // where the mesh gives no thickness_mm
  ReferenceState reference = ReferenceState::Scale;
  double residual_ml = 20.0;  // Scale: stress-free volume, below the start of filling
  // Scale: stress-free volume as a fraction of the mesh's own, replacing residual_ml when
  // > 0: a neobladder's tissue retracted from the pouch as built (docs/simulate.md).
  double residual_fraction = 0.0;
  double fixed_patch_radius_mm = 8.0;  // when the mesh has no outlet/inlet/fixed region
  Posture posture = Posture::Supine;   // decides "down" for the fallback fixed patch
};

struct WallModel {
  std::vector<Eigen::Vector3d> nodes;                  // reference positions (m)
  std::vector<std::array<int, 3>> triangles;           // outward-oriented
  std::vector<int> region;                             // Regions.h code per triangle
  std::vector<double> thickness;                       // reference thickness H (m) per triangle
  std::vector<std::array<Eigen::Vector3d, 2>> fibers;  // per triangle (unit, may be empty)
  // Per node and direction: held fixed (outlet/inlet caps, fixed region, or set by the
  // caller). Derived from the regions by fix_regions().
  std::vector<std::array<bool, 3>> fixed;
  std::vector<bool> support;  // node belongs to the elastic support region
  // Where the wall came from (load_wall): the mesh file as given, its content hash and the
  // options it was made the reference with. A wall built in memory has no file.
  std::string source_file, source_hash;
  WallOptions options;

  std::size_t node_count() const { return nodes.size(); }
  std::size_t triangle_count() const { return triangles.size(); }
};

// Enclosed volume (1/6) Σ x1·(x2×x3) of the surface at positions x (m³).
double enclosed_volume(const WallModel& wall, const std::vector<Eigen::Vector3d>& x);
// Area-weighted centroid of the surface (m).
Eigen::Vector3d surface_centroid(const WallModel& wall);

// Where Pves is measured (the reference height of the urine pressure): the bladder neck
// (centroid of the outlet patch's nodes), else the lowest node along g, else (no gravity)
// the centroid.
Eigen::Vector3d pressure_reference_point(const WallModel& wall, const Eigen::Vector3d& g);

// Marks the nodes of outlet, inlet and fixed triangles fixed and support nodes elastic.
// When nothing is fixed, holds the patch of nodes within patch_radius_m of the lowest
// node along `down` so that the model has no rigid-body motion; returns how many nodes
// were fixed.
std::size_t fix_regions(WallModel& wall, const Eigen::Vector3d& down, double patch_radius_m);

// Scales the reference surface about its centroid so that it encloses volume_m3 (the
// stress-free residual bladder, docs/physics.md §7 / issue 7).
void scale_to_volume(WallModel& wall, double volume_m3);

// Throws vesica::Error naming `source` when the surface is not closed and manifold
// (every edge in exactly two triangles, opposite orientation) or encloses no volume.
void check_closed_surface(const WallModel& wall, const std::string& source);

}  // namespace vesica::simulate
