#include "vesica/mesh/MeshQuality.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

namespace vesica::mesh {

namespace {
constexpr double kDegPerRad = 180.0 / M_PI;

double angle_deg(const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
  return kDegPerRad * std::atan2(u.cross(v).norm(), u.dot(v));
}
}  // namespace

double triangle_min_angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                              const Eigen::Vector3d& c) {
  return std::min({angle_deg(b - a, c - a), angle_deg(a - b, c - b), angle_deg(a - c, b - c)});
}

TetShape tet_shape(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                   const Eigen::Vector3d& d) {
  const std::array<Eigen::Vector3d, 4> p{a, b, c, d};
  TetShape s;
  const Eigen::Vector3d e1 = b - a, e2 = c - a, e3 = d - a;
  const double six_v = e1.dot(e2.cross(e3));
  s.volume_mm3 = six_v / 6.0;
  // Outward face normals; face i is opposite vertex i.
  std::array<Eigen::Vector3d, 4> n;
  double area_sum = 0.0;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d& q0 = p[(i + 1) % 4];
    const Eigen::Vector3d& q1 = p[(i + 2) % 4];
    const Eigen::Vector3d& q2 = p[(i + 3) % 4];
    Eigen::Vector3d normal = (q1 - q0).cross(q2 - q0);
    area_sum += 0.5 * normal.norm();
    if (normal.dot(p[i] - q0) > 0) normal = -normal;
    n[i] = normal.normalized();
  }
  s.min_dihedral_deg = 180.0;
  s.max_dihedral_deg = 0.0;
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) {
      const double dihedral = 180.0 - angle_deg(n[i], n[j]);
      s.min_dihedral_deg = std::min(s.min_dihedral_deg, dihedral);
      s.max_dihedral_deg = std::max(s.max_dihedral_deg, dihedral);
    }
  }
  // r_in = 3V / total area; R_circ from the circumcentre relative to a.
  const double volume = std::abs(s.volume_mm3);
  if (volume <= 0.0 || area_sum <= 0.0) return s;
  const Eigen::Vector3d centre =
      (e1.squaredNorm() * e2.cross(e3) + e2.squaredNorm() * e3.cross(e1) +
       e3.squaredNorm() * e1.cross(e2)) /
      (2.0 * six_v);
  const double r_in = 3.0 * volume / area_sum;
  s.radius_ratio = 3.0 * r_in / centre.norm();
  return s;
}

MeshQuality measure_quality(const VolumeMesh& mesh) {
  MeshQuality q;
  q.triangle_min_angle_deg = 180.0;
  double sum_min = 0.0;
  for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t) {
    const double a = triangle_min_angle_deg(mesh.nodes.row(mesh.triangles(t, 0)),
                                            mesh.nodes.row(mesh.triangles(t, 1)),
                                            mesh.nodes.row(mesh.triangles(t, 2)));
    q.triangle_min_angle_deg = std::min(q.triangle_min_angle_deg, a);
    sum_min += a;
  }
  if (mesh.triangles.rows()) q.triangle_mean_min_angle_deg = sum_min / mesh.triangles.rows();
  if (mesh.tets.rows() == 0) return q;
  q.tet_min_dihedral_deg = 180.0;
  q.tet_min_radius_ratio = 1.0;
  long good = 0;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    const TetShape s = tet_shape(mesh.nodes.row(mesh.tets(t, 0)), mesh.nodes.row(mesh.tets(t, 1)),
                                 mesh.nodes.row(mesh.tets(t, 2)), mesh.nodes.row(mesh.tets(t, 3)));
    if (s.volume_mm3 <= 0.0) ++q.inverted_tets;
    q.tet_min_dihedral_deg = std::min(q.tet_min_dihedral_deg, s.min_dihedral_deg);
    q.tet_max_dihedral_deg = std::max(q.tet_max_dihedral_deg, s.max_dihedral_deg);
    q.tet_min_radius_ratio = std::min(q.tet_min_radius_ratio, s.radius_ratio);
    if (s.radius_ratio >= 0.3) ++good;
    const int bin = std::clamp(static_cast<int>(s.radius_ratio * 10.0), 0, 9);
    ++q.radius_ratio_histogram[bin];
  }
  q.tet_fraction_radius_ratio_ge_0_3 = static_cast<double>(good) / mesh.tets.rows();
  return q;
}

nlohmann::json to_json(const MeshQuality& q, bool with_tets) {
  nlohmann::json j;
  j["triangle_min_angle_deg"] = q.triangle_min_angle_deg;
  j["triangle_mean_min_angle_deg"] = q.triangle_mean_min_angle_deg;
  if (!with_tets) return j;
  j["tet_min_dihedral_deg"] = q.tet_min_dihedral_deg;
  j["tet_max_dihedral_deg"] = q.tet_max_dihedral_deg;
  j["tet_min_radius_ratio"] = q.tet_min_radius_ratio;
  j["tet_fraction_radius_ratio_ge_0_3"] = q.tet_fraction_radius_ratio_ge_0_3;
  j["radius_ratio_histogram"] = {
      {"bin_edges", {0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0}},
      {"counts", q.radius_ratio_histogram}};
  j["inverted_tets"] = q.inverted_tets;
  return j;
}

}  // namespace vesica::mesh
