#include "fluid/MeshTransfer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Geometry>

namespace vesica::simulate::fluid {
namespace {

// Barycentric coordinates of p in the tetrahedron t at positions x (all zero for a flat
// tetrahedron, which then never wins).
Eigen::Vector4d barycentric(const std::vector<Eigen::Vector3d>& x, const std::array<int, 4>& t,
                            const Eigen::Vector3d& p) {
  Eigen::Matrix3d edges;
  edges << x[t[1]] - x[t[0]], x[t[2]] - x[t[0]], x[t[3]] - x[t[0]];
  const double det = edges.determinant();
  if (det == 0.0) return Eigen::Vector4d::Constant(-1.0);
  const Eigen::Vector3d l = edges.inverse() * (p - x[t[0]]);
  return {1.0 - l.sum(), l[0], l[1], l[2]};
}

// A uniform grid over the mesh's bounding box; each cell lists the tetrahedra whose
// (slightly widened) bounding boxes overlap it, so a point is tested against a few
// tetrahedra only. About one tetrahedron per cell.
class TetGrid {
 public:
  TetGrid(const std::vector<Eigen::Vector3d>& x, const std::vector<std::array<int, 4>>& tets) {
    for (const auto& p : x) box_.extend(p);
    const double pad = 1e-9 * box_.diagonal().norm();
    box_.min().array() -= pad;
    box_.max().array() += pad;
    const int per_axis = std::max(1, static_cast<int>(std::cbrt(double(tets.size()))));
    n_ = {per_axis, per_axis, per_axis};
    cells_.resize(static_cast<std::size_t>(per_axis) * per_axis * per_axis);
    for (std::size_t e = 0; e < tets.size(); ++e) {
      Eigen::AlignedBox3d b;
      for (int v : tets[e]) b.extend(x[v]);
      const auto lo = cell_of(Eigen::Vector3d(b.min().array() - pad));
      const auto hi = cell_of(Eigen::Vector3d(b.max().array() + pad));
      for (int i = lo[0]; i <= hi[0]; ++i)
        for (int j = lo[1]; j <= hi[1]; ++j)
          for (int k = lo[2]; k <= hi[2]; ++k) cells_[flat({i, j, k})].push_back(int(e));
    }
  }
  const std::vector<int>& candidates(const Eigen::Vector3d& p) const {
    return cells_[flat(cell_of(p))];
  }

 private:
  std::array<int, 3> cell_of(const Eigen::Vector3d& p) const {  // clamped to the grid
    std::array<int, 3> c{};
    for (int a = 0; a < 3; ++a) {
      const double s = (p[a] - box_.min()[a]) / (box_.max()[a] - box_.min()[a]);
      c[a] = std::clamp(static_cast<int>(std::floor(s * n_[a])), 0, n_[a] - 1);
    }
    return c;
  }
  std::size_t flat(const std::array<int, 3>& c) const {
    return (static_cast<std::size_t>(c[0]) * n_[1] + c[1]) * n_[2] + c[2];
  }
  Eigen::AlignedBox3d box_;
  std::array<int, 3> n_{};
  std::vector<std::vector<int>> cells_;
};

// Keeps the better of the current best and tetrahedron e (larger least coordinate).
void consider(const std::vector<Eigen::Vector3d>& x, const std::vector<std::array<int, 4>>& tets,
              int e, const Eigen::Vector3d& p, TetLocation& best, double& best_min) {
  const Eigen::Vector4d w = barycentric(x, tets[e], p);
  if (w.minCoeff() > best_min) {
    best_min = w.minCoeff();
    best = {e, w};
  }
}

}  // namespace

std::vector<TetLocation> locate_points(const std::vector<Eigen::Vector3d>& x,
                                       const std::vector<std::array<int, 4>>& tets,
                                       const std::vector<Eigen::Vector3d>& points) {
  if (tets.empty()) throw std::invalid_argument("locate_points: no tetrahedra");
  const TetGrid grid(x, tets);
  // A point inside (up to round-off) is in a tetrahedron of its own cell; only a point
  // clearly outside that cell's tetrahedra needs the search over all of them.
  constexpr double kInside = -1e-10;
  std::vector<TetLocation> located(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    double best_min = -std::numeric_limits<double>::infinity();
    for (int e : grid.candidates(points[i])) consider(x, tets, e, points[i], located[i], best_min);
    if (best_min >= kInside) continue;
    for (int e = 0; e < static_cast<int>(tets.size()); ++e)
      consider(x, tets, e, points[i], located[i], best_min);
  }
  return located;
}

Eigen::VectorXd interpolate_field(const Eigen::VectorXd& field, int components,
                                  const std::vector<std::array<int, 4>>& tets,
                                  const std::vector<TetLocation>& locations) {
  Eigen::VectorXd out =
      Eigen::VectorXd::Zero(components * static_cast<Eigen::Index>(locations.size()));
  for (std::size_t i = 0; i < locations.size(); ++i)
    for (int a = 0; a < 4; ++a)
      out.segment(components * static_cast<Eigen::Index>(i), components) +=
          locations[i].weights[a] *
          field.segment(components * Eigen::Index{tets[locations[i].tet][a]}, components);
  return out;
}

}  // namespace vesica::simulate::fluid
