// Acceptance of the label -> surface path against independent truths: analytic sphere and
// ellipsoid voxelised through ITK on an oblique grid, and the real CT label's voxel
// boundary measured with ITK.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "LabelImages.h"
#include "SurfaceTestSupport.h"
#include "TestData.h"
#include "vesica/surface/SurfaceStage.h"

namespace vesica::test {
namespace {

// Area of the ellipsoid x = (a sin t cos p, b sin t sin p, c cos t) by midpoint quadrature.
double ellipsoid_area(const Eigen::Vector3d& s) {
  const int nt = 1500, np = 3000;
  double area = 0;
  for (int i = 0; i < nt; ++i) {
    const double t = M_PI * (i + 0.5) / nt, st = std::sin(t), ct = std::cos(t);
    for (int j = 0; j < np; ++j) {
      const double p = 2 * M_PI * (j + 0.5) / np, cp = std::cos(p), sp = std::sin(p);
      area +=
          st * std::sqrt(std::pow(s.y() * s.z() * st * cp, 2) +
                         std::pow(s.x() * s.z() * st * sp, 2) + std::pow(s.x() * s.y() * ct, 2));
    }
  }
  return area * (M_PI / nt) * (2 * M_PI / np);
}

struct Case {
  const char* name;
  Eigen::Vector3d semi_axes;
  double spacing_mm;
  double edge_mm;
  bool mirrored = false;  // a left-handed grid (det direction = -1), as some NIfTI files are
};

// An oblique grid (rotated 25 degrees about a tilted axis) with the shape's centre off the
// voxel lattice, far from the origin, as a CT's bladder is.
GridSpec oblique_grid(const Case& c, const Eigen::Vector3d& center) {
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(25.0 * M_PI / 180, Eigen::Vector3d(1, 2, 3).normalized())
          .toRotationMatrix();
  const int n =
      static_cast<int>(std::ceil((2 * c.semi_axes.maxCoeff() + 6 * c.spacing_mm) / c.spacing_mm));
  const Eigen::Vector3d half = Eigen::Vector3d::Constant(0.5 * (n - 1) * c.spacing_mm);
  const Eigen::Vector3d origin =
      center - R * (half + Eigen::Vector3d(0.31, -0.17, 0.23) * c.spacing_mm);
  GridSpec grid;
  grid.size = {n, n, n};
  grid.spacing = {c.spacing_mm, c.spacing_mm, c.spacing_mm};
  grid.origin = {origin.x(), origin.y(), origin.z()};
  const Eigen::Matrix3d D =
      c.mirrored ? Eigen::Matrix3d(R * Eigen::Vector3d(1, 1, -1).asDiagonal()) : R;
  const Eigen::Vector3d o = center - D * (half + Eigen::Vector3d(0.31, -0.17, 0.23) * c.spacing_mm);
  grid.origin = {o.x(), o.y(), o.z()};
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) grid.direction[3 * r + k] = D(r, k);
  return grid;
}

class AnalyticLabel : public ::testing::TestWithParam<Case> {};

TEST_P(AnalyticLabel, VolumeAreaAnglesAndPlacement) {
  const Case c = GetParam();
  const auto dir = scratch_dir(std::string("surface-analytic-") + c.name);
  const Eigen::Vector3d center(-23.4, 148.2, 91.7);
  write_ellipsoid_label((dir / "label.nii.gz").string(), oblique_grid(c, center),
                        {center.x(), center.y(), center.z()},
                        {c.semi_axes.x(), c.semi_axes.y(), c.semi_axes.z()});
  surface::SurfaceStageOptions options;
  options.input = (dir / "label.nii.gz").string();
  options.output = (dir / "surface.vtp").string();
  options.edge_mm = c.edge_mm;
  const surface::TriangleSurface s = run_stage(options);

  const double volume = 4.0 / 3.0 * M_PI * c.semi_axes.prod();
  const double area = ellipsoid_area(c.semi_axes);
  const Eigen::VectorXd angles = surface::triangle_min_angles_deg(s.V, s.F);
  std::cout << c.name << ": volume/analytic " << surface::enclosed_volume(s.V, s.F) / volume
            << ", area/analytic " << surface::surface_area(s.V, s.F) / area
            << ", fraction min angle >= 25 deg " << (angles.array() >= 25.0).cast<double>().mean()
            << ", triangles " << s.F.rows() << "\n";
  EXPECT_NEAR(surface::enclosed_volume(s.V, s.F) / volume, 1.0, 0.01);
  EXPECT_NEAR(surface::surface_area(s.V, s.F) / area, 1.0, 0.03);
  EXPECT_GE((angles.array() >= 25.0).cast<double>().mean(), 0.99);
  // LPS placement through origin, spacing and direction cosines: the surface lies on the
  // analytic ellipsoid (axis-aligned in patient space) within a voxel.
  EXPECT_LT((surface::volume_centroid(s.V, s.F) - center).norm(), 0.1 * c.spacing_mm);
  for (Eigen::Index v = 0; v < s.V.rows(); ++v) {
    const double rho = (s.V.row(v).transpose() - center).cwiseQuotient(c.semi_axes).norm();
    ASSERT_LT(std::abs(rho - 1.0) * c.semi_axes.minCoeff(), c.spacing_mm) << "vertex " << v;
  }
}

INSTANTIATE_TEST_SUITE_P(
    SurfaceAcceptance, AnalyticLabel,
    ::testing::Values(Case{"sphere_1mm", {30, 30, 30}, 1.0, 2.5},
                      Case{"ellipsoid_1mm", {38, 28, 22}, 1.0, 2.5},
                      Case{"sphere_3mm", {45, 45, 45}, 3.0, 4.0},
                      Case{"ellipsoid_3mm", {55, 40, 32}, 3.0, 4.0},
                      Case{"ellipsoid_3mm_mirrored", {55, 40, 32}, 3.0, 4.0, true}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(RealLabel, VolumeHausdorffClosedManifold) {
  VESICA_REQUIRE_SHARED(label, "data/ct/abdomen-3mm/bladder-reference.nii.gz");
  const auto dir = scratch_dir("surface-real-label");
  surface::SurfaceStageOptions options;
  options.input = label.string();
  options.output = (dir / "bladder.vtp").string();
  nlohmann::json summary;
  const surface::TriangleSurface s = run_stage(options, &summary);

  const LabelBoundary boundary = label_boundary(label.string());
  ASSERT_EQ(boundary.inside_voxels, 17744);  // the reference label, counted by ITK
  const double voxel_volume = boundary.inside_voxels * boundary.voxel_volume_mm3;
  EXPECT_NEAR(surface::enclosed_volume(s.V, s.F) / voxel_volume, 1.0, 0.03);
  // The smoothing itself keeps the volume (before the final rescale to the voxel volume).
  const double smoothed_mm3 = summary["smoothed_volume_ml"].get<double>() * 1e3;
  std::cout << "smoothed volume / voxel volume " << smoothed_mm3 / voxel_volume << "\n";
  EXPECT_NEAR(smoothed_mm3 / voxel_volume, 1.0, 0.03);
  EXPECT_TRUE(summary["checks"]["closed"].get<bool>());
  EXPECT_TRUE(summary["checks"]["manifold"].get<bool>());
  EXPECT_FALSE(summary["checks"]["self_intersections"].get<bool>());

  // The voxel boundary as triangles (two per face) and as face centres.
  Eigen::MatrixXd QV(4 * boundary.quads.size(), 3);
  Eigen::MatrixXi QF(2 * boundary.quads.size(), 3);
  Eigen::MatrixXd centres(boundary.face_centres.size(), 3);
  for (std::size_t q = 0; q < boundary.quads.size(); ++q) {
    for (int c = 0; c < 4; ++c)
      QV.row(4 * q + c) << boundary.quads[q][c][0], boundary.quads[q][c][1],
          boundary.quads[q][c][2];
    const int b = static_cast<int>(4 * q);
    QF.row(2 * q) << b, b + 1, b + 2;
    QF.row(2 * q + 1) << b, b + 2, b + 3;
    centres.row(q) << boundary.face_centres[q][0], boundary.face_centres[q][1],
        boundary.face_centres[q][2];
  }
  const double surface_to_label = max_distance_to_triangles(surface_samples(s), QV, QF);
  const double label_to_surface = max_distance_to_triangles(centres, s.V, s.F);
  // Reported only: voxel corners are not on the label boundary a smooth surface can follow.
  std::cout << "voxel face corners->surface " << max_distance_to_triangles(QV, s.V, s.F) << " mm\n";
  RecordProperty("hausdorff_surface_to_label_mm", std::to_string(surface_to_label));
  RecordProperty("hausdorff_label_to_surface_mm", std::to_string(label_to_surface));
  std::cout << "Hausdorff surface->voxel boundary " << surface_to_label
            << " mm, voxel face centres->surface " << label_to_surface << " mm\n";
  EXPECT_LE(std::max(surface_to_label, label_to_surface), 3.0);
}

}  // namespace
}  // namespace vesica::test
