// Round trips through every surface format keep vertex count, connectivity, volume and
// region tags. "Exactly" means what the format stores as read back through its reader:
//  - VTP stores doubles: coordinates come back bit for bit;
//  - binary STL and PLY store float32: coordinates come back as the float rounding of the
//    written doubles, bit for bit;
//  - ASCII STL and OBJ are written with all 17 digits, but assimp parses text into float32
//    with its own (not correctly rounded) parser: coordinates within 2 float ulps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "SurfaceTestSupport.h"
#include "TestData.h"
#include "vesica/core/Regions.h"
#include "vesica/surface/Shapes.h"
#include "vesica/surface/SurfaceIO.h"
#include "vesica/surface/SurfaceRegions.h"

namespace vesica::test {
namespace {

using surface::TriangleSurface;

TriangleSurface tagged_ellipsoid() {
  surface::ShapeSpec spec;
  spec.kind = surface::ShapeKind::Ellipsoid;
  spec.volume_ml = 250;
  spec.elongation = 1.4;
  spec.edge_mm = 6;
  spec.center_mm = Eigen::Vector3d(-12.3, 145.6, 88.9);  // patient coordinates, far from 0
  TriangleSurface s = surface::make_shape(spec);
  surface::RegionOptions regions;
  regions.fixed_radius_mm = 25;
  regions.support_below_mm = 30;
  surface::assign_regions(regions, s);
  return s;
}

enum class Stored { Doubles, Floats, FloatText };

Eigen::MatrixXd stored_coordinates(const Eigen::MatrixXd& V, Stored stored) {
  return stored == Stored::Doubles ? V : Eigen::MatrixXd(V.cast<float>().cast<double>());
}

// For each read vertex, the written vertex nearest to it (readers renumber vertices).
std::vector<int> match_vertices(const Eigen::MatrixXd& read, const Eigen::MatrixXd& written,
                                double* worst_distance) {
  std::vector<int> match(read.rows());
  *worst_distance = 0;
  for (Eigen::Index v = 0; v < read.rows(); ++v) {
    Eigen::Index best = 0;
    const double d2 = (written.rowwise() - read.row(v)).rowwise().squaredNorm().minCoeff(&best);
    match[v] = static_cast<int>(best);
    *worst_distance = std::max(*worst_distance, std::sqrt(d2));
  }
  return match;
}

// Triangle f of `a` (through the vertex match) equals triangle f of `b` up to rotation.
bool same_triangle(const Eigen::RowVector3i& a, const Eigen::RowVector3i& b) {
  for (int r = 0; r < 3; ++r)
    if (a(r) == b(0) && a((r + 1) % 3) == b(1) && a((r + 2) % 3) == b(2)) return true;
  return false;
}

class RoundTrip : public ::testing::TestWithParam<std::tuple<const char*, bool, Stored>> {};

TEST_P(RoundTrip, KeepsCountsConnectivityVolumeAndTags) {
  const auto [extension, ascii, stored] = GetParam();
  const TriangleSurface original = tagged_ellipsoid();
  // A folder per instance: ctest runs the instances side by side, and scratch_dir empties
  // the folder it is given.
  std::string instance = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::replace(instance.begin(), instance.end(), '/', '-');
  const auto path = scratch_dir("surface-roundtrip-" + instance) / (std::string("s") + extension);
  surface::WriteOptions options;
  options.stl_ascii = ascii;
  surface::write_surface(original, path, options);
  const TriangleSurface back = surface::read_surface(path);

  ASSERT_EQ(back.V.rows(), original.V.rows());
  ASSERT_EQ(back.F.rows(), original.F.rows());
  const Eigen::MatrixXd expected = stored_coordinates(original.V, stored);
  double worst = 0;
  const std::vector<int> match = match_vertices(back.V, expected, &worst);
  const double float_ulp = std::numeric_limits<float>::epsilon() * original.V.cwiseAbs().maxCoeff();
  EXPECT_LE(worst, stored == Stored::FloatText ? 2 * float_ulp : 0.0);
  std::vector<int> sorted = match;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_TRUE(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end())
      << "two read vertices match one written vertex";
  int different = 0;
  for (Eigen::Index f = 0; f < back.F.rows(); ++f) {
    const Eigen::RowVector3i mapped(match[back.F(f, 0)], match[back.F(f, 1)], match[back.F(f, 2)]);
    different += !same_triangle(mapped, original.F.row(f));
  }
  EXPECT_EQ(different, 0) << "triangles whose corners or winding changed";
  const double volume = surface::enclosed_volume(expected, original.F);
  EXPECT_NEAR(surface::enclosed_volume(back.V, back.F) / volume, 1.0,
              stored == Stored::FloatText ? 1e-6 : 1e-12);
  EXPECT_TRUE(back.region == original.region) << "region tags changed";
  if (stored == Stored::Doubles) {
    EXPECT_EQ(vtp_region_array_class(path.string()), "vtkIntArray/32");
    EXPECT_EQ(vtp_units(path.string()), "mm");
  } else {
    EXPECT_TRUE(std::filesystem::exists(surface::regions_sidecar_path(path)));
  }
}

INSTANTIATE_TEST_SUITE_P(SurfaceFormats, RoundTrip,
                         ::testing::Values(std::make_tuple(".vtp", false, Stored::Doubles),
                                           std::make_tuple(".stl", false, Stored::Floats),
                                           std::make_tuple(".stl", true, Stored::FloatText),
                                           std::make_tuple(".ply", false, Stored::Floats),
                                           std::make_tuple(".obj", false, Stored::FloatText)),
                         [](const auto& info) {
                           std::string name = std::get<0>(info.param) + 1;
                           return name + (std::get<1>(info.param) ? "_ascii" : "");
                         });

// An outside edit (here: one triangle deleted, as in MeshLab) keeps the other tags.
TEST(SurfaceFormats, EditedSurfaceKeepsTagsByNearestTriangle) {
  const TriangleSurface original = tagged_ellipsoid();
  const auto dir = scratch_dir("surface-edited");
  surface::write_surface(original, dir / "s.ply");
  TriangleSurface edited = original;
  edited.F = original.F.bottomRows(original.F.rows() - 1);
  edited.region = original.region.tail(original.region.size() - 1);
  surface::write_surface(edited, dir / "edited.ply");
  std::filesystem::copy_file(surface::regions_sidecar_path(dir / "s.ply"),
                             surface::regions_sidecar_path(dir / "edited.ply"),
                             std::filesystem::copy_options::overwrite_existing);
  const TriangleSurface back = surface::read_surface(dir / "edited.ply");
  ASSERT_EQ(back.F.rows(), edited.F.rows());
  EXPECT_TRUE(back.region == edited.region);
}

}  // namespace
}  // namespace vesica::test
