// Tests of ElasticBodyBendingForce (docs/forces.md, 'Elastic bodies'), a 2D force.
//
// Math checked:
// - values: the hinge of SPEC-elastica's worked example E2 (θ = 1.0121970114513341, L =
//   1.9433981132056606) and the folded hinge of E5 (θ = -3.1 against θ0 = 3.0, no wrapping),
//   forces to the course's 17 digits (within 4 ulp);
// - the angle's sign and range: counter-clockwise turns are positive, a straight line is 0, a
//   fold is ±π;
// - derivatives by finite differences (gradient against U, hessX against the gradient, hessV = 0)
//   on random hinges and on nasty ones: straight (θ = 0), folded just inside ±π on each side of
//   the branch cut, very short and very unequal edges, θ0 far from θ;
// - the energy's jump across θ = ±π, which the course's program has and FOSSSim keeps;
// - the semi-definite Hessian (ForceInput::definite_hessian): on random hinges and hinges at
//   θ = 0 and near ±π its eigenvalues are the exact block's with the negative ones set to 0 (so
//   it is semi-definite, xᵀHx ≥ 0, and differs from an indefinite exact block); at θ = θ0 the
//   exact block (α/L) ∇θ ∇θᵀ is already semi-definite and is kept.

#include "core/forces/elastic_body_bending_force.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/force_evaluation.h"
#include "core/text.h"
#include "support/dense.h"
#include "support/finite_differences.h"
#include "support/random.h"

namespace fosssim::testing {
namespace {

constexpr double kPi = std::numbers::pi;

Vector three_points(double x0, double y0, double x1, double y1, double x2, double y2) {
  Vector q(6);
  q << x0, y0, x1, y1, x2, y2;
  return q;
}

/// A hinge at the origin between edges of lengths a (incoming, along +x) and b, turning by θ.
Vector hinge_with_angle(double a, double b, double theta) {
  return three_points(-a, 0.0, 0.0, 0.0, b * std::cos(theta), b * std::sin(theta));
}

double rest_length(const Vector& q) {
  return (q.segment<2>(2) - q.segment<2>(0)).norm() + (q.segment<2>(4) - q.segment<2>(2)).norm();
}

void expect_close_bits(double actual, double expected) {
  EXPECT_NEAR(actual, expected, 4.0 * std::abs(expected) * 2.3e-16) << "expected " << expected;
}

TEST(ElasticBodyBendingForceTest, MatchesWorkedExampleE2) {
  const Vector q = three_points(0.0, 0.0, 1.0, 0.0, 1.5, 0.8);
  const Vector v = Vector::Zero(6);
  const Vector mass = Vector::Ones(6);
  const double L = rest_length(q);
  EXPECT_DOUBLE_EQ(L, 1.9433981132056606);
  const ElasticBodyBendingForce bending(0, 1, 2, 2.0, 0.5, L);
  EXPECT_DOUBLE_EQ(bending.angle(q), 1.0121970114513341);
  const Vector F = -gradient_of(bending, q, v, mass);
  const double expected[6] = {0, -0.52711485924668156, -0.47381110943521937,
                              0.82324680264369365, 0.47381110943521937, -0.2961319433970121};
  for (int k = 0; k < 6; ++k) expect_close_bits(F[k], expected[k]);
}

TEST(ElasticBodyBendingForceTest, ItsElementForPicturesIsTheHingeWithItsAngleAndDensity) {
  // E2's hinge: θ - θ0 = 1.0121970114513341 - 0.5, density U / L = α (θ - θ0)² / (2 L²).
  const Vector q = three_points(0.0, 0.0, 1.0, 0.0, 1.5, 0.8);
  const double L = rest_length(q);
  const ElasticBodyBendingForce bending(0, 1, 2, 2.0, 0.5, L);
  std::vector<ForceElement> elements;
  bending.append_elements(q, elements);
  ASSERT_EQ(elements.size(), 1u);
  EXPECT_EQ(elements[0].kind, ForceElement::Kind::kHinge);
  EXPECT_EQ(elements[0].particles, (std::array<int, 3>{0, 1, 2}));
  EXPECT_DOUBLE_EQ(elements[0].strain, 1.0121970114513341 - 0.5);
  double energy = 0.0;
  const Vector none = Vector::Zero(6);
  bending.add_energy(ForceInput{q, none, none}, energy);
  EXPECT_DOUBLE_EQ(elements[0].energy_density, energy / L);
}

TEST(ElasticBodyBendingForceTest, MatchesWorkedExampleE5WithoutWrapping) {
  const Vector q = three_points(-1.0, 0.0, 0.0, 0.0, -0.9991351502732795, -0.04158066243329049);
  const Vector v = Vector::Zero(6);
  const Vector mass = Vector::Ones(6);
  const ElasticBodyBendingForce bending(0, 1, 2, 1.0, 3.0, rest_length(q));
  EXPECT_DOUBLE_EQ(bending.angle(q), -3.1000000000000001);
  const Vector F = -gradient_of(bending, q, v, mass);
  const double expected[6] = {0, 3.0499999999999998, -0.12682102042153598,
                              -0.0026377916664975798, 0.12682102042153598, -3.0473622083335021};
  for (int k = 0; k < 6; ++k) expect_close_bits(F[k], expected[k]);
  // U = α (θ - θ0)² / (2L) with θ - θ0 = -6.1 and L = 2.
  EXPECT_NEAR(energy_of(bending, q, v, mass), 6.1 * 6.1 / 4.0, 1e-13);
}

TEST(ElasticBodyBendingForceTest, AngleIsTheSignedTurnFromTheFirstEdgeToTheSecond) {
  const ElasticBodyBendingForce bending(0, 1, 2, 1.0, 0.0, 2.0);
  EXPECT_EQ(bending.angle(three_points(-1, 0, 0, 0, 1, 0)), 0.0);
  EXPECT_NEAR(bending.angle(three_points(-1, 0, 0, 0, 0, 1)), kPi / 2, 1e-15);   // left turn
  EXPECT_NEAR(bending.angle(three_points(-1, 0, 0, 0, 0, -1)), -kPi / 2, 1e-15); // right turn
  EXPECT_NEAR(std::abs(bending.angle(three_points(-1, 0, 0, 0, -1, 0))), kPi, 1e-15);
}

TEST(ElasticBodyBendingForceTest, EnergyJumpsAcrossTheFoldAsTheCourseDoes) {
  const Vector v = Vector::Zero(6);
  const Vector mass = Vector::Ones(6);
  const ElasticBodyBendingForce bending(0, 1, 2, 1.0, 3.0, 2.0);
  const double below = energy_of(bending, hinge_with_angle(1, 1, kPi - 1e-6), v, mass);
  const double above = energy_of(bending, hinge_with_angle(1, 1, -kPi + 1e-6), v, mass);
  EXPECT_NEAR(below, std::pow(kPi - 1e-6 - 3.0, 2) / 4.0, 1e-12);
  EXPECT_NEAR(above, std::pow(-kPi + 1e-6 - 3.0, 2) / 4.0, 1e-12);
  EXPECT_GT(above - below, 9.0);  // (−π − 3)² − (π − 3)², over 4
}

TEST(ElasticBodyBendingForceTest, DerivativesOnRandomHinges) {
  for (unsigned seed = 81; seed <= 88; ++seed) {
    Random random(seed);
    Vector q = random.uniform_vector(8, -1.0, 1.0);  // particle 3 is a bystander
    const Vector v = random.uniform_vector(8, -1.0, 1.0);
    const Vector mass = random.uniform_vector(8, 0.5, 2.0);
    const ElasticBodyBendingForce bending(2, 0, 3, random.uniform(0.1, 10.0),
                                          random.uniform(-3.0, 3.0), random.uniform(0.5, 3.0));
    check_force_everywhere(bending, 2, q, v, mass,
                           {"elastic-bending", "random", "seed " + std::to_string(seed)});
    EXPECT_LE(asymmetry(hessian_x_of(bending, q, v, mass)), 1e-12);
    EXPECT_TRUE(hessian_v_of(bending, q, v, mass).isZero(0.0));
  }
}

TEST(ElasticBodyBendingForceTest, DerivativesOnNastyHinges) {
  const Vector v = Vector::Zero(6);
  const Vector mass = Vector::Ones(6);
  struct Case {
    double a, b, theta, theta0;
    const char* name;
  };
  const Case cases[] = {
      {1.0, 1.0, 0.0, 0.3, "straight"},
      {1.0, 0.7, 0.0, 0.0, "straight-at-rest"},
      {1.0, 1.0, kPi - 1e-3, 0.0, "fold below +pi"},
      {1.0, 1.0, -kPi + 1e-3, 0.0, "fold above -pi"},
      {0.8, 1.3, kPi - 1e-3, 3.0, "fold below +pi, theta0 = 3"},
      {0.8, 1.3, -kPi + 1e-3, 3.0, "fold above -pi, theta0 = 3"},
      {1e-3, 1.0, 1.0, 0.0, "short first edge"},
      {1.0, 1e-4, -2.0, 0.5, "short second edge"},
      {1e-4, 1e-4, 0.5, -0.5, "both edges short"},
  };
  for (const Case& c : cases) {
    const Vector q = hinge_with_angle(c.a, c.b, c.theta);
    const ElasticBodyBendingForce bending(0, 1, 2, 1.5, c.theta0, 2.0);
    const bool at_rest = c.theta == c.theta0;
    check_force_everywhere(bending, 2, q, v, mass,
                           {"elastic-bending", at_rest ? kAtRest : "near-degenerate", c.name});
    EXPECT_TRUE(hessian_x_of(bending, q, v, mass).allFinite()) << c.name;
  }
}

TEST(ElasticBodyBendingForceTest, DefiniteHessianIsTheExactBlockWithNegativeEigenvaluesClamped) {
  struct Case {
    double a, b, theta, theta0;
    const char* name;
  };
  // Each exact block is indefinite: θ ≠ θ0 gives (θ - θ0) ∇²θ, whose blocks are trace-free.
  const Case cases[] = {
      {1.0, 1.0, 0.0, 0.5, "straight, bent at rest"},
      {1.0, 0.7, 0.0, -1.0, "straight, bent the other way at rest"},
      {1.0, 1.0, kPi - 1e-3, 0.0, "fold below +pi"},
      {1.0, 1.0, -kPi + 1e-3, 0.0, "fold above -pi"},
      {0.8, 1.3, kPi, 0.0, "fold at pi"},
      {0.8, 1.3, -kPi + 1e-3, 3.0, "fold above -pi, theta0 = 3"},
      {1e-3, 1.0, 1.0, 0.0, "short first edge"},
  };
  for (const Case& c : cases) {
    const Vector q = hinge_with_angle(c.a, c.b, c.theta);
    const ElasticBodyBendingForce bending(0, 1, 2, 1.5, c.theta0, 2.0);
    const Eigen::MatrixXd exact = hessian_x_of(bending, q, Vector::Zero(6), Vector::Ones(6));
    const Eigen::MatrixXd projected =
        definite_hessian_x_of(bending, q, Vector::Zero(q.size()), Vector::Ones(q.size()));
    EXPECT_LT(expect_semidefinite_projection(exact, projected, c.name), -1e-3)
        << c.name << ": the case should test a projection";
    EXPECT_GT((projected - exact).norm(), 1e-3 * exact.norm()) << c.name;
  }
  for (unsigned seed = 81; seed <= 88; ++seed) {
    Random random(seed);
    const Vector q = random.uniform_vector(8, -1.0, 1.0);  // particle 3 is a bystander
    const ElasticBodyBendingForce bending(2, 0, 3, random.uniform(0.1, 10.0),
                                          random.uniform(-3.0, 3.0), random.uniform(0.5, 3.0));
    const Eigen::MatrixXd exact = hessian_x_of(bending, q, Vector::Zero(8), Vector::Ones(8));
    expect_semidefinite_projection(
        exact, definite_hessian_x_of(bending, q, Vector::Zero(q.size()), Vector::Ones(q.size())),
        "random, seed " + std::to_string(seed));
  }
}

TEST(ElasticBodyBendingForceTest, DefiniteHessianAtTheRestAngleIsTheExactOne) {
  for (const double theta : {0.0, 1.0, -2.5}) {
    const Vector q = hinge_with_angle(1.0, 0.6, theta);
    const ElasticBodyBendingForce bending(0, 1, 2, 1.5, theta, 2.0);
    const Eigen::MatrixXd exact = hessian_x_of(bending, q, Vector::Zero(6), Vector::Ones(6));
    const Eigen::MatrixXd projected =
        definite_hessian_x_of(bending, q, Vector::Zero(q.size()), Vector::Ones(q.size()));
    EXPECT_LE((projected - exact).cwiseAbs().maxCoeff(), 1e-12 * exact.norm()) << theta;
    EXPECT_GT(exact.norm(), 0.0);
  }
}

}  // namespace
}  // namespace fosssim::testing
