#pragma once
// Neobladder configurations built from the ileum a surgeon uses (docs/surface.md, "Ileal
// neobladders"; docs/physics.md §10.3): a segment of length L and circumference C, its
// tissue area L x C conserved, left tubular (a closed tube), detubularized and folded
// (U / Studer, W / Hautmann), or the ideal detubularized sphere of that area. Millimetres;
// the outlet, where the urethra is anastomosed, is the pouch's lowest point.
#include <functional>

#include <Eigen/Core>

namespace vesica::surface {

enum class IlealConfiguration { Tubular, Studer, Hautmann, Sphere };

// In cm, as surgeons measure the bowel.
struct IleumSegment {
  double length_cm = 40.0;        // L: the whole segment used, afferent limb included
  double circumference_cm = 8.0;  // C: the bowel's circumference (lumen about 2.5 cm)
  double afferent_limb_cm = 0.0;  // Studer only: proximal limb left tubular (0 = none)
};

struct IlealPouchGeometry {
  std::function<double(const Eigen::Vector3d&)> field;  // < 0 inside, ~ signed distance
  Eigen::Vector3d half_extent_mm =
      Eigen::Vector3d::Zero();  // the shape lies in [-h, h] (x, y) and [lowest, h] (z)
  Eigen::Vector3d outlet_mm =
      Eigen::Vector3d::Zero();  // the urethral anastomosis: the lowest point
  Eigen::Vector3d reservoir_semi_axes_mm =
      Eigen::Vector3d::Zero();   // detubularized reservoir (tube: r, r, half length)
  double tube_radius_mm = 0.0;   // C / 2π
  double tissue_area_mm2 = 0.0;  // L x C: what the surface's area must equal
};

// Throws a usage error when the segment cannot make that configuration (a tube shorter
// than its own diameter, an afferent limb longer than the segment).
IlealPouchGeometry ileal_pouch(IlealConfiguration configuration, const IleumSegment& segment);

// Surface area of the ellipsoid with these semi-axes (mm²), by quadrature: no closed form.
double ellipsoid_area_mm2(const Eigen::Vector3d& semi_axes_mm);

}  // namespace vesica::surface
