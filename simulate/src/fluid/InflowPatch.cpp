#include "fluid/InflowPatch.h"

#include <map>
#include <stdexcept>

namespace vesica::simulate::fluid {

std::vector<VelocityCondition> plug_inflow(const BoundaryFaces& boundary,
                                           const std::vector<std::array<int, 3>>& patch,
                                           const std::vector<bool>& held, double flow_rate) {
  // Inward direction per free node: the mean of its faces' inward unit normals.
  std::map<int, Eigen::Vector3d> direction;
  for (const auto& f : patch) {
    const Eigen::Vector3d inward = -boundary.area_normal(f).normalized();
    for (int v : f)
      if (!held[v]) direction.try_emplace(v, Eigen::Vector3d::Zero()).first->second += inward;
  }
  if (direction.empty()) throw std::invalid_argument("inflow patch has no free node");
  for (auto& [node, d] : direction) d.normalize();
  // Flux of the unit plug: u is linear on each face, so ∫ u·n dA = Σ_corners u·(A n)/3.
  double unit_inflow = 0.0;
  for (const auto& f : patch) {
    const Eigen::Vector3d area_normal = boundary.area_normal(f);
    for (int v : f) {
      const auto it = direction.find(v);
      if (it != direction.end()) unit_inflow -= it->second.dot(area_normal) / 3.0;
    }
  }
  std::vector<VelocityCondition> conditions;
  conditions.reserve(direction.size());
  for (const auto& [node, d] : direction)
    conditions.push_back({node, {true, true, true}, flow_rate / unit_inflow * d});
  return conditions;
}

}  // namespace vesica::simulate::fluid
