// Tests of ConstantForce (docs/forces.md) in 2D and 3D.
//
// Math checked: F_p = f on every particle whatever its mass, U = -Σ f·x_p, both Hessians zero;
// gradE against U and zero Hessians against differences of gradE by the library checker and the
// full-matrix check on random configurations.

#include "core/forces/constant_force.h"

#include <gtest/gtest.h>

#include "support/dense.h"
#include "support/finite_differences.h"
#include "support/random.h"
#include "support/typed_tests.h"

namespace fosssim::testing {
namespace {

FOSSSIM_TEST_SUITE_IN_2D_AND_3D(ConstantForceTest);

TYPED_TEST(ConstantForceTest, SameForceOnEveryParticleWhateverItsMass) {
  constexpr int D = TypeParam::value;
  const Vec<D> f = Vec<D>::LinSpaced(D, 1.0, 2.0);
  Vector q = Vector::Zero(2 * D), v = Vector::Zero(2 * D), mass(2 * D);
  q.segment(D, D).setConstant(3.0);
  mass << Vector::Constant(D, 2.0), Vector::Constant(D, 7.0);
  const ConstantForce<D> force(f);
  const Vector gradient = gradient_of(force, q, v, mass);
  EXPECT_EQ(Vector(gradient.segment(0, D)), Vector(-f));
  EXPECT_EQ(Vector(gradient.segment(D, D)), Vector(-f));
  EXPECT_NEAR(energy_of(force, q, v, mass), -3.0 * f.sum(), 1e-15);
  EXPECT_TRUE(hessian_x_of(force, q, v, mass).isZero(0.0));
  EXPECT_TRUE(hessian_v_of(force, q, v, mass).isZero(0.0));
}

TYPED_TEST(ConstantForceTest, DerivativesOnRandomConfigurations) {
  constexpr int D = TypeParam::value;
  for (unsigned seed = 51; seed <= 54; ++seed) {
    Random random(seed);
    const ConstantForce<D> force(Vec<D>(random.uniform_vector(D, -5.0, 5.0)));
    check_force_everywhere(force, D, random.uniform_vector(3 * D, -1.0, 1.0),
                           random.uniform_vector(3 * D, -1.0, 1.0),
                           random.uniform_vector(3 * D, 0.5, 2.0),
                           {"constantforce", "random", "seed " + std::to_string(seed)});
  }
}

}  // namespace
}  // namespace fosssim::testing
