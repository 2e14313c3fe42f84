#include "vesica/segment/Phantom.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <thread>
#include <vector>

#include <itkImageRegionIteratorWithIndex.h>

namespace vesica::segment {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kFatShellMm = 15.0;   // perivesical fat around the bladder
constexpr double kRectumGapMm = 18.0;  // fat shell surface to rectum axis
constexpr double kRectumRadiusMm = 17.0, kRectumLumenMm = 11.0;
// Relative semi-axes of the ellipsoidal bladder (wider than tall, as when filled).
constexpr double kEllipsoidRatios[3] = {1.25, 1.0, 0.8};

struct Anatomy {
  double cx, cy, cz;  // bladder centre (LPS mm)
  double ax, ay, az;  // bladder semi-axes
  double rectum_y;    // rectum axis (runs head-feet)

  static double inside_ellipsoid(double x, double y, double z, double a, double b, double c) {
    return x * x / (a * a) + y * y / (b * b) + z * z / (c * c);
  }

  // HU at a patient point. Order matters: the bladder and its fat override the rest.
  double hu(double x, double y, double z) const {
    const double dx = x - cx, dy = y - cy, dz = z - cz;
    if (inside_ellipsoid(dx, dy, dz, ax, ay, az) <= 1) return PhantomTissues::kUrine;
    if (inside_ellipsoid(dx, dy, dz, ax + kFatShellMm, ay + kFatShellMm, az + kFatShellMm) <= 1)
      return PhantomTissues::kFat;
    const double body = x * x / (170.0 * 170.0) + (y - 10) * (y - 10) / (125.0 * 125.0);
    if (body > 1) return PhantomTissues::kAir;
    const double rr = x * x + (y - rectum_y) * (y - rectum_y);
    if (rr <= kRectumLumenMm * kRectumLumenMm) return PhantomTissues::kAir;
    if (rr <= kRectumRadiusMm * kRectumRadiusMm) return PhantomTissues::kMuscle;
    const double ring_outer = x * x / (135.0 * 135.0) + (y - 10) * (y - 10) / (110.0 * 110.0);
    const double ring_inner = x * x / (120.0 * 120.0) + (y - 10) * (y - 10) / (95.0 * 95.0);
    if (ring_outer <= 1 && ring_inner > 1) return PhantomTissues::kBone;
    const double subcutaneous = x * x / (158.0 * 158.0) + (y - 10) * (y - 10) / (113.0 * 113.0);
    if (subcutaneous > 1) return PhantomTissues::kFat;
    return PhantomTissues::kMuscle;
  }
};

Anatomy anatomy_of(const PhantomSpec& spec) {
  const PhantomTruth t = phantom_truth(spec);
  Anatomy a{};
  a.cx = t.bladder_center_mm[0];
  a.cy = t.bladder_center_mm[1];
  a.cz = t.bladder_center_mm[2];
  a.ax = t.bladder_semi_axes_mm[0];
  a.ay = t.bladder_semi_axes_mm[1];
  a.az = t.bladder_semi_axes_mm[2];
  a.rectum_y = a.cy + a.ay + kFatShellMm + kRectumGapMm;
  return a;
}

CtImage::DirectionType direction_of(const PhantomSpec& spec) {
  CtImage::DirectionType d;
  d.SetIdentity();
  if (spec.orientation == PhantomOrientation::Oblique) {
    // A gantry-tilt-like rotation about the L-R axis, then a small in-plane turn.
    const double a = 20.0 * kPi / 180.0, b = 15.0 * kPi / 180.0;
    CtImage::DirectionType rx, rz;
    rx.SetIdentity();
    rz.SetIdentity();
    rx(1, 1) = std::cos(a), rx(1, 2) = -std::sin(a), rx(2, 1) = std::sin(a), rx(2, 2) = std::cos(a);
    rz(0, 0) = std::cos(b), rz(0, 1) = -std::sin(b), rz(1, 0) = std::sin(b), rz(1, 1) = std::cos(b);
    d = rx * rz;
  }
  if (spec.reverse_slices)
    for (int r = 0; r < 3; ++r) d(r, 2) = -d(r, 2);
  return d;
}

// An empty image whose grid is centred on the patient origin.
CtImage::Pointer make_grid(const PhantomSpec& spec) {
  CtImage::SizeType size;
  CtImage::SpacingType spacing;
  for (int i = 0; i < 3; ++i) {
    size[i] = std::max<itk::SizeValueType>(
        1, static_cast<itk::SizeValueType>(std::lround(spec.fov_mm[i] / spec.spacing_mm)));
    spacing[i] = spec.spacing_mm;
  }
  const auto d = direction_of(spec);
  CtImage::PointType origin;
  for (int r = 0; r < 3; ++r) {
    origin[r] = 0;
    for (int c = 0; c < 3; ++c) origin[r] -= d(r, c) * 0.5 * (size[c] - 1) * spacing[c];
  }
  auto image = CtImage::New();
  image->SetRegions(CtImage::RegionType(size));
  image->SetSpacing(spacing);
  image->SetOrigin(origin);
  image->SetDirection(d);
  image->Allocate();
  return image;
}

// Mean HU over one voxel: the centre value when the centre and all eight corners agree
// (no border inside), else the mean of 4x4x4 sub-samples (partial-volume effect).
double voxel_value(const Anatomy& anatomy, const CtImage& image, const itk::Index<3>& index) {
  const auto& d = image.GetDirection();
  const auto& s = image.GetSpacing();
  CtImage::PointType centre;
  image.TransformIndexToPhysicalPoint(index, centre);
  auto at = [&](double u, double v, double w) {  // offsets in voxels along the grid axes
    double p[3];
    for (int r = 0; r < 3; ++r)
      p[r] = centre[r] + d(r, 0) * u * s[0] + d(r, 1) * v * s[1] + d(r, 2) * w * s[2];
    return anatomy.hu(p[0], p[1], p[2]);
  };
  const double c = at(0, 0, 0);
  bool uniform = true;
  for (int k = 0; k < 8 && uniform; ++k)
    uniform = at(k & 1 ? 0.5 : -0.5, k & 2 ? 0.5 : -0.5, k & 4 ? 0.5 : -0.5) == c;
  if (uniform) return c;
  constexpr int n = 4;
  double sum = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        sum += at((i + 0.5) / n - 0.5, (j + 0.5) / n - 0.5, (k + 0.5) / n - 0.5);
  return sum / (n * n * n);
}

}  // namespace

PhantomTruth phantom_truth(const PhantomSpec& spec) {
  PhantomTruth t;
  t.bladder_volume_ml = spec.bladder_ml;
  t.bladder_center_mm = {0.0, -15.0, -10.0};
  const double product = 3.0 * spec.bladder_ml * 1000.0 / (4.0 * kPi);  // a*b*c in mm^3
  if (spec.shape == PhantomShape::Sphere) {
    const double r = std::cbrt(product);
    t.bladder_semi_axes_mm = {r, r, r};
  } else {
    const double k =
        std::cbrt(product / (kEllipsoidRatios[0] * kEllipsoidRatios[1] * kEllipsoidRatios[2]));
    t.bladder_semi_axes_mm = {k * kEllipsoidRatios[0], k * kEllipsoidRatios[1],
                              k * kEllipsoidRatios[2]};
  }
  return t;
}

CtImage::Pointer make_phantom(const PhantomSpec& spec) {
  const Anatomy anatomy = anatomy_of(spec);
  auto image = make_grid(spec);
  const auto size = image->GetLargestPossibleRegion().GetSize();
  float* buffer = image->GetBufferPointer();
  const std::size_t slice = size[0] * size[1];
  const unsigned workers = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> threads;
  for (unsigned w = 0; w < workers; ++w)
    threads.emplace_back([&, w] {
      for (itk::IndexValueType k = w; k < static_cast<itk::IndexValueType>(size[2]); k += workers)
        for (itk::IndexValueType j = 0; j < static_cast<itk::IndexValueType>(size[1]); ++j)
          for (itk::IndexValueType i = 0; i < static_cast<itk::IndexValueType>(size[0]); ++i)
            buffer[k * slice + j * size[0] + i] =
                static_cast<float>(voxel_value(anatomy, *image, {{i, j, k}}));
    });
  for (auto& t : threads) t.join();
  if (spec.noise_hu > 0) {
    std::mt19937 rng(spec.rng_seed);
    std::normal_distribution<float> noise(0.0f, static_cast<float>(spec.noise_hu));
    const std::size_t n = slice * size[2];
    for (std::size_t v = 0; v < n; ++v) buffer[v] += noise(rng);
  }
  return image;
}

LabelImage::Pointer phantom_bladder_mask(const PhantomSpec& spec, const CtImage& like) {
  const Anatomy anatomy = anatomy_of(spec);
  auto mask = LabelImage::New();
  mask->CopyInformation(&like);
  mask->SetRegions(like.GetLargestPossibleRegion());
  mask->Allocate();
  itk::ImageRegionIteratorWithIndex<LabelImage> it(mask, mask->GetLargestPossibleRegion());
  for (; !it.IsAtEnd(); ++it) {
    LabelImage::PointType p;
    mask->TransformIndexToPhysicalPoint(it.GetIndex(), p);
    it.Set(anatomy.hu(p[0], p[1], p[2]) == PhantomTissues::kUrine ? 1 : 0);
  }
  return mask;
}

}  // namespace vesica::segment
