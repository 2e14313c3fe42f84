#pragma once
// The ileal neobladder pouch as an implicit shape, in millimetres: a reservoir ellipsoid
// elongated left-right (x), joined by a smooth fillet to a short outlet neck (a vertical
// capsule) whose rounded end is the pouch's lowest point (smallest z), the outlet.
//
// One definition for two stages: the surface stage contours it (`vesica-surface --shape
// pouch`) and the phantom fills it with urine (`vesica-phantom --shape pouch`), so a
// what-if study can start from either and see the same pouch. Header-only: core links
// no geometry library, and segment must not depend on surface.
#include <algorithm>
#include <array>
#include <cmath>

namespace vesica::pouch {

using Vec3 = std::array<double, 3>;

struct PouchGeometry {
  Vec3 semi_axes_mm{};          // reservoir ellipsoid, centred on the origin
  double neck_radius_mm = 0;    // radius of the neck capsule
  double neck_bottom_z_mm = 0;  // the neck's axis runs from here up to z = 0
  double lowest_z_mm = 0;       // the outlet: bottom of the neck's rounded end
};

// Semi-axes (elongation, 1, 1) * k of the ellipsoid that holds volume_ml.
inline Vec3 reservoir_semi_axes_mm(double volume_ml, double elongation) {
  const double r = std::cbrt(3.0 * volume_ml * 1e3 / (4.0 * M_PI));  // sphere of that volume
  const double k = std::cbrt(r * r * r / elongation);
  return {elongation * k, k, k};
}

// neck_radius_mm <= 0 chooses a quarter of the reservoir's smallest semi-axis. The neck's
// axis starts half a radius below the reservoir, so the fillet has room to form.
inline PouchGeometry pouch_geometry(double volume_ml, double elongation, double neck_radius_mm) {
  PouchGeometry g;
  g.semi_axes_mm = reservoir_semi_axes_mm(volume_ml, elongation);
  const double smallest = *std::min_element(g.semi_axes_mm.begin(), g.semi_axes_mm.end());
  g.neck_radius_mm = neck_radius_mm > 0 ? neck_radius_mm : 0.25 * smallest;
  g.neck_bottom_z_mm = -g.semi_axes_mm[2] - 0.5 * g.neck_radius_mm;
  g.lowest_z_mm = g.neck_bottom_z_mm - g.neck_radius_mm;
  return g;
}

// Zero set is the exact ellipsoid; the value approximates a signed distance (< 0 inside).
inline double ellipsoid_field(const Vec3& p, const Vec3& axes) {
  const double u = p[0] / axes[0], v = p[1] / axes[1], w = p[2] / axes[2];
  return (std::sqrt(u * u + v * v + w * w) - 1.0) * std::min({axes[0], axes[1], axes[2]});
}

// Signed distance to a vertical capsule around the segment z in [z0, z1]: the rounded
// end gives the neck a single lowest point, the outlet.
inline double capsule_field(const Vec3& p, double radius, double z0, double z1) {
  const double dz = p[2] - std::clamp(p[2], z0, z1);
  return std::sqrt(p[0] * p[0] + p[1] * p[1] + dz * dz) - radius;
}

// Polynomial smooth minimum: a fillet of width k where the neck meets the reservoir.
inline double smooth_union(double a, double b, double k) {
  const double h = std::clamp(0.5 + 0.5 * (b - a) / k, 0.0, 1.0);
  return b * (1 - h) + a * h - k * h * (1 - h);
}

// < 0 inside the pouch; approximately the signed distance to its wall near it (mm).
inline double pouch_field(const PouchGeometry& g, const Vec3& p) {
  return smooth_union(ellipsoid_field(p, g.semi_axes_mm),
                      capsule_field(p, g.neck_radius_mm, g.neck_bottom_z_mm, 0.0),
                      0.5 * g.neck_radius_mm);
}

}  // namespace vesica::pouch
