// Tests of DragDampingForce (docs/forces.md) in 2D and 3D.
//
// Math checked: F_p = -b v_p on every particle, no energy, hessX = 0, hessV = b I (symmetric);
// the derivatives against differences of gradE by the library checker and the full-matrix
// check on random configurations.

#include "core/forces/drag_damping_force.h"

#include <gtest/gtest.h>

#include "support/dense.h"
#include "support/finite_differences.h"
#include "support/random.h"
#include "support/typed_tests.h"

namespace fosssim::testing {
namespace {

FOSSSIM_TEST_SUITE_IN_2D_AND_3D(DragDampingForceTest);

TYPED_TEST(DragDampingForceTest, ForceOpposesVelocityAndHessVIsBI) {
  constexpr int D = TypeParam::value;
  Random random(61);
  const Vector q = random.uniform_vector(2 * D, -1.0, 1.0);
  const Vector v = random.uniform_vector(2 * D, -1.0, 1.0);
  const Vector mass = random.uniform_vector(2 * D, 0.5, 2.0);
  const DragDampingForce<D> drag(0.3);
  EXPECT_TRUE(gradient_of(drag, q, v, mass).isApprox(Vector(0.3 * v), 1e-16));
  EXPECT_EQ(energy_of(drag, q, v, mass), 0.0);
  EXPECT_FALSE(drag.is_conservative());
  EXPECT_TRUE(hessian_x_of(drag, q, v, mass).isZero(0.0));
  EXPECT_EQ(hessian_v_of(drag, q, v, mass), 0.3 * Eigen::MatrixXd::Identity(2 * D, 2 * D));
}

TYPED_TEST(DragDampingForceTest, DerivativesOnRandomConfigurations) {
  constexpr int D = TypeParam::value;
  for (unsigned seed = 62; seed <= 65; ++seed) {
    Random random(seed);
    const DragDampingForce<D> drag(random.uniform(0.0, 3.0));
    check_force_everywhere(drag, D, random.uniform_vector(3 * D, -1.0, 1.0),
                           random.uniform_vector(3 * D, -1.0, 1.0),
                           random.uniform_vector(3 * D, 0.5, 2.0),
                           {"dragdamping", "random", "seed " + std::to_string(seed)});
  }
}

}  // namespace
}  // namespace fosssim::testing
