#include "wall/MembraneElement.h"

#include <cmath>
#include <stdexcept>

#include "wall/TensionField.h"

namespace vesica::simulate {

MembraneGeometry membrane_geometry(const std::array<Eigen::Vector3d, 3>& X, double H) {
  MembraneGeometry geo;
  const Eigen::Vector3d a = X[1] - X[0], b = X[2] - X[0];
  const Eigen::Vector3d n = a.cross(b);
  const double twice_area = n.norm();
  if (!(twice_area > 1e-14 * a.squaredNorm()) || a.norm() == 0.0)
    throw std::invalid_argument("degenerate triangle");
  const Eigen::Vector3d e1 = a.normalized(), n0 = n / twice_area, e2 = n0.cross(e1);
  geo.frame.row(0) = e1;
  geo.frame.row(1) = e2;
  geo.frame.row(2) = n0;
  geo.area0 = 0.5 * twice_area;
  geo.H = H;
  // Local coordinates of the nodes: (0,0), (s1,0), (t1,t2); gradients of linear N_a.
  const double s1 = a.dot(e1), t1 = b.dot(e1), t2 = b.dot(e2);
  Eigen::Matrix2d Jm;  // ∂s/∂ξ for N1 = 1-ξ-η, N2 = ξ, N3 = η
  Jm << s1, t1, 0.0, t2;
  const Eigen::Matrix2d Jinv = Jm.inverse();
  Eigen::Matrix<double, 2, 3> dN_dxi;
  dN_dxi << -1.0, 1.0, 0.0, -1.0, 0.0, 1.0;
  geo.dN = Jinv.transpose() * dN_dxi;
  return geo;
}

std::array<Eigen::Vector3d, 2> element_fibers(const MembraneGeometry& geo, const WallModel& wall,
                                              std::size_t e) {
  std::array<Eigen::Vector3d, 2> fibers{Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY()};
  if (e < wall.fibers.size()) {
    for (int f = 0; f < 2; ++f) {
      Eigen::Vector3d a = geo.frame * wall.fibers[e][f];
      a.z() = 0.0;
      if (a.norm() > 1e-6) fibers[f] = a.normalized();
    }
  }
  return fibers;
}

MembraneResponse membrane_response(const MembraneGeometry& geo,
                                   const std::array<Eigen::Vector3d, 3>& x,
                                   const Material& material, const MaterialPoint& point,
                                   double J2_guess, const double* history_old, double* history_new,
                                   bool tension_field, double wrinkle_regularisation) {
  MembraneResponse r;
  r.g.setZero();
  for (int a = 0; a < 3; ++a) r.g += x[a] * geo.dN.col(a).transpose();
  const Eigen::Matrix2d C2 = r.g.transpose() * r.g;
  r.stress = tension_field
                 ? regularised_tension_field_stress(material, C2, point, J2_guess, history_old,
                                                    history_new, wrinkle_regularisation)
                 : plane_stress(material, C2, point, J2_guess, history_old, history_new);
  const Eigen::Matrix2d& S = r.stress.S;
  const double HA = geo.H * geo.area0;

  // B maps nodal displacement variations to (δE11, δE22, 2 δE12).
  Eigen::Matrix<double, 3, 9> B;
  for (Eigen::Index a = 0; a < 3; ++a) {
    const Eigen::Vector3d g1 = r.g.col(0), g2 = r.g.col(1);
    B.block<1, 3>(0, 3 * a) = geo.dN(0, a) * g1.transpose();
    B.block<1, 3>(1, 3 * a) = geo.dN(1, a) * g2.transpose();
    B.block<1, 3>(2, 3 * a) = (geo.dN(1, a) * g1 + geo.dN(0, a) * g2).transpose();
  }
  const Eigen::Vector3d S_voigt(S(0, 0), S(1, 1), S(0, 1));
  r.f_int = HA * B.transpose() * S_voigt;
  // Coefficient-wise product: Eigen's blocked GEMM, which it picks for these sizes, is
  // several times slower on a 9x3 by 3x9 product.
  const Eigen::Matrix<double, 9, 3> BtD = HA * B.transpose() * r.stress.D;
  r.K.noalias() = BtD.lazyProduct(B);
  // Geometric stiffness of the full S: the consistent tangent, also where the wall is in
  // compression (there it is negative; the tissue drag of the cavity models keeps the
  // system well-posed, ProtocolSettings::wall_drag_pa_s_per_m).
  for (Eigen::Index a = 0; a < 3; ++a)
    for (Eigen::Index b = 0; b < 3; ++b) {
      const double kg = HA * geo.dN.col(a).dot(S * geo.dN.col(b));
      r.K.block<3, 3>(3 * a, 3 * b).diagonal().array() += kg;
    }
  return r;
}

MembraneStressOutput membrane_stress_output(const MembraneGeometry& geo,
                                            const MembraneResponse& r) {
  MembraneStressOutput out;
  const Eigen::Matrix2d C2 = r.g.transpose() * r.g;
  const double J = std::sqrt(C2.determinant() * r.stress.C33);
  // σ's in-plane eigenvalues equal those of L S Lᵀ / J with C2 = Lᵀ L ... use C2 = U Uᵀ.
  const Eigen::LLT<Eigen::Matrix2d> llt(C2);
  const Eigen::Matrix2d L = llt.matrixL();
  const Eigen::Matrix2d sym = L.transpose() * r.stress.S * L / J;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(sym);
  out.sigma1 = es.eigenvalues()(1);
  out.sigma2 = es.eigenvalues()(0);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> ec(C2);
  out.stretch1 = std::sqrt(ec.eigenvalues()(1));
  out.stretch2 = std::sqrt(ec.eigenvalues()(0));
  out.thickness = geo.H * std::sqrt(r.stress.C33);
  return out;
}

}  // namespace vesica::simulate
