#include "core/solvers/anderson_acceleration.h"

#include <Eigen/QR>
#include <algorithm>

namespace fosssim {

Vector AndersonAcceleration::next(const Vector& x, const Vector& g) {
  const Eigen::Index n = x.size();
  if (residual_changes_.rows() != n) {
    residual_changes_.resize(n, window_);
    image_changes_.resize(n, window_);
    stored_ = 0;
    have_previous_ = false;
  }
  Vector residual = g - x;
  if (have_previous_) {
    const int column = stored_ % window_;
    residual_changes_.col(column) = residual - previous_residual_;
    image_changes_.col(column) = g - previous_image_;
    ++stored_;
  }
  previous_residual_ = residual;
  previous_image_ = g;
  have_previous_ = true;
  const int m = std::min(stored_, window_);
  if (m == 0) return g;
  const auto dF = residual_changes_.leftCols(m);
  const Eigen::MatrixXd gram = dF.transpose() * dF;
  const Vector projected = dF.transpose() * residual;
  const Vector gamma = gram.completeOrthogonalDecomposition().solve(projected);
  return g - image_changes_.leftCols(m) * gamma;
}

}  // namespace fosssim
