#pragma once
// Dense views: sparse matrices as dense ones, and a force's energy, gradient and Hessians at one
// configuration, assembled densely, for comparisons written without the library's assembly.

#include <Eigen/Dense>

#include "core/force.h"
#include "core/force_evaluation.h"
#include "core/types.h"

namespace fosssim::testing {

/// A sparse matrix as a dense one.
inline Eigen::MatrixXd dense(const SparseMatrix& A) { return Eigen::MatrixXd(A); }

/// ‖A - Aᵀ‖_F / ‖A‖_F, 0 for the zero matrix.
double asymmetry(const Eigen::MatrixXd& A);

/// The pair pattern of pair forces (docs/forces.md) as a dense n×n matrix: +H on blocks (i,i),
/// (j,j), -H on (i,j), (j,i). Written out here so tests do not depend on HessianBuilder for
/// expected values.
Eigen::MatrixXd dense_pair_pattern(int n, int dim, int i, int j, const Eigen::MatrixXd& H);

/// The force's hessX and hessV at (q, v) with per-coordinate masses, assembled densely (its
/// gradient and energy: gradient_of and energy_of of core/force_evaluation.h).
Eigen::MatrixXd hessian_x_of(const Force& force, const Vector& q, const Vector& v,
                             const Vector& mass);
Eigen::MatrixXd hessian_v_of(const Force& force, const Vector& q, const Vector& v,
                             const Vector& mass);
/// The force's hessX with ForceInput::definite_hessian set (each element's block projected onto
/// the positive semi-definite matrices), assembled densely.
Eigen::MatrixXd definite_hessian_x_of(const Force& force, const Vector& q, const Vector& v,
                                      const Vector& mass);

/// Expects `projected` to be the projection of the symmetric `exact` onto the positive
/// semi-definite matrices, to 1e-12 of exact's largest eigenvalue magnitude: symmetric, its
/// eigenvalues max(λ, 0) of exact's λ (so none below the tolerance), projected − exact
/// semi-definite (the projection only adds stiffness), and xᵀ projected x ≥ 0 for 20 random x.
/// `name` labels the failures. Returns exact's smallest eigenvalue over its largest magnitude,
/// so that a caller can check that a case tests a projection at all.
double expect_semidefinite_projection(const Eigen::MatrixXd& exact,
                                      const Eigen::MatrixXd& projected, const std::string& name);

}  // namespace fosssim::testing
