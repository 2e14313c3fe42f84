// Bad inputs through the executable: one-line error naming the file and the problem,
// exit 1, nothing written; repairable inputs are repaired with a note.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <sys/wait.h>
#include <nlohmann/json.hpp>

#include "LabelImages.h"
#include "TestData.h"
#include "vesica/surface/Shapes.h"
#include "vesica/surface/SurfaceIO.h"

namespace vesica::test {
namespace {

namespace fs = std::filesystem;
using surface::TriangleSurface;

struct ToolRun {
  int exit_code = -1;
  std::string stderr_text;
};

ToolRun run_surface(const std::string& arguments, const fs::path& dir) {
  const fs::path err = dir / "stderr.txt";
  const std::string command =
      (bin_dir() / "vesica-surface").string() + " " + arguments + " 2> " + err.string();
  const int status = std::system(command.c_str());
  std::ifstream in(err);
  std::stringstream text;
  text << in.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

int line_count(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

TriangleSurface sphere() {
  surface::ShapeSpec spec;
  spec.volume_ml = 150;
  spec.edge_mm = 8;
  return surface::make_shape(spec);
}

TriangleSurface without_triangles(const TriangleSurface& s, const std::vector<int>& drop) {
  TriangleSurface out = s;
  out.F.resize(s.F.rows() - static_cast<Eigen::Index>(drop.size()), 3);
  Eigen::Index n = 0;
  for (Eigen::Index f = 0; f < s.F.rows(); ++f)
    if (std::find(drop.begin(), drop.end(), f) == drop.end()) out.F.row(n++) = s.F.row(f);
  out.region.resize(0);
  return out;
}

// Two triangles far apart: two holes of three boundary edges each.
int far_triangle(const TriangleSurface& s) {
  Eigen::Index far = 0;
  (s.V.rowwise() - s.V.row(s.F(0, 0))).rowwise().squaredNorm().maxCoeff(&far);
  for (Eigen::Index f = 0; f < s.F.rows(); ++f)
    if (s.F(f, 0) == far || s.F(f, 1) == far || s.F(f, 2) == far) return static_cast<int>(f);
  return 1;
}

TEST(SurfaceBadInput, EmptyLabelFailsWithOneLine) {
  const auto dir = scratch_dir("surface-bad-empty");
  GridSpec grid;
  grid.size = {20, 20, 20};
  ASSERT_EQ(
      write_ellipsoid_label((dir / "empty.nii.gz").string(), grid, {500, 500, 500}, {5, 5, 5}), 0);
  const ToolRun run =
      run_surface((dir / "empty.nii.gz").string() + " -o " + (dir / "out.vtp").string(), dir);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(line_count(run.stderr_text), 1) << run.stderr_text;
  EXPECT_NE(run.stderr_text.find("empty.nii.gz"), std::string::npos) << run.stderr_text;
  EXPECT_NE(run.stderr_text.find("empty"), std::string::npos) << run.stderr_text;
  EXPECT_FALSE(fs::exists(dir / "out.vtp"));
}

TEST(SurfaceBadInput, OpenStlReportsHolesAndBoundaryEdges) {
  const auto dir = scratch_dir("surface-bad-open");
  const TriangleSurface s = sphere();
  surface::write_surface(without_triangles(s, {0, far_triangle(s)}), dir / "open.stl");
  const ToolRun run =
      run_surface((dir / "open.stl").string() + " -o " + (dir / "out.vtp").string(), dir);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(line_count(run.stderr_text), 1) << run.stderr_text;
  EXPECT_NE(run.stderr_text.find("open.stl"), std::string::npos) << run.stderr_text;
  EXPECT_NE(run.stderr_text.find("6 boundary edges in 2 hole(s)"), std::string::npos)
      << run.stderr_text;
  EXPECT_FALSE(fs::exists(dir / "out.vtp"));
}

TEST(SurfaceBadInput, SmallHolesAreFilledOnRequest) {
  const auto dir = scratch_dir("surface-bad-fill");
  const TriangleSurface s = sphere();
  surface::write_surface(without_triangles(s, {0}), dir / "open.stl");
  const ToolRun run =
      run_surface((dir / "open.stl").string() + " --fill-holes -o " + (dir / "out.vtp").string() +
                      " --report " + (dir / "r.json").string(),
                  dir);
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  std::ifstream in(dir / "r.json");
  const auto summary = nlohmann::json::parse(in);
  EXPECT_TRUE(summary["checks"]["closed"].get<bool>());
  EXPECT_NE(summary["notes"].dump().find("filled 1 hole"), std::string::npos) << summary["notes"];
}

TEST(SurfaceBadInput, NonManifoldStlReportsNonManifoldEdges) {
  const auto dir = scratch_dir("surface-bad-nonmanifold");
  TriangleSurface s = sphere();
  // A fin: a third triangle on the edge of triangle 0, pointing outward.
  const Eigen::RowVector3d fin = s.V.row(s.F(0, 0)) * 1.5;
  s.V.conservativeResize(s.V.rows() + 1, 3);
  s.V.row(s.V.rows() - 1) = fin;
  s.F.conservativeResize(s.F.rows() + 1, 3);
  s.F.row(s.F.rows() - 1) << s.F(0, 0), s.F(0, 1), static_cast<int>(s.V.rows() - 1);
  s.region.resize(0);
  surface::write_surface(s, dir / "fin.stl");
  const ToolRun run =
      run_surface((dir / "fin.stl").string() + " -o " + (dir / "out.vtp").string(), dir);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(line_count(run.stderr_text), 1) << run.stderr_text;
  EXPECT_NE(run.stderr_text.find("1 non-manifold edges, 2 boundary edges"), std::string::npos)
      << run.stderr_text;
  EXPECT_FALSE(fs::exists(dir / "out.vtp"));
}

TEST(SurfaceBadInput, InvertedNormalsAreFixedWithANote) {
  const auto dir = scratch_dir("surface-bad-inverted");
  TriangleSurface s = sphere();
  const double volume = surface::enclosed_volume(s.V, s.F);
  s.F.col(1).swap(s.F.col(2));
  s.region.resize(0);
  ASSERT_LT(surface::enclosed_volume(s.V, s.F), 0);
  surface::write_surface(s, dir / "inverted.stl");
  const ToolRun run =
      run_surface((dir / "inverted.stl").string() + " -o " + (dir / "out.vtp").string() +
                      " --report " + (dir / "r.json").string(),
                  dir);
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  std::ifstream in(dir / "r.json");
  const auto summary = nlohmann::json::parse(in);
  EXPECT_NE(summary["notes"].dump().find("inward"), std::string::npos) << summary["notes"];
  EXPECT_EQ(summary["checks"]["orientation"], "outward");
  const TriangleSurface fixed = surface::read_surface(dir / "out.vtp");
  EXPECT_NEAR(surface::enclosed_volume(fixed.V, fixed.F) / volume, 1.0, 1e-6);
}

TEST(SurfaceBadInput, ExtraComponentsAreRemovedWithANote) {
  const auto dir = scratch_dir("surface-bad-components");
  const TriangleSurface big = sphere();
  surface::ShapeSpec small_spec;
  small_spec.volume_ml = 10;
  small_spec.edge_mm = 4;
  small_spec.center_mm = Eigen::Vector3d(120, 0, 0);
  const TriangleSurface small = surface::make_shape(small_spec);
  TriangleSurface both;
  both.V.resize(big.V.rows() + small.V.rows(), 3);
  both.V << big.V, small.V;
  both.F.resize(big.F.rows() + small.F.rows(), 3);
  both.F << big.F, (small.F.array() + static_cast<int>(big.V.rows())).matrix();
  surface::write_surface(both, dir / "two.ply");
  const ToolRun run = run_surface((dir / "two.ply").string() + " -o " + (dir / "out.vtp").string() +
                                      " --report " + (dir / "r.json").string(),
                                  dir);
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  std::ifstream in(dir / "r.json");
  const auto summary = nlohmann::json::parse(in);
  EXPECT_EQ(summary["checks"]["components"], 1);
  EXPECT_NE(summary["notes"].dump().find("removed 1 component"), std::string::npos)
      << summary["notes"];
  EXPECT_NEAR(summary["volume_ml"].get<double>(), 150.0, 1e-3);
}

}  // namespace
}  // namespace vesica::test
