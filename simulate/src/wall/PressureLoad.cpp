#include "wall/PressureLoad.h"

namespace vesica::simulate {
namespace {
Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}
}  // namespace

PressureResponse pressure_response(const std::array<Eigen::Vector3d, 3>& x,
                                   const HydrostaticPressure& inside,
                                   const HydrostaticPressure& outside) {
  PressureResponse r;
  const Eigen::Vector3d n2 = (x[1] - x[0]).cross(x[2] - x[0]);  // twice the area vector
  double p[3];
  for (int a = 0; a < 3; ++a) p[a] = inside.at(x[a]) - outside.at(x[a]);
  const double P = p[0] + p[1] + p[2];
  // d(n2) = Σ_b δx_b × (x_{b+1} - x_{b+2}) = -Σ_b skew(x_{b+1} - x_{b+2}) δx_b
  std::array<Eigen::Matrix3d, 3> dn2;
  for (int b = 0; b < 3; ++b) dn2[b] = -skew(x[(b + 1) % 3] - x[(b + 2) % 3]);
  const Eigen::RowVector3d dp =  // ∂p_c/∂x_c
      inside.rho * inside.gravity.transpose() - outside.rho * outside.gravity.transpose();
  for (Eigen::Index a = 0; a < 3; ++a) {
    const double s = p[a] + P;
    r.f.segment<3>(3 * a) = n2 * s / 24.0;
    r.dfdp0.segment<3>(3 * a) = n2 * 4.0 / 24.0;
    for (Eigen::Index b = 0; b < 3; ++b) {
      const double ds = (a == b ? 2.0 : 1.0);
      r.dfdx.block<3, 3>(3 * a, 3 * b) = (s * dn2[b] + ds * n2 * dp) / 24.0;
    }
  }
  return r;
}

Eigen::Matrix<double, 9, 1> volume_gradient(const std::array<Eigen::Vector3d, 3>& x) {
  Eigen::Matrix<double, 9, 1> g;
  for (Eigen::Index a = 0; a < 3; ++a)
    g.segment<3>(3 * a) = x[(a + 1) % 3].cross(x[(a + 2) % 3]) / 6.0;
  return g;
}

double signed_volume(const std::array<Eigen::Vector3d, 3>& x) {
  return x[0].dot(x[1].cross(x[2])) / 6.0;
}

}  // namespace vesica::simulate
