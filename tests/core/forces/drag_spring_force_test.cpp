// DragSpringForce: a zero-rest-length spring from a particle to a movable point.

#include "core/forces/drag_spring_force.h"

#include <gtest/gtest.h>

#include "core/analysis/derivative_check.h"

namespace fosssim {
namespace {

void expect_drag_spring_derivatives_pass(const Force& force, const Vector& q) {
  const Vector v = Vector::LinSpaced(q.size(), -0.5, 0.5);
  DerivativeCheckOptions options;
  options.step = 1e-5;
  for (const DerivativeCheck& check :
       check_force_derivatives(force, q, v, Vector::Ones(q.size()), options)) {
    EXPECT_TRUE(check.passed()) << derivative_name(check.which) << ": " << check.relative_error();
  }
}

TEST(DragSpringForce, DerivativesMatchFiniteDifferences3D) {
  DragSpringForce force(3);
  force.grab(1, Eigen::Vector3d(0.3, -2.0, 0.7), 250.0);
  Vector q(9);
  q << 0.1, 0.2, 0.3, -0.4, 0.5, 0.9, 1.0, 1.1, -1.2;
  expect_drag_spring_derivatives_pass(force, q);
}

TEST(DragSpringForce, DerivativesMatchFiniteDifferences2D) {
  DragSpringForce force(2);
  force.grab(0, Eigen::Vector3d(0.3, -2.0, 99.0), 40.0);  // z is ignored in 2D
  Vector q(4);
  q << 0.1, 0.2, -0.4, 0.5;
  expect_drag_spring_derivatives_pass(force, q);
}

TEST(DragSpringForce, PullsTheGrabbedParticleTowardTheTarget) {
  DragSpringForce force(3);
  Vector q(6);
  q << 0.0, 0.0, 0.0, 1.0, 2.0, 3.0;
  const Vector zero = Vector::Zero(6);
  force.grab(1, Eigen::Vector3d(1.0, 0.0, 3.0), 10.0);
  Vector gradient = Vector::Zero(6);
  force.add_gradient({q, zero, zero}, gradient);
  Vector expected = Vector::Zero(6);
  expected[4] = 20.0;  // gradE = k (x - t): the force -20 N along y
  EXPECT_EQ(gradient, expected);
  double energy = 0.0;
  force.add_energy({q, zero, zero}, energy);
  EXPECT_DOUBLE_EQ(energy, 0.5 * 10.0 * 4.0);

  force.move_target(Eigen::Vector3d(1.0, 2.0, 3.0));
  gradient.setZero();
  force.add_gradient({q, zero, zero}, gradient);
  EXPECT_EQ(gradient, Vector::Zero(6));
}

TEST(DragSpringForce, AddsNothingUntilGrabbedAndAfterRelease) {
  DragSpringForce force(3);
  Vector q = Vector::Ones(6);
  const Vector zero = Vector::Zero(6);
  EXPECT_FALSE(force.active());
  EXPECT_EQ(force.particle(), -1);
  force.move_target(Eigen::Vector3d(5.0, 5.0, 5.0));  // ignored: nothing is grabbed
  EXPECT_FALSE(force.active());
  EXPECT_EQ(force.target(), Eigen::Vector3d::Zero());

  force.grab(0, Eigen::Vector3d::Zero(), 3.0);
  EXPECT_TRUE(force.active());
  EXPECT_EQ(force.particle(), 0);
  EXPECT_EQ(force.stiffness(), 3.0);

  force.release();
  Vector gradient = Vector::Zero(6);
  HessianBuilder hessian;
  double energy = 0.0;
  force.add_gradient({q, zero, zero}, gradient);
  force.add_hessian_x({q, zero, zero}, hessian);
  force.add_energy({q, zero, zero}, energy);
  EXPECT_EQ(gradient, Vector::Zero(6));
  EXPECT_TRUE(hessian.triplets().empty());
  EXPECT_EQ(energy, 0.0);
  EXPECT_EQ(force.particle(), -1);
}

}  // namespace
}  // namespace fosssim
