// SpringSetForce: the same physics as one SpringForce per spring, with exact derivatives.

#include "core/forces/spring_set_force.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "core/analysis/derivative_check.h"
#include "core/forces/spring_force.h"

namespace fosssim {
namespace {

/// Random springs among n particles at random positions and velocities.
struct RandomSprings {
  Vector q, v, mass;
  std::vector<SpringTerm> springs;
};

RandomSprings random_springs(int dim, int n, int count, bool damped, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  RandomSprings out;
  out.q = Vector::NullaryExpr(dim * n, [&] { return uniform(rng); });
  out.v = Vector::NullaryExpr(dim * n, [&] { return uniform(rng); });
  out.mass = Vector::Constant(dim * n, 1.0);
  std::uniform_int_distribution<int> particle(0, n - 1);
  while (static_cast<int>(out.springs.size()) < count) {
    const int i = particle(rng), j = particle(rng);
    if (i == j) continue;
    const double k = 1.0 + 99.0 * (0.5 + 0.5 * uniform(rng));
    const double l0 = 0.1 + 1.5 * (0.5 + 0.5 * uniform(rng));  // some stretched, some compressed
    const double b = damped ? 0.5 + 0.5 * uniform(rng) : 0.0;
    out.springs.push_back({i, j, k, l0, b});
  }
  return out;
}

template <int D>
void expect_spring_set_derivatives_pass(const Force& force, const Vector& q, const Vector& v,
                                        const Vector& mass) {
  DerivativeCheckOptions options;
  options.step = suggest_finite_difference_step(q, D);
  for (const DerivativeCheck& check : check_force_derivatives(force, q, v, mass, options)) {
    EXPECT_TRUE(check.passed()) << check.force << " " << derivative_name(check.which)
                                << ": relative error " << check.relative_error();
  }
}

template <int D>
void check_random(bool damped) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const RandomSprings r = random_springs(D, 6, 9, damped, seed);
    const SpringSetForce<D> force(r.springs, "random");
    expect_spring_set_derivatives_pass<D>(force, r.q, r.v, r.mass);
  }
}

TEST(SpringSetForce, DerivativesMatchFiniteDifferences2D) { check_random<2>(false); }
TEST(SpringSetForce, DerivativesMatchFiniteDifferences3D) { check_random<3>(false); }
TEST(SpringSetForce, DampedDerivativesMatchFiniteDifferences2D) { check_random<2>(true); }
TEST(SpringSetForce, DampedDerivativesMatchFiniteDifferences3D) { check_random<3>(true); }

TEST(SpringSetForce, DerivativesHoldForNearlyCoincidentEnds) {
  // A 1e-7 m long spring of rest length 1 and a zero-rest-length spring at 1e-7 m.
  Vector q(9);
  q << 0.0, 0.0, 0.0, 1e-7, 0.3e-7, -0.2e-7, 1.0, 1.0, 1.0;
  const Vector v = Vector::LinSpaced(9, -1.0, 1.0);
  const SpringSetForce<3> force(
      {{0, 1, 10.0, 1.0, 0.0}, {1, 2, 5.0, 0.0, 0.0}, {0, 2, 3.0, 0.5, 0.7}}, "nasty");
  DerivativeCheckOptions options;
  options.step = 1e-11;
  for (const DerivativeCheck& check :
       check_force_derivatives(force, q, v, Vector::Ones(9), options)) {
    EXPECT_TRUE(check.passed()) << derivative_name(check.which) << ": " << check.relative_error();
  }
}

/// Sums of one SpringForce per spring, to compare against the set.
template <int D>
struct Separate {
  std::vector<std::unique_ptr<Force>> forces;
  explicit Separate(const std::vector<SpringTerm>& springs) {
    for (const SpringTerm& s : springs)
      forces.push_back(std::make_unique<SpringForce<D>>(s.i, s.j, s.k, s.l0, s.b));
  }
};

template <int D>
void expect_same_as_separate_springs() {
  const RandomSprings r = random_springs(D, 7, 12, true, 42);
  const SpringSetForce<D> set(r.springs, "set");
  const Separate<D> separate(r.springs);
  const ForceInput in{r.q, r.v, r.mass};
  double e_set = 0.0, e_sep = 0.0;
  Vector g_set = Vector::Zero(r.q.size()), g_sep = g_set;
  HessianBuilder hx_set, hx_sep, hv_set, hv_sep;
  set.add_energy(in, e_set);
  set.add_gradient(in, g_set);
  set.add_hessian_x(in, hx_set);
  set.add_hessian_v(in, hv_set);
  for (const auto& f : separate.forces) {
    f->add_energy(in, e_sep);
    f->add_gradient(in, g_sep);
    f->add_hessian_x(in, hx_sep);
    f->add_hessian_v(in, hv_sep);
  }
  // Same formulas in the same order: identical bits, not just close.
  EXPECT_EQ(e_set, e_sep);
  EXPECT_EQ(g_set, g_sep);
  const int n = static_cast<int>(r.q.size());
  EXPECT_EQ(Eigen::MatrixXd(hx_set.build(n)), Eigen::MatrixXd(hx_sep.build(n)));
  EXPECT_EQ(Eigen::MatrixXd(hv_set.build(n)), Eigen::MatrixXd(hv_sep.build(n)));
}

TEST(SpringSetForce, EqualsOneSpringForcePerSpring2D) { expect_same_as_separate_springs<2>(); }
TEST(SpringSetForce, EqualsOneSpringForcePerSpring3D) { expect_same_as_separate_springs<3>(); }

TEST(SpringSetForce, ProjectedHessianIsPositiveSemiDefiniteAndExactWhenStretched) {
  Vector q(6);
  q << 0.0, 0.0, 0.0, 0.6, 0.0, 0.0;
  const Vector zero = Vector::Zero(6);
  for (double l0 : {1.0, 0.3}) {  // compressed, then stretched
    const SpringSetForce<3> force({{0, 1, 100.0, l0, 0.0}}, "one");
    HessianBuilder exact, projected;
    force.add_hessian_x({q, zero, zero}, exact);
    force.add_hessian_x({q, zero, zero, /*definite_hessian=*/true}, projected);
    const Eigen::MatrixXd He(exact.build(6)), Hp(projected.build(6));
    const double min_exact =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(He).eigenvalues().minCoeff();
    const double min_projected =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Hp).eigenvalues().minCoeff();
    EXPECT_GE(min_projected, -1e-12);
    if (l0 > 0.6) {
      EXPECT_LT(min_exact, -1.0) << "a compressed spring's exact Hessian is indefinite";
    } else {
      EXPECT_EQ(He, Hp);
    }
  }
}

TEST(SpringSetForce, DescribesItsSpringsForTheLocalGlobalSolver) {
  const std::vector<SpringTerm> springs = {{0, 1, 2.0, 0.5, 0.1}, {1, 2, 3.0, 0.25, 0.0}};
  const SpringSetForce<3> force(springs, "pair");
  const std::vector<SpringTerm>& described = force.springs();
  ASSERT_EQ(described.size(), 2u);
  EXPECT_EQ(described[1].j, 2);
  EXPECT_EQ(described[0].b, 0.1);
  EXPECT_FALSE(force.is_conservative());
  EXPECT_FALSE(force.has_symmetric_jacobians());
  EXPECT_TRUE(SpringSetForce<3>({springs[1]}, "undamped").has_symmetric_jacobians());
}

}  // namespace
}  // namespace fosssim
