#pragma once
// The wall a cystometry runs on, from a mesh file: read (MeshReader.h), made the stress-free
// reference (scaled to the residual volume, or prestressed later by run_cystometry), and
// held at its caps or a base patch. Clinical units (mm, ml) in WallOptions; the wall in SI.
//   WallModel wall = load_wall("bladder.vtu", WallOptions{});
#include <filesystem>

#include <Eigen/Dense>

#include "vesica/simulate/wall/WallModel.h"

namespace vesica::simulate {

// Gravity vector in LPS patient coordinates (m/s²): supine = towards posterior (+y),
// sitting = towards inferior (-z).
Eigen::Vector3d gravity_lps(Posture posture);

// Reads the mesh (MeshReader.h), makes the reference state (Scale: about the centroid to
// residual_ml) and fixes the caps (outlet, inlet), the fixed region or a base patch.
// Prestress is applied later by run_cystometry (it needs the material).
WallModel load_wall(const std::filesystem::path& path, const WallOptions& options);

}  // namespace vesica::simulate
