// Tests of SimpleGravityForce (docs/forces.md) in 2D and 3D.
//
// Math checked: F_p = m_p g (an acceleration, scaled by each particle's mass, fixed particles
// included), U = -Σ m_p g·x_p, both Hessians zero; gradE against U and zero Hessians against
// differences of gradE by the library checker and the full-matrix check on random
// configurations with unequal masses.

#include "core/forces/simple_gravity_force.h"

#include <gtest/gtest.h>

#include "support/dense.h"
#include "support/finite_differences.h"
#include "support/random.h"
#include "support/typed_tests.h"

namespace fosssim::testing {
namespace {

FOSSSIM_TEST_SUITE_IN_2D_AND_3D(SimpleGravityForceTest);

TYPED_TEST(SimpleGravityForceTest, ForceIsMassTimesAccelerationAndEnergyIsLinear) {
  constexpr int D = TypeParam::value;
  Vec<D> g = Vec<D>::Zero();
  g[1] = -9.81;
  g[0] = 0.5;
  Vector q = Vector::Zero(2 * D), v = Vector::Zero(2 * D), mass(2 * D);
  q[1] = 2.0;
  q[D] = 1.0;
  mass << Vector::Constant(D, 2.0), Vector::Constant(D, 0.25);
  const SimpleGravityForce<D> gravity(g);
  const Vector gradient = gradient_of(gravity, q, v, mass);
  EXPECT_TRUE(gradient.segment(0, D).isApprox(Vector(-2.0 * g), 1e-16));
  EXPECT_TRUE(gradient.segment(D, D).isApprox(Vector(-0.25 * g), 1e-16));
  // U = -(2 g·(0, 2) + 0.25 g·(1, 0)) = -(2·2·(-9.81) + 0.25·0.5) = 39.115.
  EXPECT_NEAR(energy_of(gravity, q, v, mass), 39.115, 1e-13);
  EXPECT_TRUE(hessian_x_of(gravity, q, v, mass).isZero(0.0));
  EXPECT_TRUE(hessian_v_of(gravity, q, v, mass).isZero(0.0));
}

TYPED_TEST(SimpleGravityForceTest, DerivativesOnRandomConfigurations) {
  constexpr int D = TypeParam::value;
  for (unsigned seed = 41; seed <= 44; ++seed) {
    Random random(seed);
    Vector mass(3 * D);
    for (int p = 0; p < 3; ++p) mass.segment(D * p, D).setConstant(random.uniform(0.1, 10.0));
    const SimpleGravityForce<D> gravity(Vec<D>(random.uniform_vector(D, -10.0, 10.0)));
    check_force_everywhere(gravity, D, random.uniform_vector(3 * D, -1.0, 1.0),
                           random.uniform_vector(3 * D, -1.0, 1.0), mass,
                           {"simplegravity", "random", "seed " + std::to_string(seed)});
  }
}

}  // namespace
}  // namespace fosssim::testing
