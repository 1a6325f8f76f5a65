// Tests of ElasticBodySpringForce (docs/forces.md, 'Elastic bodies') in 2D and 3D.
//
// Math checked:
// - values: the spring of SPEC-elastica's worked example E1 (α = 3, l0 = 1, l = 1.3): U = 0.135,
//   F_0 = (0.83076923076923082, 0.3461538461538462) to the bit, in the course's evaluation
//   order, and hessX = k [P + (1 - l0/l)(I - P)] in the pair pattern;
// - the stiffness is α / l0, not α: doubling l0 at a fixed stretch halves the force;
// - derivatives by finite differences on random configurations and on nasty ones: nearly
//   coincident particles (l = 1e-3, 1e-4, where 1 - l0/l is large and negative), a spring at
//   its rest length (F = 0), and a long stretch;
// - the definite Hessian drops the negative transverse stiffness of a compressed spring and
//   only that.

#include "core/forces/elastic_body_spring_force.h"

#include <gtest/gtest.h>

#include "core/force_evaluation.h"
#include "core/text.h"
#include "support/dense.h"
#include "support/finite_differences.h"
#include "support/random.h"
#include "support/typed_tests.h"

namespace fosssim::testing {
namespace {

FOSSSIM_TEST_SUITE_IN_2D_AND_3D(ElasticBodySpringForceTest);

/// Particles 0 at the origin and 1 at (1.2, 0.5) (z = 0), unit masses, at rest.
template <int D>
Vector worked_example_positions() {
  Vector q = Vector::Zero(2 * D);
  q[D] = 1.2;
  q[D + 1] = 0.5;
  return q;
}

TYPED_TEST(ElasticBodySpringForceTest, MatchesTheWorkedExampleToTheBit) {
  constexpr int D = TypeParam::value;
  const Vector q = worked_example_positions<D>();
  const Vector v = Vector::Zero(2 * D);
  const Vector mass = Vector::Ones(2 * D);
  const ElasticBodySpringForce<D> spring(0, 1, 3.0, 1.0);
  const Vector g = gradient_of(spring, q, v, mass);
  // F_0 = -∇_0 U; SPEC-elastica E1 gives these to 17 digits, bit-identical to the course.
  EXPECT_EQ(-g[0], 0.83076923076923082);
  EXPECT_EQ(-g[1], 0.3461538461538462);
  EXPECT_EQ(g[D], 0.83076923076923082);
  EXPECT_EQ(g[D + 1], 0.3461538461538462);
  EXPECT_NEAR(energy_of(spring, q, v, mass), 0.135, 1e-15);
  // hessX block: k = 3, l = 1.3, n = (12, 5)/13, 1 - l0/l = 3/13.
  Eigen::MatrixXd n = Eigen::MatrixXd::Zero(D, 1);
  n(0, 0) = 12.0 / 13.0;
  n(1, 0) = 5.0 / 13.0;
  const Eigen::MatrixXd P = n * n.transpose();
  const Eigen::MatrixXd block =
      3.0 * (P + (3.0 / 13.0) * (Eigen::MatrixXd::Identity(D, D) - P));
  EXPECT_TRUE(hessian_x_of(spring, q, v, mass).isApprox(dense_pair_pattern(2 * D, D, 0, 1, block),
                                                        1e-14));
  EXPECT_TRUE(hessian_v_of(spring, q, v, mass).isZero(0.0));
}

TYPED_TEST(ElasticBodySpringForceTest, StiffnessIsTheModulusOverTheRestLength) {
  constexpr int D = TypeParam::value;
  const Vector v = Vector::Zero(2 * D);
  const Vector mass = Vector::Ones(2 * D);
  Vector q = Vector::Zero(2 * D);
  q[D] = 1.5;  // stretch 0.5 from l0 = 1
  const double short_rest = gradient_of(ElasticBodySpringForce<D>(0, 1, 4.0, 1.0), q, v, mass)[0];
  q[D] = 2.5;  // stretch 0.5 from l0 = 2
  const double long_rest = gradient_of(ElasticBodySpringForce<D>(0, 1, 4.0, 2.0), q, v, mass)[0];
  EXPECT_DOUBLE_EQ(short_rest, -2.0);  // ∇_0 U = k (l - l0) n, n = (-1, 0): -4 · 0.5
  EXPECT_DOUBLE_EQ(long_rest, -1.0);
}

TYPED_TEST(ElasticBodySpringForceTest, DerivativesOnRandomConfigurations) {
  constexpr int D = TypeParam::value;
  for (unsigned seed = 71; seed <= 76; ++seed) {
    Random random(seed);
    const PairCase c = random_pair_case(D, random);
    const ElasticBodySpringForce<D> spring(c.i, c.j, random.uniform(0.5, 50.0),
                                           random.uniform(0.1, 2.0));
    check_force_everywhere(spring, D, c.q, c.v, c.mass,
                           {"elastic-spring", "random", "seed " + std::to_string(seed)});
    EXPECT_LE(asymmetry(hessian_x_of(spring, c.q, c.v, c.mass)), 1e-14);
  }
}

TYPED_TEST(ElasticBodySpringForceTest, DerivativesOfNearlyCoincidentAndLongSprings) {
  constexpr int D = TypeParam::value;
  Random random(77);
  for (double l : {1e-3, 1e-4, 0.7, 1.0, 40.0}) {
    const PairCase c = pair_at_distance(D, random, l);
    const ElasticBodySpringForce<D> spring(0, 1, 2.0, 0.7);
    const std::string configuration = l == 0.7 ? kAtRest : "near-degenerate";
    check_force_everywhere(spring, D, c.q, c.v, c.mass,
                           {"elastic-spring", configuration, "l = " + to_text(l)});
    EXPECT_TRUE(gradient_of(spring, c.q, c.v, c.mass).allFinite());
  }
}

TYPED_TEST(ElasticBodySpringForceTest, DefiniteHessianDropsOnlyTheCompressedTransverseTerm) {
  constexpr int D = TypeParam::value;
  const Vector v = Vector::Zero(2 * D);
  const Vector mass = Vector::Ones(2 * D);
  Vector q = Vector::Zero(2 * D);
  q[D] = 0.5;  // compressed: l = 0.5 < l0 = 1, n = (1, 0)
  const ElasticBodySpringForce<D> spring(0, 1, 2.0, 1.0);
  HessianBuilder exact_builder;
  HessianBuilder definite_builder;
  spring.add_hessian_x({q, v, mass, false}, exact_builder);
  spring.add_hessian_x({q, v, mass, true}, definite_builder);
  const Eigen::MatrixXd exact = dense(exact_builder.build(2 * D));
  const Eigen::MatrixXd definite = dense(definite_builder.build(2 * D));
  EXPECT_DOUBLE_EQ(exact(1, 1), -2.0);    // k (1 - l0/l) = 2 · (1 - 2)
  EXPECT_DOUBLE_EQ(definite(1, 1), 0.0);  // clamped
  EXPECT_DOUBLE_EQ(definite(0, 0), 2.0);  // the axial stiffness k stays
  EXPECT_DOUBLE_EQ(exact(0, 0), 2.0);
}

}  // namespace
}  // namespace fosssim::testing
