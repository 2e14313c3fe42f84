#pragma once
// The wall a cystometry runs on, from a mesh file: read (MeshReader.h), made the stress-free
// reference (scaled to the residual volume, or prestressed later by run_cystometry), and
// held at its caps or a base patch. Clinical units (mm, ml) in WallOptions; the wall in SI.
//   WallModel wall = load_wall("bladder.vtu", WallOptions{});
#include <filesystem>

#include <Eigen/Dense>

#include "vesica/simulate/wall/WallModel.h"

namespace vesica::simulate {

enum class Posture { Supine, Sitting };
enum class ReferenceState { Scale, Prestress };

// How the imaged surface becomes the stress-free reference wall.
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

// Gravity vector in LPS patient coordinates (m/s²): supine = towards posterior (+y),
// sitting = towards inferior (-z).
Eigen::Vector3d gravity_lps(Posture posture);

// Reads the mesh (MeshReader.h), makes the reference state (Scale: about the centroid to
// residual_ml) and fixes the caps (outlet, inlet), the fixed region or a base patch.
// Prestress is applied later by run_cystometry (it needs the material).
WallModel load_wall(const std::filesystem::path& path, const WallOptions& options);

}  // namespace vesica::simulate
