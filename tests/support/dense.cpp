#include "support/dense.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>

#include "core/hessian_builder.h"
#include "support/random.h"

namespace fosssim::testing {

double asymmetry(const Eigen::MatrixXd& A) {
  const double norm = A.norm();
  return norm > 0.0 ? (A - A.transpose()).norm() / norm : 0.0;
}

Eigen::MatrixXd dense_pair_pattern(int n, int dim, int i, int j, const Eigen::MatrixXd& H) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n, n);
  out.block(dim * i, dim * i, dim, dim) += H;
  out.block(dim * j, dim * j, dim, dim) += H;
  out.block(dim * i, dim * j, dim, dim) -= H;
  out.block(dim * j, dim * i, dim, dim) -= H;
  return out;
}

Eigen::MatrixXd hessian_x_of(const Force& force, const Vector& q, const Vector& v,
                             const Vector& mass) {
  HessianBuilder builder;
  force.add_hessian_x({q, v, mass}, builder);
  return dense(builder.build(static_cast<int>(q.size())));
}

Eigen::MatrixXd hessian_v_of(const Force& force, const Vector& q, const Vector& v,
                             const Vector& mass) {
  HessianBuilder builder;
  force.add_hessian_v({q, v, mass}, builder);
  return dense(builder.build(static_cast<int>(q.size())));
}

Eigen::MatrixXd definite_hessian_x_of(const Force& force, const Vector& q, const Vector& v,
                                      const Vector& mass) {
  HessianBuilder builder;
  force.add_hessian_x({q, v, mass, /*definite_hessian=*/true}, builder);
  return dense(builder.build(static_cast<int>(q.size())));
}

namespace {
Eigen::VectorXd symmetric_eigenvalues(const Eigen::MatrixXd& H) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(H, Eigen::EigenvaluesOnly).eigenvalues();
}
}  // namespace

double expect_semidefinite_projection(const Eigen::MatrixXd& exact,
                                      const Eigen::MatrixXd& projected, const std::string& name) {
  const Eigen::VectorXd lambda = symmetric_eigenvalues(exact);
  const double scale = std::max(lambda.cwiseAbs().maxCoeff(), 1e-300);
  const double tolerance = 1e-12 * scale;
  EXPECT_LE(asymmetry(projected), tolerance) << name;
  const Eigen::VectorXd mu = symmetric_eigenvalues(projected);
  EXPECT_GE(mu.minCoeff(), -tolerance) << name;
  EXPECT_LE((mu - lambda.cwiseMax(0.0)).cwiseAbs().maxCoeff(), tolerance) << name;
  EXPECT_GE(symmetric_eigenvalues(projected - exact).minCoeff(), -tolerance) << name;
  Random random(7);
  for (int k = 0; k < 20; ++k) {
    const Vector x = random.uniform_vector(static_cast<int>(exact.rows()), -1.0, 1.0);
    EXPECT_GE(x.dot(projected * x), -tolerance * x.squaredNorm()) << name;
  }
  return lambda.minCoeff() / scale;
}

}  // namespace fosssim::testing
