// Tests of GravitationalForce (docs/forces.md) in 2D and 3D.
//
// Math checked:
// - values: U = -G m_i m_j / l, F_i = (G m_i m_j / l²) n, F_j = -F_i on a 3-4-5 triangle worked
//   out by hand, and hessX = (G m_i m_j / l³)(I - 3P) in the pair pattern;
// - derivatives by finite differences (library checker and full-matrix check): gradE against U,
//   hessX and hessV (= 0) against gradE, on random configurations (random positions, masses, G;
//   several seeds) and on nearly coincident particles, l = 1e-4, 1e-5, 1e-6, where the force
//   grows like 1/l² and hessX like 1/l³;
// - symmetry: hessX is symmetric to round-off, as has_symmetric_jacobians() claims.

#include "core/forces/gravitational_force.h"

#include <gtest/gtest.h>

#include "core/text.h"
#include "support/dense.h"
#include "support/finite_differences.h"
#include "support/random.h"
#include "support/typed_tests.h"

namespace fosssim::testing {
namespace {

FOSSSIM_TEST_SUITE_IN_2D_AND_3D(GravitationalForceTest);

TYPED_TEST(GravitationalForceTest, ForceEnergyAndHessianMatchTheFormulaOnA345Triangle) {
  constexpr int D = TypeParam::value;
  Vector q = Vector::Zero(2 * D);
  q[D] = 3.0;
  q[D + 1] = 4.0;  // l = 5, n = (0.6, 0.8)
  const Vector v = Vector::Zero(2 * D);
  Vector mass(2 * D);
  mass << Vector::Constant(D, 2.0), Vector::Constant(D, 3.0);
  const GravitationalForce<D> gravity(0, 1, 0.5);
  // G m_i m_j = 3: F_i = 3/25 (0.6, 0.8) = (0.072, 0.096), U = -3/5.
  const Vector g = gradient_of(gravity, q, v, mass);
  EXPECT_NEAR(g[0], -0.072, 1e-16);
  EXPECT_NEAR(g[1], -0.096, 1e-16);
  EXPECT_NEAR(g[D], 0.072, 1e-16);
  EXPECT_NEAR(g[D + 1], 0.096, 1e-16);
  EXPECT_NEAR(energy_of(gravity, q, v, mass), -0.6, 1e-15);
  // hessX block = (3/125)(I - 3P), P = [[0.36, 0.48], [0.48, 0.64]] (zero in z).
  Eigen::MatrixXd block = Eigen::MatrixXd::Identity(D, D);
  block.topLeftCorner(2, 2) -= 3.0 * (Eigen::Matrix2d() << 0.36, 0.48, 0.48, 0.64).finished();
  block *= 3.0 / 125.0;
  EXPECT_TRUE(
      hessian_x_of(gravity, q, v, mass).isApprox(dense_pair_pattern(2 * D, D, 0, 1, block), 1e-15));
  EXPECT_TRUE(hessian_v_of(gravity, q, v, mass).isZero(0.0));
  EXPECT_TRUE(gravity.is_conservative());
}

TYPED_TEST(GravitationalForceTest, DerivativesOnRandomConfigurations) {
  constexpr int D = TypeParam::value;
  for (unsigned seed = 31; seed <= 36; ++seed) {
    Random random(seed);
    const PairCase c = random_pair_case(D, random);
    const GravitationalForce<D> gravity(c.i, c.j, random.uniform(0.1, 5.0));
    check_force_everywhere(gravity, D, c.q, c.v, c.mass,
                           {"gravitation", "random", "seed " + std::to_string(seed)});
    EXPECT_LE(asymmetry(hessian_x_of(gravity, c.q, c.v, c.mass)), 1e-15);
  }
}

TYPED_TEST(GravitationalForceTest, DerivativesOfNearlyCoincidentParticles) {
  constexpr int D = TypeParam::value;
  Random random(37);
  for (double l : {1e-4, 1e-5, 1e-6}) {
    PairCase c = pair_at_distance(D, random, l);
    c.mass = random.uniform_vector(3 * D, 0.5, 2.0);
    const GravitationalForce<D> gravity(1, 0, 0.3);
    check_force_everywhere(gravity, D, c.q, c.v, c.mass,
                           {"gravitation", "near-degenerate", "l = " + to_text(l)});
    EXPECT_LE(asymmetry(hessian_x_of(gravity, c.q, c.v, c.mass)), 1e-15);
  }
}

}  // namespace
}  // namespace fosssim::testing
