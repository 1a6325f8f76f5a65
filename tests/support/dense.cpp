#include "support/dense.h"

#include "core/hessian_builder.h"

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

}  // namespace fosssim::testing
