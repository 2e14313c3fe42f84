#pragma once
// A synthetic pelvic CT with a urine-filled bladder of exactly known volume. The anatomy
// is analytic (ellipses and ellipsoids in patient millimetres, LPS), so the bladder
// volume and centre are exact and independent of the voxel grid; the grid may be axial
// or oblique and its slices stored in either order.
#include <array>
#include <cstdint>
#include <string>

#include "vesica/segment/ImageTypes.h"

namespace vesica::segment {

enum class PhantomShape { Sphere, Ellipsoid };
enum class PhantomOrientation { Axial, Oblique };

struct PhantomSpec {
  double bladder_ml = 300.0;
  double spacing_mm = 2.0;                         // isotropic voxel edge
  std::array<double, 3> fov_mm = {400, 400, 240};  // grid extent (L-R, A-P, I-S)
  PhantomShape shape = PhantomShape::Sphere;
  PhantomOrientation orientation = PhantomOrientation::Axial;
  bool reverse_slices = false;  // slice axis points feet-ward (instance 1 at the top)
  double noise_hu = 15.0;
  std::uint32_t rng_seed = 1;
};

// Tissue values (HU) of the phantom; the segmenter's defaults do not read these.
struct PhantomTissues {
  static constexpr double kAir = -1000, kFat = -100, kUrine = 10, kMuscle = 50, kBone = 700;
};

struct PhantomTruth {
  double bladder_volume_ml = 0;               // exact analytic volume
  std::array<double, 3> bladder_center_mm{};  // LPS
  std::array<double, 3> bladder_semi_axes_mm{};
};

PhantomTruth phantom_truth(const PhantomSpec& spec);

// The phantom image in HU with partial-volume averaging at tissue borders and Gaussian
// noise. Geometry (origin, spacing, direction) follows spec.
CtImage::Pointer make_phantom(const PhantomSpec& spec);

// 1 inside the analytic bladder (voxel centre test) on the grid of `like`.
LabelImage::Pointer phantom_bladder_mask(const PhantomSpec& spec, const CtImage& like);

}  // namespace vesica::segment
