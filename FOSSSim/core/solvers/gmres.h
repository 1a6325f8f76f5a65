#pragma once
// GMRES with a preconditioner, for step matrices near one whose factor is at hand.

#include <functional>

#include "core/types.h"

namespace fosssim {

/// How a Krylov solve ended.
struct KrylovResult {
  int iterations = 0;      ///< matrix products and preconditioner solves taken
  bool converged = false;  ///< ‖b - A x‖ reached the tolerance
  double residual = 0.0;   ///< ‖b - A x‖ at the end
};

/// Right-preconditioned GMRES (Saad and Schultz, "GMRES: a generalized minimal residual
/// algorithm for solving nonsymmetric linear systems", SISC 7(3), 1986) with the
/// preconditioned directions kept, as in flexible GMRES (Saad, SISC 14(2), 1993), so that the
/// update needs no extra preconditioner solve. Iterate k minimises ‖b - A x‖ over
/// x₀ + M⁻¹ K_k(A M⁻¹, r₀). It suits a non-symmetric or indefinite A close to an SPD matrix
/// whose factor is M (a factor of an earlier step matrix, or of A's symmetric part): then a few
/// iterations reach round-off. Every operation runs in a fixed order, so the result is
/// deterministic. The basis is kept between solves: no allocation once it has grown.
class Gmres {
 public:
  /// z = M⁻¹ r for vectors of A's size (r and z do not overlap).
  using Preconditioner = std::function<void(const double* r, double* z)>;

  /// Improves x (in/out, the start) until ‖b - A x‖ ≤ tolerance, for at most max_iterations
  /// (≥ 1) iterations without restarting. With `give_up_early`, stops as soon as (from the
  /// third iteration on) the residual's mean rate of decrease so far would not reach the
  /// tolerance within max_iterations: a preconditioner far from A is dropped after a few
  /// iterations rather than after all of them.
  KrylovResult solve(const SparseMatrix& A, const Vector& b, Vector& x,
                     const Preconditioner& precondition, double tolerance, int max_iterations,
                     bool give_up_early = false);

 private:
  Eigen::MatrixXd basis_;           // V: orthonormal basis of the Krylov space, n × (k+1)
  Eigen::MatrixXd preconditioned_;  // Z = M⁻¹ V, n × k
  Vector work_, residual_;
};

}  // namespace fosssim
