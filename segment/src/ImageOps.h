#pragma once
// Small image operations the segmentation steps share, each a thin wrapper around one
// ITK filter with radii in millimetres (so that parameters do not depend on the grid).
#include <optional>

#include "vesica/segment/ImageTypes.h"

namespace vesica::segment::ops {

using Float = ScanImage;
using Mask = LabelImage;
using Index = Float::IndexType;
using LabelMap = itk::Image<unsigned int, 3>;

double voxel_ml(const itk::ImageBase<3>& image);
std::size_t count(const Mask& m);
Mask::Pointer erode(const Mask& m, double radius_mm);
Mask::Pointer dilate(const Mask& m, double radius_mm);
Mask::Pointer threshold(const Float& image, double lower, double upper);
Mask::Pointer component_at(const Mask& m, const Index& seed);  // flood fill from seed
Mask::Pointer largest_component(const Mask& m);
Mask::Pointer fill_holes(const Mask& m);
// Cube of half edge radius_mm around centre, clipped to the image.
Float::RegionType region_around(const Float& image, const Float::PointType& centre,
                                double radius_mm);
// The index region of `image` covering the mask's voxels grown by margin_mm (mask and
// image may have different grids), clipped to the image.
Float::RegionType region_covering(const Float& image, const Mask& mask, double margin_mm);
Float::Pointer crop_region(const Float& image, const Float::RegionType& region);
Float::Pointer gaussian(const Float& image, double sigma_mm);
// Same physical box on an isotropic grid (linear interpolation); `outside` beyond the
// image (air: -1000 HU on CT, 0 on MR).
Float::Pointer resample_isotropic(const Float& image, double spacing, double outside);
Float::Pointer anisotropic_diffusion(const Float& image, int iterations, double conductance);
// The index box of half edge radius_mm around `seed`, clipped to the image; empty when
// none of it lies inside.
std::optional<Float::RegionType> box_within(const itk::ImageBase<3>& image, const Index& seed,
                                            double radius_mm);
// The mask voxel nearest to `seed` within radius_mm, if any.
std::optional<Index> nearest_inside(const Mask& m, const Index& seed, double radius_mm);
Float::Pointer signed_distance(const Mask& m);  // mm, negative inside
// The value below which `percent` of the image's values where `where` is set lie (the
// element at rank floor(percent/100 * n)); NaN when empty.
double percentile_where(const Float& image, const Mask& where, double percent);
double median_where(const Float& image, const Mask& where);  // percentile 50

}  // namespace vesica::segment::ops
