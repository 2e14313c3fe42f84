#pragma once
// The phantom's bladder (its urine) as an implicit shape in patient millimetres (LPS):
// a sphere, an ellipsoid (semi-axes 1.25 : 1 : 0.8, L-R : A-P : I-S) or the ileal
// neobladder pouch of the surface stage (vesica/core/PouchShape.h), scaled to hold
// exactly the requested volume. Inside tests and the volume do not depend on any grid.
#include <array>
#include <functional>

#include "vesica/core/PouchShape.h"

namespace vesica::segment {

enum class PhantomShape { Sphere, Ellipsoid, Pouch };

struct BladderShapeSpec {
  PhantomShape shape = PhantomShape::Sphere;
  double volume_ml = 300.0;
  std::array<double, 3> center_mm = {0.0, -15.0, -10.0};  // sphere/ellipsoid centre; pouch
                                                          // reservoir centre
  double elongation = 1.0;      // pouch: left-right length ratio (as vesica-surface)
  double neck_radius_mm = 0.0;  // pouch: 0 = a quarter of the reservoir
};

class BladderShape {
 public:
  explicit BladderShape(const BladderShapeSpec& spec);

  // Inside the urine grown outwards by grow_mm (0 = the urine itself). Sphere and
  // ellipsoid grow their semi-axes; the pouch its distance-like field.
  bool inside(const std::array<double, 3>& p, double grow_mm = 0.0) const;

  // The first of `count` ascending grow distances whose grown shape holds p, or count
  // when none does: one evaluation of the shape for all layers (urine, wall, fat).
  int layer(const std::array<double, 3>& p, const double* grows_mm, int count) const;

  double volume_ml() const { return volume_ml_; }  // exact (pouch: integrated, see .cpp)
  const std::array<double, 3>& centroid_mm() const { return centroid_mm_; }
  // Sphere/ellipsoid semi-axes; for the pouch those of its reservoir.
  const std::array<double, 3>& semi_axes_mm() const { return semi_axes_mm_; }
  // The lowest point (smallest z) of the urine, LPS mm: the pouch's outlet.
  double lowest_z_mm() const;

 private:
  double pouch_level(const std::array<double, 3>& p) const;  // mm, < 0 inside

  BladderShapeSpec spec_;
  double volume_ml_ = 0;
  std::array<double, 3> centroid_mm_{};
  std::array<double, 3> semi_axes_mm_{};
  pouch::PouchGeometry pouch_;  // before scaling
  double pouch_scale_ = 1.0;    // the pouch field's shape is scaled by this to hold volume_ml
};

// Volume (mm^3) and centroid height (mm) of {level < 0} for a shape mirror-symmetric in
// x and y that lies within |x| <= half_x, |y| <= half_y, z0 <= z <= z1: the midpoint rule
// over n x n columns of the quarter x, y >= 0, each column's inside intervals found by
// marching along z and bisection.
struct ShapeIntegral {
  double volume_mm3 = 0;
  double centroid_z_mm = 0;
};
ShapeIntegral integrate_mirror_symmetric(const std::function<double(double, double, double)>& level,
                                         double half_x, double half_y, double z0, double z1, int n);

}  // namespace vesica::segment
