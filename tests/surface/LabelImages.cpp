#include "LabelImages.h"

#include <itkImage.h>
#include <itkImageFileReader.h>
#include <itkImageFileWriter.h>
#include <itkImageRegionIteratorWithIndex.h>

namespace vesica::test {

using Image = itk::Image<unsigned char, 3>;

long write_ellipsoid_label(const std::string& path, const GridSpec& grid, const Vec3& center,
                           const Vec3& semi_axes) {
  auto image = Image::New();
  Image::RegionType region;
  Image::SizeType size;
  for (int d = 0; d < 3; ++d) size[d] = grid.size[d];
  region.SetSize(size);
  image->SetRegions(region);
  Image::SpacingType spacing;
  Image::PointType origin;
  Image::DirectionType direction;
  for (int d = 0; d < 3; ++d) {
    spacing[d] = grid.spacing[d];
    origin[d] = grid.origin[d];
    for (int e = 0; e < 3; ++e) direction(d, e) = grid.direction[3 * d + e];
  }
  image->SetSpacing(spacing);
  image->SetOrigin(origin);
  image->SetDirection(direction);
  image->Allocate();
  long inside = 0;
  for (itk::ImageRegionIteratorWithIndex<Image> it(image, region); !it.IsAtEnd(); ++it) {
    Image::PointType p;
    image->TransformIndexToPhysicalPoint(it.GetIndex(), p);
    double r2 = 0;
    for (int d = 0; d < 3; ++d) r2 += std::pow((p[d] - center[d]) / semi_axes[d], 2);
    it.Set(r2 <= 1.0 ? 1 : 0);
    inside += r2 <= 1.0;
  }
  auto writer = itk::ImageFileWriter<Image>::New();
  writer->SetInput(image);
  writer->SetFileName(path);
  writer->Update();
  return inside;
}

LabelBoundary label_boundary(const std::string& path) {
  auto reader = itk::ImageFileReader<Image>::New();
  reader->SetFileName(path);
  reader->Update();
  const Image* image = reader->GetOutput();
  const auto region = image->GetLargestPossibleRegion();
  LabelBoundary out;
  out.voxel_volume_mm3 = image->GetSpacing()[0] * image->GetSpacing()[1] * image->GetSpacing()[2];
  auto physical = [&](double i, double j, double k) {
    itk::ContinuousIndex<double, 3> index;
    index[0] = i, index[1] = j, index[2] = k;
    Image::PointType p;
    image->TransformContinuousIndexToPhysicalPoint(index, p);
    return Vec3{p[0], p[1], p[2]};
  };
  auto inside = [&](Image::IndexType index) {
    return region.IsInside(index) && image->GetPixel(index) != 0;
  };
  for (itk::ImageRegionConstIteratorWithIndex<Image> it(image, region); !it.IsAtEnd(); ++it) {
    if (it.Get() == 0) continue;
    ++out.inside_voxels;
    const auto idx = it.GetIndex();
    for (int axis = 0; axis < 3; ++axis)
      for (int side : {-1, 1}) {
        auto neighbour = idx;
        neighbour[axis] += side;
        if (inside(neighbour)) continue;
        // Face at index + side/2 along `axis`, spanning +-1/2 along the other two axes.
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        std::array<Vec3, 4> quad;
        const double du[4] = {-0.5, 0.5, 0.5, -0.5}, dv[4] = {-0.5, -0.5, 0.5, 0.5};
        for (int c = 0; c < 4; ++c) {
          double q[3] = {double(idx[0]), double(idx[1]), double(idx[2])};
          q[axis] += 0.5 * side;
          q[u] += du[c];
          q[v] += dv[c];
          quad[c] = physical(q[0], q[1], q[2]);
        }
        double q[3] = {double(idx[0]), double(idx[1]), double(idx[2])};
        q[axis] += 0.5 * side;
        out.face_centres.push_back(physical(q[0], q[1], q[2]));
        out.quads.push_back(quad);
      }
  }
  return out;
}

}  // namespace vesica::test
