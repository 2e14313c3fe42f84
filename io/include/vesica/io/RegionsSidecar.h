#pragma once
// "<surface>.regions.json": the region tags of a surface saved as STL, PLY or OBJ, formats
// without cell data, written beside it:
//   {"units": "mm", "triangle_count": M, "region_names": {"1": "wall", ...},
//    "region": [M tags in file order], "centroids_mm": [x0,y0,z0, x1,y1,z1, ...]}
// The triangle centroids let the tags follow an outside edit (MeshLab, Blender) that
// changes the triangles: every stage applies the one rule of retag_by_nearest_centroid.
#include <filesystem>
#include <optional>

#include <Eigen/Core>

#include "vesica/io/TaggedSurface.h"

namespace vesica::io {

struct RegionsSidecar {
  Eigen::VectorXi region;     // tags as recorded
  Eigen::MatrixXd centroids;  // one row per tag (mm); 0 rows when the file has none
};

std::filesystem::path regions_sidecar_path(const std::filesystem::path& surface_path);

// Writes the sidecar of `surface` atomically (tags as wall when it has none).
void write_regions_sidecar(const TaggedSurface& surface, const std::filesystem::path& sidecar);

// nullopt when there is no sidecar; throws vesica::Error naming it when it is not valid
// JSON, has no "region" array, a non-integer tag or centroids of the wrong length.
std::optional<RegionsSidecar> read_regions_sidecar(const std::filesystem::path& sidecar);

// The one rule for tags whose triangles changed: each triangle of `surface` takes the tag
// of the recorded triangle whose centroid is nearest to its own centroid.
Eigen::VectorXi retag_by_nearest_centroid(const Eigen::MatrixXd& recorded_centroids,
                                          const Eigen::VectorXi& recorded_region,
                                          const TaggedSurface& surface);

}  // namespace vesica::io
