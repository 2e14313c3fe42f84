#include "vesica/simulate/TensionField.h"

#include <Eigen/Eigenvalues>

namespace vesica::simulate {

bool relax_compression(PlaneStressState& state) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(state.S);
  const double s_min = es.eigenvalues()(0), s_max = es.eigenvalues()(1);
  if (s_min >= 0.0) return false;  // taut
  if (s_max <= 0.0) {              // slack
    state.S.setZero();
    state.D.setZero();
    return true;
  }
  const Eigen::Vector2d v = es.eigenvectors().col(1);
  // v vᵀ as a stress (11, 22, 12) and as a strain with engineering shear (11, 22, 2·12).
  const Eigen::Vector3d m_stress(v(0) * v(0), v(1) * v(1), v(0) * v(1));
  const Eigen::Vector3d m_strain(v(0) * v(0), v(1) * v(1), 2.0 * v(0) * v(1));
  const double stiffness = m_strain.dot(state.D * m_strain);
  state.S = s_max * v * v.transpose();
  state.D = stiffness * m_stress * m_stress.transpose();
  return true;
}

}  // namespace vesica::simulate
