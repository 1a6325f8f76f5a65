// Anderson acceleration on fixed-point maps whose answer is known.

#include "core/solvers/anderson_acceleration.h"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <Eigen/QR>

namespace fosssim {
namespace {

/// G(x) = B x + c with B symmetric, its eigenvalues spread over [-0.3, 0.95]: the plain
/// iteration converges at the rate 0.95 to the fixed point x* = (I - B)⁻¹ c.
struct LinearMap {
  Eigen::MatrixXd B;
  Vector c;
  Vector fixed_point;

  explicit LinearMap(int n) {
    const Eigen::MatrixXd random = Eigen::MatrixXd::Random(n, n);
    const Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(random).householderQ();
    const Vector eigenvalues = Vector::LinSpaced(n, -0.3, 0.95);
    B = Q * eigenvalues.asDiagonal() * Q.transpose();
    c = Vector::LinSpaced(n, 1.0, 2.0);
    fixed_point = (Eigen::MatrixXd::Identity(n, n) - B).partialPivLu().solve(c);
  }
  Vector operator()(const Vector& x) const { return B * x + c; }
};

TEST(AndersonAcceleration, AWindowAsLargeAsTheProblemSolvesALinearMapInFewIterations) {
  // With the full window, Anderson acceleration of a linear map is GMRES on (I - B) x = c
  // (Walker and Ni 2011): it has the answer after n + 1 images, to round-off.
  const int n = 8;
  const LinearMap G(n);
  AndersonAcceleration anderson(n);
  Vector x = Vector::Zero(n);
  Vector plain = x;
  for (int k = 0; k < n + 2; ++k) {
    x = anderson.next(x, G(x));
    plain = G(plain);
  }
  const double start_error = G.fixed_point.norm();
  EXPECT_LT((x - G.fixed_point).norm(), 1e-10 * start_error);
  EXPECT_GT((plain - G.fixed_point).norm(), 0.3 * start_error) << "the plain iteration is slow";
}

TEST(AndersonAcceleration, AShortWindowStillBeatsThePlainIterationByFar) {
  const int n = 40;
  const LinearMap G(n);
  AndersonAcceleration anderson(5);
  Vector x = Vector::Zero(n);
  Vector plain = x;
  for (int k = 0; k < 40; ++k) {
    x = anderson.next(x, G(x));
    plain = G(plain);
  }
  const double plain_error = (plain - G.fixed_point).norm();
  EXPECT_LT((x - G.fixed_point).norm(), 1e-3 * plain_error);
}

TEST(AndersonAcceleration, AfterAResetTheFirstIterateIsThePlainImage) {
  const LinearMap G(4);
  AndersonAcceleration anderson(3);
  Vector x = Vector::Ones(4);
  for (int k = 0; k < 3; ++k) x = anderson.next(x, G(x));
  anderson.reset();
  const Vector image = G(x);
  EXPECT_EQ(anderson.next(x, image), image);
}

}  // namespace
}  // namespace fosssim
