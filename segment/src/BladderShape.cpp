#include "vesica/segment/BladderShape.h"

#include <algorithm>
#include <cmath>

namespace vesica::segment {
namespace {

constexpr double kEllipsoidRatios[3] = {1.25, 1.0, 0.8};  // L-R : A-P : I-S, as when filled
constexpr double kMm3PerMl = 1e3;
constexpr int kPouchColumns = 400;  // per half axis; integration error well below 1e-4

// The ends of the inside intervals of one column: the field is sampled on `steps` points
// and every sign change refined by bisection to round-off.
void column_intervals(const std::function<double(double)>& f, double z0, double z1, int steps,
                      double& length, double& moment) {
  const double dz = (z1 - z0) / steps;
  double za = z0, fa = f(z0), enter = 0;
  bool inside = fa < 0;
  if (inside) enter = z0;
  for (int k = 1; k <= steps; ++k) {
    const double zb = z0 + k * dz, fb = f(zb);
    if ((fb < 0) != inside) {
      double lo = za, hi = zb;
      for (int it = 0; it < 60 && hi - lo > 1e-12 * (1 + std::abs(hi)); ++it) {
        const double mid = 0.5 * (lo + hi);
        ((f(mid) < 0) == inside ? lo : hi) = mid;
      }
      const double z = 0.5 * (lo + hi);
      if (inside) {
        length += z - enter;
        moment += 0.5 * (z * z - enter * enter);
      } else {
        enter = z;
      }
      inside = !inside;
    }
    za = zb;
    fa = fb;
  }
  if (inside) {
    length += z1 - enter;
    moment += 0.5 * (z1 * z1 - enter * enter);
  }
}

}  // namespace

ShapeIntegral integrate_mirror_symmetric(const std::function<double(double, double, double)>& level,
                                         double half_x, double half_y, double z0, double z1,
                                         int n) {
  const double hx = half_x / n, hy = half_y / n;
  const int steps = 64;  // finds each interval of a column; bisection then refines its ends
  double volume = 0, moment = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = (i + 0.5) * hx, y = (j + 0.5) * hy;
      double length = 0, m = 0;
      column_intervals([&](double z) { return level(x, y, z); }, z0, z1, steps, length, m);
      volume += length;
      moment += m;
    }
  ShapeIntegral r;
  r.volume_mm3 = 4.0 * volume * hx * hy;  // four mirrored quarters
  r.centroid_z_mm = volume > 0 ? moment / volume : 0.0;
  return r;
}

BladderShape::BladderShape(const BladderShapeSpec& spec) : spec_(spec), volume_ml_(spec.volume_ml) {
  const double product = 3.0 * spec.volume_ml * kMm3PerMl / (4.0 * M_PI);  // a*b*c, mm^3
  centroid_mm_ = spec.center_mm;
  switch (spec.shape) {
    case PhantomShape::Sphere:
      semi_axes_mm_.fill(std::cbrt(product));
      break;
    case PhantomShape::Ellipsoid: {
      const double k =
          std::cbrt(product / (kEllipsoidRatios[0] * kEllipsoidRatios[1] * kEllipsoidRatios[2]));
      for (int i = 0; i < 3; ++i) semi_axes_mm_[i] = k * kEllipsoidRatios[i];
      break;
    }
    case PhantomShape::Pouch: {
      // The surface stage contours this field and rescales the contour to the volume; the
      // same scale here comes from the field's integrated volume instead of a contour's.
      pouch_ = pouch::pouch_geometry(spec.volume_ml, spec.elongation, spec.neck_radius_mm);
      const auto& g = pouch_;
      const auto& a = g.semi_axes_mm;
      const double margin = g.neck_radius_mm;
      const auto integral = integrate_mirror_symmetric(
          [&g](double x, double y, double z) {
            return pouch::pouch_field(g, {x, y, z});
          },
          a[0] + margin, a[1] + margin, g.lowest_z_mm - margin, a[2] + margin, kPouchColumns);
      pouch_scale_ = std::cbrt(spec.volume_ml * kMm3PerMl / integral.volume_mm3);
      for (int i = 0; i < 3; ++i) semi_axes_mm_[i] = pouch_scale_ * a[i];
      centroid_mm_[2] += pouch_scale_ * integral.centroid_z_mm;
      break;
    }
  }
}

double BladderShape::pouch_level(const std::array<double, 3>& p) const {
  const double s = pouch_scale_;
  const auto& c = spec_.center_mm;
  return s * pouch::pouch_field(pouch_, {(p[0] - c[0]) / s, (p[1] - c[1]) / s, (p[2] - c[2]) / s});
}

bool BladderShape::inside(const std::array<double, 3>& p, double grow_mm) const {
  if (spec_.shape == PhantomShape::Pouch) return pouch_level(p) <= grow_mm;
  const auto& c = spec_.center_mm;
  double sum = 0;
  for (int i = 0; i < 3; ++i) {
    const double d = (p[i] - c[i]) / (semi_axes_mm_[i] + grow_mm);
    sum += d * d;
  }
  return sum <= 1;
}

int BladderShape::layer(const std::array<double, 3>& p, const double* grows, int count) const {
  if (count == 0) return 0;
  // Outside the ball that holds the shape grown by the largest distance there is no layer
  // (most of a phantom lies there). A distance-like field grown by g reaches at most
  // g * largest / smallest semi-axis beyond the shape.
  const auto [lo, hi] = std::minmax({semi_axes_mm_[0], semi_axes_mm_[1], semi_axes_mm_[2]});
  const double reach =
      std::max(hi, spec_.center_mm[2] - lowest_z_mm()) + grows[count - 1] * hi / lo + 1.0;
  double r2 = 0;
  for (int i = 0; i < 3; ++i) r2 += (p[i] - spec_.center_mm[i]) * (p[i] - spec_.center_mm[i]);
  if (r2 > reach * reach) return count;
  if (spec_.shape == PhantomShape::Pouch) {
    const double level = pouch_level(p);
    for (int k = 0; k < count; ++k)
      if (level <= grows[k]) return k;
    return count;
  }
  for (int k = 0; k < count; ++k)
    if (inside(p, grows[k])) return k;
  return count;
}

double BladderShape::lowest_z_mm() const {
  if (spec_.shape != PhantomShape::Pouch) return spec_.center_mm[2] - semi_axes_mm_[2];
  return spec_.center_mm[2] + pouch_scale_ * pouch_.lowest_z_mm;
}

}  // namespace vesica::segment
