#pragma once
// What a synthetic pelvis (Phantom.h) is made of: modality, bladder volume and shape, the
// voxel grid (lengths in mm, patient LPS), noise and the MR acquisition. Standard headers
// only, so that vesica-phantom's parameter table (vesica/phantom/PhantomParameters.h),
// which the runner links, can bind to it and size the grid without ITK.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "vesica/segment/BladderShape.h"
#include "vesica/segment/Modality.h"
#include "vesica/segment/PhantomContrast.h"

namespace vesica::segment {

enum class PhantomOrientation { Axial, Oblique };

struct PhantomSpec {
  Modality modality = Modality::CT;
  double bladder_ml = 300.0;
  PhantomShape shape = PhantomShape::Sphere;
  double elongation = 1.0;        // pouch: left-right length ratio (as vesica-surface)
  double neck_radius_mm = 0.0;    // pouch: 0 = a quarter of the reservoir
  double spacing_mm = 2.0;        // in-plane voxel edge
  double slice_spacing_mm = 0.0;  // 0 = spacing_mm (isotropic voxels)
  std::array<double, 3> fov_mm = {400, 400, 240};  // grid extent (L-R, A-P, I-S)
  PhantomOrientation orientation = PhantomOrientation::Axial;
  bool reverse_slices = false;  // slice axis points feet-ward (instance 1 at the top)
  double noise_hu = 15.0;       // CT: Gaussian noise standard deviation
  MrAcquisition mr;             // MR: contrast, bias field, noise
  std::uint32_t rng_seed = 1;
};

// Voxel edges along the grid's axes (the third is the slice axis), mm.
inline std::array<double, 3> phantom_spacing_mm(const PhantomSpec& spec) {
  const double slice = spec.slice_spacing_mm > 0 ? spec.slice_spacing_mm : spec.spacing_mm;
  return {spec.spacing_mm, spec.spacing_mm, slice};
}

// Voxels along each axis: the field of view over the spacing, rounded, at least one.
inline std::array<double, 3> phantom_grid_size(const PhantomSpec& spec) {
  const std::array<double, 3> spacing = phantom_spacing_mm(spec);
  std::array<double, 3> size{};
  for (int i = 0; i < 3; ++i) size[i] = std::max(1.0, std::round(spec.fov_mm[i] / spacing[i]));
  return size;
}

inline double phantom_voxel_count(const PhantomSpec& spec) {
  const std::array<double, 3> n = phantom_grid_size(spec);
  return n[0] * n[1] * n[2];
}

}  // namespace vesica::segment
