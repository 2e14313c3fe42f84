#include "vesica/surface/IlealPouch.h"

#include <algorithm>
#include <cmath>

#include "vesica/core/Error.h"
#include "vesica/core/PouchShape.h"

namespace vesica::surface {
namespace {

struct Segment {  // the ileal segment in mm
  double length_mm, circumference_mm, afferent_limb_mm;
};

// Detubularized reservoirs as ellipsoids (left-right x, antero-posterior y, cranio-caudal
// z), proportions as the reconstructions are drawn and imaged (docs/surface.md): the W
// pouch is nearly spherical, the U pouch an ovoid wider than tall.
Eigen::Vector3d reservoir_proportions(IlealConfiguration configuration) {
  switch (configuration) {
    case IlealConfiguration::Studer:
      return {1.5, 1.0, 1.0};
    case IlealConfiguration::Hautmann:
      return {1.2, 1.0, 1.0};
    default:
      return {1.0, 1.0, 1.0};
  }
}

double signed_distance_to_segment_capsule(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                          const Eigen::Vector3d& b, double radius) {
  const Eigen::Vector3d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm() - radius;
}

double ellipsoid_field(const Eigen::Vector3d& p, const Eigen::Vector3d& axes) {
  return pouch::ellipsoid_field({p.x(), p.y(), p.z()}, {axes.x(), axes.y(), axes.z()});
}

// The tube left whole (Camey I's principle): a closed tube of radius r = C/2π whose ends
// are rounded, cylinder length L - 2r, so its area C (L - 2r) + 4πr² is L C exactly. It lies
// left-right; the urethra is joined at the middle of its lowest line.
IlealPouchGeometry tubular(const Segment& s, IlealPouchGeometry g) {
  const double r = g.tube_radius_mm, half = 0.5 * (s.length_mm - 2 * r);
  if (!(half > 0)) usage_error("--ileum-length-cm must exceed the bowel's diameter C/π");
  const Eigen::Vector3d a(-half, 0, 0), b(half, 0, 0);
  g.field = [a, b, r](const Eigen::Vector3d& p) {
    return signed_distance_to_segment_capsule(p, a, b, r);
  };
  g.half_extent_mm = {half + r, r, r};
  g.reservoir_semi_axes_mm = {half + r, r, r};
  g.outlet_mm = {0, 0, -r};
  return g;
}

// Ellipsoid of the given proportions whose area is `area_mm2`.
Eigen::Vector3d semi_axes_of_area(const Eigen::Vector3d& proportions, double area_mm2) {
  return proportions * std::sqrt(area_mm2 / ellipsoid_area_mm2(proportions));
}

// A detubularized reservoir, with Studer's afferent limb when asked: a tube closed at its
// far end, leaving the reservoir left-right above its equator. The limb outside the
// reservoir has the area of its length (cylinder a - r plus a hemispherical end of area
// C r); the reservoir keeps the rest plus the disc the limb's mouth cuts from it.
IlealPouchGeometry detubularized(IlealConfiguration configuration, const Segment& s,
                                 IlealPouchGeometry g) {
  const double r = g.tube_radius_mm, limb = s.afferent_limb_mm;
  const double reservoir_area =
      (s.length_mm - limb) * s.circumference_mm + (limb > 0 ? M_PI * r * r : 0.0);
  const Eigen::Vector3d axes =
      semi_axes_of_area(reservoir_proportions(configuration), reservoir_area);
  g.reservoir_semi_axes_mm = axes;
  g.half_extent_mm = axes;
  g.outlet_mm = {0, 0, -axes.z()};
  if (limb <= 0) {
    g.field = [axes](const Eigen::Vector3d& p) { return ellipsoid_field(p, axes); };
    return g;
  }
  if (limb < 2 * r) usage_error("--afferent-limb-cm must exceed the bowel's diameter C/π");
  const double z0 = 0.4 * axes.z();  // the limb's axis: above the equator, as Studer's enters
  const double exit_x = axes.x() * std::sqrt(1 - (z0 / axes.z()) * (z0 / axes.z()));
  const Eigen::Vector3d a(0, 0, z0), b(exit_x + limb - r, 0, z0);
  g.field = [axes, a, b, r](const Eigen::Vector3d& p) {
    return pouch::smooth_union(ellipsoid_field(p, axes),
                               signed_distance_to_segment_capsule(p, a, b, r), 0.25 * r);
  };
  g.half_extent_mm = {b.x() + r, axes.y(), axes.z()};
  return g;
}

}  // namespace

double ellipsoid_area_mm2(const Eigen::Vector3d& semi_axes_mm) {
  // Midpoint rule in (θ, φ) of |∂x/∂θ × ∂x/∂φ| = sin θ |(bc sinθ cosφ, ac sinθ sinφ, ab cosθ)|.
  const double a = semi_axes_mm.x(), b = semi_axes_mm.y(), c = semi_axes_mm.z();
  const int n_theta = 400, n_phi = 800;
  const double d_theta = M_PI / n_theta, d_phi = 2 * M_PI / n_phi;
  double area = 0;
  for (int i = 0; i < n_theta; ++i) {
    const double th = (i + 0.5) * d_theta, st = std::sin(th), ct = std::cos(th);
    for (int j = 0; j < n_phi; ++j) {
      const double ph = (j + 0.5) * d_phi;
      area +=
          st *
          Eigen::Vector3d(b * c * st * std::cos(ph), a * c * st * std::sin(ph), a * b * ct).norm();
    }
  }
  return area * d_theta * d_phi;
}

IlealPouchGeometry ileal_pouch(IlealConfiguration configuration, const IleumSegment& ileum) {
  const Segment s{10 * ileum.length_cm, 10 * ileum.circumference_cm, 10 * ileum.afferent_limb_cm};
  if (!(s.length_mm > 0) || !(s.circumference_mm > 0))
    usage_error("--ileum-length-cm and --ileum-circumference-cm must be positive");
  if (s.afferent_limb_mm < 0 || s.afferent_limb_mm >= 0.5 * s.length_mm)
    usage_error("--afferent-limb-cm must be below half the segment");
  if (s.afferent_limb_mm > 0 && configuration != IlealConfiguration::Studer)
    usage_error("--afferent-limb-cm is Studer's: use it with --shape studer");
  IlealPouchGeometry g;
  g.tube_radius_mm = s.circumference_mm / (2 * M_PI);
  g.tissue_area_mm2 = s.length_mm * s.circumference_mm;
  if (configuration == IlealConfiguration::Tubular) return tubular(s, g);
  return detubularized(configuration, s, g);
}

}  // namespace vesica::surface
