#include "core/solvers/gmres.h"

#include <cmath>

namespace fosssim {

KrylovResult Gmres::solve(const SparseMatrix& A, const Vector& b, Vector& x,
                          const Preconditioner& precondition, double tolerance, int max_iterations,
                          bool give_up_early) {
  const Eigen::Index n = b.size();
  const int m = max_iterations;
  KrylovResult result;
  residual_.noalias() = b - A * x;
  const double beta = residual_.norm();
  result.residual = beta;
  if (beta <= tolerance) {
    result.converged = true;
    return result;
  }
  if (basis_.rows() != n || basis_.cols() < m + 1) basis_.resize(n, m + 1);
  if (preconditioned_.rows() != n || preconditioned_.cols() < m) preconditioned_.resize(n, m);
  Eigen::MatrixXd hessenberg = Eigen::MatrixXd::Zero(m + 1, m);
  Vector cosines(m), sines(m), g = Vector::Zero(m + 1);
  g[0] = beta;
  basis_.col(0) = residual_ / beta;
  int k = 0;  // columns of the basis used
  while (k < m) {
    const int j = k++;
    precondition(basis_.col(j).data(), preconditioned_.col(j).data());
    work_.noalias() = A * preconditioned_.col(j);
    for (int i = 0; i <= j; ++i) {  // modified Gram-Schmidt
      hessenberg(i, j) = work_.dot(basis_.col(i));
      work_ -= hessenberg(i, j) * basis_.col(i);
    }
    const double next = work_.norm();
    hessenberg(j + 1, j) = next;
    if (next > 0.0) basis_.col(j + 1) = work_ / next;
    for (int i = 0; i < j; ++i) {  // the earlier rotations, then a new one zeroing H(j+1, j)
      const double upper = hessenberg(i, j), lower = hessenberg(i + 1, j);
      hessenberg(i, j) = cosines[i] * upper + sines[i] * lower;
      hessenberg(i + 1, j) = -sines[i] * upper + cosines[i] * lower;
    }
    const double radius = std::hypot(hessenberg(j, j), next);
    cosines[j] = radius > 0.0 ? hessenberg(j, j) / radius : 1.0;
    sines[j] = radius > 0.0 ? next / radius : 0.0;
    hessenberg(j, j) = radius;
    hessenberg(j + 1, j) = 0.0;
    g[j + 1] = -sines[j] * g[j];
    g[j] = cosines[j] * g[j];
    if (std::abs(g[j + 1]) <= tolerance || next == 0.0) break;
    if (give_up_early && k >= 3) {
      // ‖r_k‖ = |g[k]|; at the mean rate so far, ‖r_m‖ ≈ ‖r_k‖ (‖r_k‖ / β)^((m - k) / k).
      const double reduction = std::abs(g[j + 1]) / beta;
      const double projected = std::abs(g[j + 1]) * std::pow(reduction, double(m - k) / k);
      if (projected > tolerance) break;
    }
  }
  // x += Z y with H y = g (upper triangular, k × k).
  const Vector y = hessenberg.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
  x.noalias() += preconditioned_.leftCols(k) * y;
  residual_.noalias() = b - A * x;
  result.iterations = k;
  result.residual = residual_.norm();
  result.converged = result.residual <= tolerance;
  return result;
}

}  // namespace fosssim
