#include "vesica/surface/Topology.h"

#include <map>
#include <numeric>
#include <utility>
#include <vector>

namespace vesica::surface {

namespace {
// Union-find over vertex ids, to count boundary loops as connected boundary-edge sets.
int find_root(std::vector<int>& parent, int v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}
}  // namespace

EdgeTopology edge_topology(const Eigen::MatrixXi& F) {
  // undirected edge -> (uses, sum of directions: +1 for a->b with a<b, -1 otherwise)
  std::map<std::pair<int, int>, std::pair<int, int>> edges;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = F(f, k), b = F(f, (k + 1) % 3);
      auto& e = edges[{std::min(a, b), std::max(a, b)}];
      e.first += 1;
      e.second += a < b ? 1 : -1;
    }
  EdgeTopology t;
  const int n = F.size() ? F.maxCoeff() + 1 : 0;
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<bool> on_boundary(n, false);
  for (const auto& [edge, use] : edges) {
    if (use.first == 1) {
      ++t.boundary_edges;
      on_boundary[edge.first] = on_boundary[edge.second] = true;
      parent[find_root(parent, edge.first)] = find_root(parent, edge.second);
    } else if (use.first > 2) {
      ++t.non_manifold_edges;
    } else if (use.second != 0) {
      ++t.inconsistent_edges;
    }
  }
  for (int v = 0; v < n; ++v)
    if (on_boundary[v] && find_root(parent, v) == v) ++t.holes;
  return t;
}

}  // namespace vesica::surface
