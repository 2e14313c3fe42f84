#include "wall/ElasticFoundation.h"

#include <algorithm>
#include <cmath>

#include "wall/MembraneProblem.h"

namespace vesica::simulate {

ElasticFoundation::ElasticFoundation(const MembraneProblem& wall, const FoundationOptions& options)
    : options_(options), area_(static_cast<Eigen::Index>(wall.free_dof_count())) {
  for (std::size_t g = 0; g < wall.dof_map().size(); ++g)
    if (wall.dof_map()[g] >= 0) area_(wall.dof_map()[g]) = wall.node_areas()[g / 3];
  const WallModel& model = wall.wall();
  double edges = 0.0;
  for (const auto& t : model.triangles)
    for (int k = 0; k < 3; ++k) edges += (model.nodes[t[(k + 1) % 3]] - model.nodes[t[k]]).norm();
  if (!model.triangles.empty())
    mean_edge_ = edges / (3.0 * static_cast<double>(model.triangle_count()));
}

double ElasticFoundation::stiffness_scale(const Eigen::SparseMatrix<double>& K) const {
  double diagonal = 0.0;
  for (Eigen::Index d = 0; d < area_.size(); ++d) diagonal += std::abs(K.coeff(d, d));
  return diagonal / std::max(area_.sum(), 1e-300);
}

void ElasticFoundation::add(Eigen::SparseMatrix<double>& K, double added) const {
  for (Eigen::Index d = 0; d < area_.size(); ++d) K.coeffRef(d, d) += added * area_(d);
}

}  // namespace vesica::simulate
