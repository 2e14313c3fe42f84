#include "fluid/StabilizedTet.h"

#include <cmath>
#include <stdexcept>

namespace vesica::simulate::fluid {
namespace {

// 4-point, degree-2 rule on the tetrahedron (barycentric weights, equal weights V/4):
// the mass and convection integrands are quadratic in a P1 element.
constexpr double kQa = 0.5854101966249685;
constexpr double kQb = 0.1381966011250105;

double element_size(double volume) {
  return 2.0 * std::cbrt(3.0 * volume / (4.0 * M_PI));
}

}  // namespace

void tet_gradients(const std::array<Eigen::Vector3d, 4>& x, Eigen::Matrix<double, 4, 3>& grad,
                   double& volume) {
  Eigen::Matrix3d J;
  J << x[1] - x[0], x[2] - x[0], x[3] - x[0];
  const double det = J.determinant();
  const double scale = (x[1] - x[0]).squaredNorm() * (x[2] - x[0]).norm() + 1e-300;
  if (std::abs(det) <= 1e-12 * scale) throw std::runtime_error("degenerate tetrahedron");
  volume = std::abs(det) / 6.0;
  // Rows of J⁻¹ are ∇ξ_1..3 of the barycentric coordinates ξ_1..3.
  const Eigen::Matrix3d Jinv = J.inverse();
  grad.bottomRows<3>() = Jinv;
  grad.row(0) = -Jinv.colwise().sum();
}

void stabilized_tet(const TetState& s, const FluidProperties& fluid, double inverse_dt,
                    TetVector& residual, TetMatrix* tangent) {
  Eigen::Matrix<double, 4, 3> dN;
  double volume = 0.0;
  tet_gradients(s.x, dN, volume);
  const double rho = fluid.density, mu = fluid.viscosity;
  const double h = element_size(volume);

  // Constant in a P1 element: velocity gradient G_ij = ∂u_i/∂x_j, ∇p, ∇·u.
  Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
  Eigen::Vector3d grad_p = Eigen::Vector3d::Zero();
  for (int a = 0; a < 4; ++a) {
    G += s.u[a] * dN.row(a);
    grad_p += s.p[a] * dN.row(a).transpose();
  }
  const double div_u = G.trace();
  const Eigen::Matrix3d two_mu_eps = mu * (G + G.transpose());

  // τ from the element-mean convective velocity c̄; τ_M = (A + B |c̄|²)^(-1/2), so
  // ∂τ_M/∂u_b = −τ_M³ B c̄ / 4 (c̄ is the mean of the four nodes).
  Eigen::Vector3d c_mean = Eigen::Vector3d::Zero();
  for (int a = 0; a < 4; ++a) c_mean += 0.25 * (s.u[a] - s.w_mesh[a]);
  const double B = std::pow(2.0 * rho / h, 2);
  const double tau_m = 1.0 / std::sqrt(std::pow(2.0 * rho * inverse_dt, 2) +
                                       B * c_mean.squaredNorm() + std::pow(24.0 * mu / (h * h), 2));
  const double tau_c = h * h / (6.0 * tau_m);
  const Eigen::Vector3d dtau_m = -std::pow(tau_m, 3) * B * c_mean / 4.0;
  const Eigen::Vector3d dtau_c = -tau_c / tau_m * dtau_m;

  residual.setZero();
  if (tangent) tangent->setZero();
  const double w = volume / 4.0;
  for (int q = 0; q < 4; ++q) {
    Eigen::Vector4d N = Eigen::Vector4d::Constant(kQb);
    N[q] = kQa;
    Eigen::Vector3d u = Eigen::Vector3d::Zero(), u_old = Eigen::Vector3d::Zero(),
                    c = Eigen::Vector3d::Zero();
    for (int a = 0; a < 4; ++a) {
      u += N[a] * s.u[a];
      u_old += N[a] * s.u_old[a];
      c += N[a] * (s.u[a] - s.w_mesh[a]);
    }
    const Eigen::Vector3d inertia = rho * (inverse_dt * (u - u_old) + G * c);
    const Eigen::Vector3d r_m = inertia + grad_p - rho * fluid.gravity;
    const Eigen::Vector4d c_dot_grad = dN * c;  // c·∇N_a
    const double p = N.dot(Eigen::Vector4d(s.p[0], s.p[1], s.p[2], s.p[3]));

    for (Eigen::Index a = 0; a < 4; ++a) {
      const Eigen::Vector3d dNa = dN.row(a).transpose();
      const Eigen::Vector3d r_a = N[a] * (inertia - rho * fluid.gravity) + two_mu_eps * dNa -
                                  p * dNa + tau_m * rho * c_dot_grad[a] * r_m + tau_c * div_u * dNa;
      residual.segment<3>(4 * a) += w * r_a;
      residual[4 * a + 3] += w * (N[a] * div_u + tau_m * dNa.dot(r_m));
    }

    if (!tangent) continue;
    TetMatrix& K = *tangent;
    for (Eigen::Index a = 0; a < 4; ++a) {
      const Eigen::Vector3d dNa = dN.row(a).transpose();
      for (Eigen::Index b = 0; b < 4; ++b) {
        const Eigen::Vector3d dNb = dN.row(b).transpose();
        // ∂r_M/∂u_b = ρ(N_b/Δt + c·∇N_b) I + ρ N_b G: both places u enters (c·∇)u. The
        // second (and every other term through c: τ, c·∇N_a) drops when the mesh
        // follows node b, since then c does not depend on u_b.
        const double through_c = s.mesh_follows[b] ? 0.0 : 1.0;
        const Eigen::Vector3d dtau_m_b = through_c * dtau_m, dtau_c_b = through_c * dtau_c;
        const double scalar_b = rho * (inverse_dt * N[b] + c_dot_grad[b]);
        const Eigen::Matrix3d d_inertia =
            scalar_b * Eigen::Matrix3d::Identity() + through_c * rho * N[b] * G;
        const Eigen::Matrix3d k_uu =
            N[a] * d_inertia +
            mu * (dNa.dot(dNb) * Eigen::Matrix3d::Identity() + dNb * dNa.transpose()) +
            rho * c_dot_grad[a] * (tau_m * d_inertia + r_m * dtau_m_b.transpose()) +
            through_c * tau_m * rho * N[b] * r_m * dNa.transpose() +
            dNa * (tau_c * dNb + div_u * dtau_c_b).transpose();
        const Eigen::Vector3d k_up = -N[b] * dNa + tau_m * rho * c_dot_grad[a] * dNb;
        const Eigen::RowVector3d k_pu = N[a] * dNb.transpose() +
                                        tau_m * dNa.transpose() * d_inertia +
                                        dNa.dot(r_m) * dtau_m_b.transpose();
        const double k_pp = tau_m * dNa.dot(dNb);
        K.block<3, 3>(4 * a, 4 * b) += w * k_uu;
        K.block<3, 1>(4 * a, 4 * b + 3) += w * k_up;
        K.block<1, 3>(4 * a + 3, 4 * b) += w * k_pu;
        K(4 * a + 3, 4 * b + 3) += w * k_pp;
      }
    }
  }
}

}  // namespace vesica::simulate::fluid
