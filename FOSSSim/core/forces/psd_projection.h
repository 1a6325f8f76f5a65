#pragma once
// Projection of a small symmetric element Hessian onto the positive semi-definite matrices,
// for forces asked for ForceInput::definite_hessian (docs/forces.md, 'Semi-definite element Hessians').

#include <Eigen/Eigenvalues>

namespace fosssim {

/// The positive semi-definite matrix nearest to the symmetric N×N matrix H in the Frobenius
/// norm: H = Q Λ Qᵀ (symmetric eigen-decomposition), negative eigenvalues set to 0,
/// Q max(Λ, 0) Qᵀ. This is the per-element projection of projected Newton (Teran, Sifakis,
/// Irving and Fedkiw 2005 clamp per element in FEM). A block that is already semi-definite
/// comes back equal to H up to round-off of the decomposition. Only H's lower triangle is read.
template <int N>
Eigen::Matrix<double, N, N> projected_to_semidefinite(const Eigen::Matrix<double, N, N>& H) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> eigen(H);
  const auto& values = eigen.eigenvalues();
  if (values.minCoeff() >= 0.0) return H;  // already semi-definite: the exact block, bit for bit
  const auto& Q = eigen.eigenvectors();
  Eigen::Matrix<double, N, N> out = Q * values.cwiseMax(0.0).asDiagonal() * Q.transpose();
  return 0.5 * (out + out.transpose());  // exactly symmetric
}

}  // namespace fosssim
