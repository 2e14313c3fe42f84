#include "vesica/simulate/wall/WallLoading.h"

#include "vesica/core/ContentHash.h"
#include "vesica/core/Error.h"
#include "vesica/core/Units.h"
#include "vesica/simulate/wall/MeshReader.h"

namespace vesica::simulate {

Eigen::Vector3d gravity_lps(Posture posture) {
  return posture == Posture::Supine ? Eigen::Vector3d(0.0, units::kStandardGravity, 0.0)
                                    : Eigen::Vector3d(0.0, 0.0, -units::kStandardGravity);
}

WallModel load_wall(const std::filesystem::path& path, const WallOptions& options) {
  if (!(options.thickness_mm > 0.0)) usage_error("thickness_mm must be > 0");
  WallModel wall = read_wall(path, units::m_from_mm(options.thickness_mm));
  if (options.reference == ReferenceState::Scale) {
    if (!(options.residual_ml > 0.0)) usage_error("residual_ml must be > 0");
    const double residual_m3 = options.residual_fraction > 0.0
                                   ? options.residual_fraction * enclosed_volume(wall, wall.nodes)
                                   : units::m3_from_ml(options.residual_ml);
    scale_to_volume(wall, residual_m3);
  }
  const Eigen::Vector3d down = gravity_lps(options.posture).normalized();
  fix_regions(wall, down, units::m_from_mm(options.fixed_patch_radius_mm));
  wall.source_file = path.string();
  wall.source_hash = content_hash(path);
  wall.options = options;
  // What ran: a fraction's residual volume, so the model card names the volume it scaled to.
  if (options.reference == ReferenceState::Scale && options.residual_fraction > 0.0)
    wall.options.residual_ml = units::ml_from_m3(enclosed_volume(wall, wall.nodes));
  return wall;
}

}  // namespace vesica::simulate
