#pragma once
// Symmetric second- and fourth-order tensors in Voigt notation, the common language of
// the materials and the element. Order of components: 11, 22, 33, 12, 23, 13.
// A fourth-order tensor D with minor symmetries is stored as D(I, J) = D_ijkl with
// I = (ij), J = (kl); then dS_I = D(I, J) dE_J with engineering shear strains 2 dE_12.
#include <Eigen/Dense>

namespace vesica::simulate {

using Voigt6 = Eigen::Matrix<double, 6, 6>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

inline constexpr int kVoigtIndex[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};

inline Vector6 to_voigt(const Eigen::Matrix3d& S) {
  Vector6 v;
  for (int I = 0; I < 6; ++I) v(I) = S(kVoigtIndex[I][0], kVoigtIndex[I][1]);
  return v;
}

inline Eigen::Matrix3d from_voigt(const Vector6& v) {
  Eigen::Matrix3d S;
  for (int I = 0; I < 6; ++I) {
    S(kVoigtIndex[I][0], kVoigtIndex[I][1]) = v(I);
    S(kVoigtIndex[I][1], kVoigtIndex[I][0]) = v(I);
  }
  return S;
}

// (A ⊗ B)_ijkl = A_ij B_kl: the outer product of the Voigt vectors (one vectorized
// 6x6 product; the materials form several per evaluation).
inline Voigt6 outer(const Eigen::Matrix3d& A, const Eigen::Matrix3d& B) {
  return to_voigt(A) * to_voigt(B).transpose();
}

// (A ⊙ A)_ijkl = (A_ik A_jl + A_il A_jk) / 2; -C⁻¹⊙C⁻¹ is dC⁻¹/dC.
inline Voigt6 odot(const Eigen::Matrix3d& A) {
  Voigt6 D;
  for (int I = 0; I < 6; ++I) {
    const int i = kVoigtIndex[I][0], j = kVoigtIndex[I][1];
    for (int J = 0; J < 6; ++J) {
      const int k = kVoigtIndex[J][0], l = kVoigtIndex[J][1];
      D(I, J) = 0.5 * (A(i, k) * A(j, l) + A(i, l) * A(j, k));
    }
  }
  return D;
}

}  // namespace vesica::simulate
