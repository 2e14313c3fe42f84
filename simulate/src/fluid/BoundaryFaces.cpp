#include "fluid/BoundaryFaces.h"

#include <algorithm>
#include <stdexcept>

#include "fluid/StabilizedTet.h"

namespace vesica::simulate::fluid {
namespace {

std::array<int, 3> sorted(std::array<int, 3> f) {
  std::sort(f.begin(), f.end());
  return f;
}

// The four faces of a tetrahedron, each listed with the opposite vertex last.
constexpr int kFaces[4][4] = {{1, 2, 3, 0}, {0, 2, 3, 1}, {0, 1, 3, 2}, {0, 1, 2, 3}};

}  // namespace

BoundaryFaces::BoundaryFaces(const FluidMesh& mesh) : mesh_(mesh) {
  std::map<std::array<int, 3>, int> count;
  for (int t = 0; t < static_cast<int>(mesh.tets.size()); ++t) {
    for (const auto& f : kFaces) {
      const auto key = sorted({mesh.tets[t][f[0]], mesh.tets[t][f[1]], mesh.tets[t][f[2]]});
      if (++count[key] == 1) owner_[key] = t;
    }
  }
  for (auto it = owner_.begin(); it != owner_.end();) {
    if (count[it->first] != 1) {
      it = owner_.erase(it);
      continue;
    }
    std::array<int, 3> face = it->first;
    // Orient right-handed outward: flip when the normal points to the opposite vertex.
    const auto& tet = mesh.tets[it->second];
    int opposite = -1;
    for (int v : tet)
      if (v != face[0] && v != face[1] && v != face[2]) opposite = v;
    const Eigen::Vector3d& a = mesh.nodes[face[0]];
    const Eigen::Vector3d n = (mesh.nodes[face[1]] - a).cross(mesh.nodes[face[2]] - a);
    if (n.dot(mesh.nodes[opposite] - a) > 0.0) std::swap(face[1], face[2]);
    faces_.push_back(face);
    ++it;
  }
}

int BoundaryFaces::owner(const std::array<int, 3>& face) const {
  const auto it = owner_.find(sorted(face));
  if (it == owner_.end()) throw std::invalid_argument("triangle is not a boundary face");
  return it->second;
}

Eigen::Vector3d BoundaryFaces::area_normal(const std::array<int, 3>& face) const {
  return area_normal(face, mesh_.nodes);
}

Eigen::Vector3d BoundaryFaces::area_normal(const std::array<int, 3>& face,
                                           const std::vector<Eigen::Vector3d>& x) const {
  const auto& tet = mesh_.tets[owner(face)];
  int opposite = -1;
  for (int v : tet)
    if (v != face[0] && v != face[1] && v != face[2]) opposite = v;
  const Eigen::Vector3d& a = x[face[0]];
  Eigen::Vector3d n = 0.5 * (x[face[1]] - a).cross(x[face[2]] - a);
  return n.dot(x[opposite] - a) > 0.0 ? Eigen::Vector3d(-n) : n;
}

double flow_rate(const BoundaryFaces& boundary, const std::vector<std::array<int, 3>>& faces,
                 const Eigen::VectorXd& state) {
  double q = 0.0;
  for (const auto& f : faces) {
    // u is linear on the face: its integral is the area times the mean of the corners.
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int v : f) mean += state.segment<3>(kDofsPerNode * v) / 3.0;
    q += mean.dot(boundary.area_normal(f));
  }
  return q;
}

std::vector<Eigen::Vector3d> wall_shear_stress(const BoundaryFaces& boundary,
                                               const std::vector<std::array<int, 3>>& faces,
                                               const FluidProperties& fluid,
                                               const Eigen::VectorXd& state) {
  const FluidMesh& mesh = boundary.mesh();
  std::vector<Eigen::Vector3d> shear;
  shear.reserve(faces.size());
  for (const auto& f : faces) {
    const auto& tet = mesh.tets[boundary.owner(f)];
    std::array<Eigen::Vector3d, 4> x;
    for (int a = 0; a < 4; ++a) x[a] = mesh.nodes[tet[a]];
    Eigen::Matrix<double, 4, 3> dN;
    double volume = 0.0;
    tet_gradients(x, dN, volume);
    Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
    for (int a = 0; a < 4; ++a) G += state.segment<3>(kDofsPerNode * tet[a]) * dN.row(a);
    // The pressure part of σn is normal and drops out of the tangential projection.
    const Eigen::Vector3d n = boundary.area_normal(f).normalized();
    const Eigen::Vector3d t = fluid.viscosity * (G + G.transpose()) * n;
    shear.push_back(t - t.dot(n) * n);
  }
  return shear;
}

}  // namespace vesica::simulate::fluid
