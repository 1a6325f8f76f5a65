// Tests of SpringForce (docs/forces.md) in 2D and 3D.
//
// Math checked:
// - values: F_i = k (l - l0) n + b (n·dv) n, F_j = -F_i, U = ½ k (l - l0)², on a 3-4-5 triangle
//   worked out by hand;
// - derivatives by finite differences: gradE against U (at v = 0), hessX = -dF/dq and
//   hessV = -dF/dv against central differences of gradE, with the library's checker and with the
//   full-matrix check of support/finite_differences.h, on random configurations (several seeds, b =
//   0 and b > 0) and on nasty ones: springs of length 1e-4..1e-6 (compressed with l0 = 1, stretched
//   with l0 = l/2, zero rest length), ordinary compressed and stretched springs, damping with
//   relative velocity parallel to the spring and zero relative velocity;
// - zero rest length with exactly coincident ends: F = k d = 0 and hessX = k I (pair pattern)
//   exactly, hessV = 0;
// - symmetry: b = 0 gives exactly symmetric hessX and hessV; b > 0 gives a hessX whose
//   asymmetry (b/l) [n dvᵀ (I - P) - (I - P) dv nᵀ] is of the size predicted by hand.

#include "core/forces/spring_force.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/text.h"
#include "support/dense.h"
#include "support/finite_differences.h"
#include "support/random.h"
#include "support/typed_tests.h"

namespace fosssim::testing {
namespace {

FOSSSIM_TEST_SUITE_IN_2D_AND_3D(SpringForceTest);

TYPED_TEST(SpringForceTest, ForceAndEnergyMatchTheFormulaOnA345Triangle) {
  constexpr int D = TypeParam::value;
  Vector q = Vector::Zero(2 * D), v = Vector::Zero(2 * D);
  q[D] = 3.0;
  q[D + 1] = 4.0;  // l = 5, n = (0.6, 0.8)
  v[D] = 1.0;      // dv = (1, 0), n·dv = 0.6
  const Vector mass = Vector::Ones(2 * D);
  const SpringForce<D> spring(0, 1, 2.0, 2.0, 0.5);
  // F_i = k (l - l0) n + b (n·dv) n = 6 (0.6, 0.8) + 0.3 (0.6, 0.8) = (3.78, 5.04).
  const Vector g = gradient_of(spring, q, v, mass);
  EXPECT_NEAR(g[0], -3.78, 1e-14);
  EXPECT_NEAR(g[1], -5.04, 1e-14);
  EXPECT_NEAR(g[D], 3.78, 1e-14);
  EXPECT_NEAR(g[D + 1], 5.04, 1e-14);
  if constexpr (D == 3) {
    EXPECT_EQ(g[2], 0.0);
  }
  EXPECT_NEAR(energy_of(spring, q, v, mass), 9.0, 1e-14);  // ½ · 2 · 3²
  EXPECT_FALSE(spring.is_conservative());
  EXPECT_TRUE(SpringForce<D>(0, 1, 2.0, 2.0, 0.0).is_conservative());
}

TYPED_TEST(SpringForceTest, DerivativesOnRandomConfigurations) {
  constexpr int D = TypeParam::value;
  for (unsigned seed = 1; seed <= 6; ++seed) {
    Random random(seed);
    const PairCase c = random_pair_case(D, random);
    const double k = random.uniform(0.1, 10.0);
    const double l0 = random.uniform(0.0, 2.0);
    const double b = random.uniform(0.1, 2.0);
    const std::string detail = "seed " + std::to_string(seed);
    check_force_everywhere(SpringForce<D>(c.i, c.j, k, l0, 0.0), D, c.q, c.v, c.mass,
                           {"spring", "random", detail});
    check_force_everywhere(SpringForce<D>(c.i, c.j, k, l0, b), D, c.q, c.v, c.mass,
                           {"spring(b>0)", "random", detail});
  }
}

TYPED_TEST(SpringForceTest, DerivativesOfVeryShortSprings) {
  constexpr int D = TypeParam::value;
  Random random(7);
  for (double l : {1e-4, 1e-5, 1e-6}) {
    const auto c = pair_at_distance(D, random, l);
    const std::string detail = "l = " + to_text(l);
    // Strongly compressed (l0 = 1 ≫ l), stretched (l0 = l/2), zero rest length.
    for (double l0 : {1.0, 0.5 * l, 0.0}) {
      check_force_everywhere(SpringForce<D>(0, 1, 3.0, l0, 0.0), D, c.q, c.v, c.mass,
                             {"spring", "near-degenerate", detail});
      check_force_everywhere(SpringForce<D>(0, 1, 3.0, l0, 0.7), D, c.q, c.v, c.mass,
                             {"spring(b>0)", "near-degenerate", detail});
    }
  }
}

TYPED_TEST(SpringForceTest, DerivativesOfCompressedAndStretchedSprings) {
  constexpr int D = TypeParam::value;
  Random random(8);
  const auto c = pair_at_distance(D, random, 1.0);
  for (double l0 : {1.7, 1.0 + 1e-9, 1.0, 0.3}) {
    const std::string detail = "l = 1, l0 = " + to_text(l0);
    // At l0 = l the gradient is round-off: checked against round-off, not recorded as relative.
    const std::string configuration = l0 == 1.0 ? kAtRest : "near-degenerate";
    check_force_everywhere(SpringForce<D>(0, 1, 5.0, l0, 0.0), D, c.q, c.v, c.mass,
                           {"spring", configuration, detail});
    check_force_everywhere(SpringForce<D>(0, 1, 5.0, l0, 1.3), D, c.q, c.v, c.mass,
                           {"spring(b>0)", configuration, detail});
  }
}

TYPED_TEST(SpringForceTest, DampingDerivativesWithCollinearAndZeroRelativeVelocity) {
  constexpr int D = TypeParam::value;
  Random random(9);
  auto c = pair_at_distance(D, random, 0.8);
  const Vector n = (c.q.segment(D, D) - c.q.segment(0, D)).normalized();
  for (double along : {2.0, -0.5, 0.0}) {
    // v_j - v_i = along · n: the damping hessX reduces to (b/l)(n·dv)(I - P).
    c.v.segment(D, D) = c.v.segment(0, D) + along * n;
    check_force_everywhere(SpringForce<D>(0, 1, 2.0, 0.5, 0.9), D, c.q, c.v, c.mass,
                           {"spring(b>0)", "near-degenerate", "dv = " + to_text(along) + " n"});
  }
}

TYPED_TEST(SpringForceTest, ZeroRestLengthWithCoincidentEndsHasHessianKI) {
  constexpr int D = TypeParam::value;
  Random random(10);
  const Vector c = random.uniform_vector(D, -1.0, 1.0);
  Vector q(3 * D);
  q << c, c, c + random.unit_vector(D);  // particles 0 and 1 coincide exactly
  const Vector v = random.uniform_vector(3 * D, -1.0, 1.0);
  const Vector mass = Vector::Ones(3 * D);
  const double k = 4.5;
  const SpringForce<D> spring(0, 1, k, 0.0, 0.0);

  EXPECT_TRUE(gradient_of(spring, q, v, mass).isZero(0.0));
  EXPECT_EQ(energy_of(spring, q, v, mass), 0.0);
  const Eigen::MatrixXd expected =
      dense_pair_pattern(3 * D, D, 0, 1, k * Eigen::MatrixXd::Identity(D, D));
  EXPECT_EQ(hessian_x_of(spring, q, v, mass), expected);
  EXPECT_TRUE(hessian_v_of(spring, q, v, mass).isZero(0.0));
  check_force_everywhere(spring, D, q, v, mass,
                         {"spring", "near-degenerate", "coincident, l0 = 0"});

  // Away from coincidence a zero-rest-length spring is linear: hessX = k I to round-off.
  q.segment(D, D) = c + 0.3 * random.unit_vector(D);
  EXPECT_TRUE(hessian_x_of(spring, q, v, mass).isApprox(expected, 1e-15));
}

TYPED_TEST(SpringForceTest, UndampedJacobiansAreSymmetricDampedHessXIsNot) {
  constexpr int D = TypeParam::value;
  for (unsigned seed = 11; seed <= 14; ++seed) {
    Random random(seed);
    auto c = pair_at_distance(D, random, random.uniform(0.5, 1.5));
    // Relative velocity with a component across the spring, where the damping hessX is not
    // symmetric.
    const Vector n0 = (c.q.segment(D, D) - c.q.segment(0, D)).normalized();
    Vector across = random.unit_vector(D);
    across = (across - across.dot(n0) * n0).normalized();
    c.v.segment(D, D) = c.v.segment(0, D) + random.uniform(-1.0, 1.0) * n0 + 0.7 * across;
    const SpringForce<D> undamped(0, 1, 3.0, 1.0, 0.0);
    const SpringForce<D> damped(0, 1, 3.0, 1.0, 0.8);
    ASSERT_TRUE(undamped.has_symmetric_jacobians());
    ASSERT_FALSE(damped.has_symmetric_jacobians());
    // Symmetric to round-off (b P is formed as (b n) nᵀ, so its mirror entries may differ in
    // the last bit).
    EXPECT_LE(asymmetry(hessian_x_of(undamped, c.q, c.v, c.mass)), 1e-15);
    EXPECT_LE(asymmetry(hessian_v_of(damped, c.q, c.v, c.mass)), 1e-15);

    // The antisymmetric part of the damping block is (b/2l)[n wᵀ - w nᵀ] with w = (I - P) dv;
    // as n ⊥ w its Frobenius norm is (b/2l)·√2|w|, and the pair pattern has four such blocks,
    // so ‖(H - Hᵀ)/2‖_F = 2·(b/2l)·√2|w| = √2 (b/l)|w|.
    const Vector d = c.q.segment(D, D) - c.q.segment(0, D);
    const Vector dv = c.v.segment(D, D) - c.v.segment(0, D);
    const double l = d.norm();
    const Vector n = d / l;
    const Vector w = dv - n.dot(dv) * n;
    const Eigen::MatrixXd H = hessian_x_of(damped, c.q, c.v, c.mass);
    const double antisymmetric = 0.5 * (H - H.transpose()).norm();
    EXPECT_NEAR(antisymmetric, std::sqrt(2.0) * (0.8 / l) * w.norm(), 1e-12 * H.norm());
    EXPECT_NEAR(w.norm(), 0.7, 1e-12);
    EXPECT_GT(asymmetry(H), 1e-3);  // thirteen orders above round-off: the asymmetry is real
  }
}

}  // namespace
}  // namespace fosssim::testing
