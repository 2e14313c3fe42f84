#include "fluid/FlowStructures.h"

#include <stdexcept>

#include "fluid/StabilizedTet.h"

namespace vesica::simulate::fluid {

TetVortexMeasures vortex_measures(const Eigen::Matrix3d& G) {
  TetVortexMeasures m;
  m.vorticity = {G(2, 1) - G(1, 2), G(0, 2) - G(2, 0), G(1, 0) - G(0, 1)};
  const Eigen::Matrix3d S = 0.5 * (G + G.transpose());
  const Eigen::Matrix3d W = 0.5 * (G - G.transpose());
  m.q_criterion = 0.5 * (W.squaredNorm() - S.squaredNorm());
  return m;
}

std::vector<TetVortexMeasures> tet_vortex_measures(const FluidMesh& mesh,
                                                   const Eigen::VectorXd& state) {
  std::vector<TetVortexMeasures> out(mesh.tets.size());
  for (std::size_t e = 0; e < mesh.tets.size(); ++e) {
    const auto& t = mesh.tets[e];
    const std::array<Eigen::Vector3d, 4> x{mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]],
                                           mesh.nodes[t[3]]};
    Eigen::Matrix<double, 4, 3> grad;
    double volume = 0.0;
    try {
      tet_gradients(x, grad, volume);
    } catch (const std::runtime_error&) {
      continue;  // degenerate: no gradient to speak of
    }
    // G = Σ_a u_a ⊗ ∇N_a.
    Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
    for (int a = 0; a < 4; ++a) G += state.segment<3>(kDofsPerNode * t[a]) * grad.row(a);
    out[e] = vortex_measures(G);
  }
  return out;
}

}  // namespace vesica::simulate::fluid
