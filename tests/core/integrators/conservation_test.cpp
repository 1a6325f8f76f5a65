// Energy and momentum behaviour of the four Euler methods, in 2D and 3D.
//
// Math checked:
// - Kepler orbit (eccentricity 0.5, around a fixed sun, 100 periods, h = P/2000). Symplectic
//   Euler (kick with F(qⁿ), then drift with vⁿ⁺¹) is the flow of the splitting e^{hT} e^{hU},
//   which exactly conserves a modified energy H̃ = H - (h/2) v·F + O(h²). With the start at
//   perihelion, where v·F = 0, |H(t) - H(0)| ≤ (h/2) max|v·F| + O(h²), and on the orbit
//   |v·F| = G M m |ṙ|/r² with r = p/(1 + e cos θ), ṙ = √(GM/p) e sin θ, whose maximum is taken
//   over θ below. The relative oscillation stays under that bound (+10% for the O(h²) part),
//   equally in the first and the last period. Explicit Euler's energy, sampled each time the
//   planet crosses the perihelion direction, rises at every crossing, far beyond the bound.
// - Implicit and linearized implicit Euler dissipate on undamped springs: for a quadratic
//   potential ½ qᵀK q (zero-rest-length springs, a fixed anchor) backward Euler gives
//   E' - E = -½ ΔvᵀMΔv - ½ ΔqᵀKΔq < 0 at every step, and both methods are backward Euler on
//   linear systems; implicit Euler also on a nonlinear spring moving radially (U convex in l).
// - Momentum: with pair forces only (springs with and without damping, Newtonian gravity,
//   vortices) and no fixed particle, Σ F = 0 and the pair pattern makes every column of hessX
//   and hessV sum to zero per coordinate, so 1ᵀA δv = 1ᵀM δv = 1ᵀ rhs = 0: every method keeps
//   Σ m v constant to round-off.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/analysis/energy.h"
#include "core/forces/vortex_force.h"
#include "test_support.h"

namespace fosssim::testing {
namespace {

FOSSSIM_TEST_SUITE_IN_2D_AND_3D(ConservationTest);

double total_energy(const TestScene& scene) {
  return compute_energies(scene.model, scene.state).total();
}

/// A planet of mass m = 1 at perihelion r_p = a(1 - e) of an orbit with a = 1, e = 0.5 around a
/// fixed sun M = 1, G = 1: v_p = √(GM(1 + e)/(a(1 - e))) = √3, E = -GMm/(2a) = -0.5, P = 2π.
template <int D>
TestScene kepler(IntegratorKind kind, double h) {
  const auto [e1, e2] = plane_axes<D>();
  TestScene scene(D, kind, h);
  scene.add_particle(1.0, Vector::Zero(D), Vector::Zero(D), /*fixed=*/true);
  scene.add_particle(1.0, 0.5 * e1, std::sqrt(3.0) * e2);
  scene.add_gravitation(0, 1, 1.0);
  return scene;
}

TYPED_TEST(ConservationTest, SymplecticEulerKeepsKeplerEnergyBoundedExplicitEulerDrifts) {
  constexpr int D = TypeParam::value;
  const int per_period = 2000, periods = 100;
  const double h = 2.0 * std::numbers::pi / per_period;
  // max |v·F| = GMm √(GM/p) e max_θ |sin θ| (1 + e cos θ)² / p², p = a(1 - e²) = 0.75.
  const double p = 0.75, e = 0.5;
  double shape = 0.0;
  for (int i = 0; i < 100000; ++i) {
    const double theta = 2.0 * std::numbers::pi * i / 100000;
    shape = std::max(shape, std::abs(std::sin(theta)) * std::pow(1.0 + e * std::cos(theta), 2));
  }
  const double bound = 1.1 * 0.5 * h * std::sqrt(1.0 / p) * e * shape / (p * p) / 0.5;

  TestScene symplectic = kepler<D>(IntegratorKind::kSymplecticEuler, h);
  const double e0 = total_energy(symplectic);
  ASSERT_NEAR(e0, -0.5, 1e-15);
  auto integrator = make_integrator(symplectic.model);
  double first = 0.0, last = 0.0, worst = 0.0;
  for (int k = 0; k < periods; ++k) {
    double in_period = 0.0;
    for (int i = 0; i < per_period; ++i) {
      integrator->step(symplectic.model, symplectic.state);
      in_period = std::max(in_period, std::abs(total_energy(symplectic) - e0) / 0.5);
    }
    if (k == 0) first = in_period;
    last = in_period;
    worst = std::max(worst, in_period);
  }
  std::printf(
      "%dD Kepler, 100 periods: symplectic relative energy oscillation %.4e "
      "(bound %.4e), first period %.4e, last %.4e\n",
      D, worst, bound, first, last);
  EXPECT_LE(worst, bound);
  EXPECT_NEAR(last, first, 0.01 * first) << "the oscillation does not grow";

  TestScene explicit_euler = kepler<D>(IntegratorKind::kExplicitEuler, h);
  integrator = make_integrator(explicit_euler.model);
  std::vector<double> at_perihelion_direction;
  const Vector e1 = plane_axes<D>().first, e2 = plane_axes<D>().second;
  double previous_y = 0.0;
  for (int i = 0; i < periods * per_period; ++i) {
    integrator->step(explicit_euler.model, explicit_euler.state);
    const Vector x = explicit_euler.state.q.tail(D);
    const double y = x.dot(e2);
    if (previous_y < 0.0 && y >= 0.0 && x.dot(e1) > 0.0) {
      at_perihelion_direction.push_back(total_energy(explicit_euler));
    }
    previous_y = y;
  }
  ASSERT_GE(at_perihelion_direction.size(), 10u);
  for (size_t k = 1; k < at_perihelion_direction.size(); ++k) {
    EXPECT_GT(at_perihelion_direction[k], at_perihelion_direction[k - 1]) << "revolution " << k;
  }
  const double drift = (at_perihelion_direction.back() - e0) / 0.5;
  std::printf(
      "%dD Kepler, same run: explicit Euler energy up by %.3f of |E| over %zu revolutions\n", D,
      drift, at_perihelion_direction.size());
  EXPECT_GT(drift, 100.0 * bound);
}

/// A chain: fixed anchor 0 at the origin, free particles 1 and 2, zero-rest-length springs.
template <int D>
TestScene quadratic_chain(IntegratorKind kind) {
  Random random(141);
  TestScene scene(D, kind, 0.05);
  scene.add_particle(1.0, Vector::Zero(D), Vector::Zero(D), /*fixed=*/true);
  scene.add_particle(0.7, random.uniform_vector(D, -1.0, 1.0), random.uniform_vector(D, -1.0, 1.0));
  scene.add_particle(1.3, random.uniform_vector(D, -1.0, 1.0), random.uniform_vector(D, -1.0, 1.0));
  scene.add_spring(0, 1, 30.0, 0.0);
  scene.add_spring(1, 2, 50.0, 0.0);
  return scene;
}

/// Runs `steps` steps and expects the total energy to fall at every one, and by 10% overall.
void expect_monotone_dissipation(TestScene scene, int steps, const char* what) {
  auto integrator = make_integrator(scene.model);
  const double start = total_energy(scene);
  double previous = start;
  for (int s = 0; s < steps; ++s) {
    integrator->step(scene.model, scene.state);
    const double energy = total_energy(scene);
    EXPECT_LT(energy, previous) << what << ", step " << s + 1;
    previous = energy;
  }
  EXPECT_LT(previous, 0.9 * start) << what;
}

TYPED_TEST(ConservationTest, ImplicitMethodsDissipateEnergyOnUndampedSprings) {
  constexpr int D = TypeParam::value;
  expect_monotone_dissipation(quadratic_chain<D>(IntegratorKind::kImplicitEuler), 200,
                              "implicit Euler, zero-rest-length chain");
  expect_monotone_dissipation(quadratic_chain<D>(IntegratorKind::kLinearizedImplicitEuler), 200,
                              "linearized implicit Euler, zero-rest-length chain");
  // A nonlinear spring (l0 = 1) oscillating along its own line between l = 0.6 and 1.4.
  const Vector axis = plane_axes<D>().first;
  TestScene radial(D, IntegratorKind::kImplicitEuler, 0.05);
  radial.add_particle(1.0, Vector::Zero(D), Vector::Zero(D), /*fixed=*/true);
  radial.add_particle(1.0, 1.4 * axis, Vector::Zero(D));
  radial.add_spring(0, 1, 40.0, 1.0);
  expect_monotone_dissipation(std::move(radial), 200, "implicit Euler, radial spring");
}

/// Five free particles joined by pair forces only: springs (one damped), Newtonian gravity and a
/// vortex, with unequal masses, spread on a circle with random velocities. (Particles that
/// collide under Newtonian gravity or a vortex meet a singularity, where Newton's method rightly
/// fails; the test checks that those pairs stay 0.1 apart.)
template <int D>
TestScene pair_forces_only(IntegratorKind kind) {
  Random random(142);
  const auto [e1, e2] = plane_axes<D>();
  TestScene scene(D, kind, 0.01);
  for (int p = 0; p < 5; ++p) {
    const double angle = 2.0 * std::numbers::pi * p / 5.0;
    Vector x = std::cos(angle) * e1 + std::sin(angle) * e2;
    if constexpr (D == 3) x += random.uniform(-0.3, 0.3) * Vector::Ones(3);
    scene.add_particle(random.uniform(0.5, 2.0), x, random.uniform_vector(D, -0.5, 0.5));
  }
  scene.add_spring(0, 1, 20.0, 1.0);
  scene.add_spring(1, 2, 10.0, 1.2, 0.5);
  scene.add_spring(2, 3, 15.0, 1.1);
  scene.add_spring(3, 4, 25.0, 1.2);
  scene.add_gravitation(0, 1, 0.5);  // on springs, which keep the pairs apart
  scene.add_gravitation(3, 4, 0.5);
  scene.add_force(
      std::make_unique<VortexForce<D>>(4, 0, 0.8, 0.3, vortex_rotation<D>(Vec<3>(0.0, 0.6, 0.8))));
  return scene;
}

TYPED_TEST(ConservationTest, PairForcesConserveMomentumWithEveryMethod) {
  constexpr int D = TypeParam::value;
  for (IntegratorKind kind :
       {IntegratorKind::kExplicitEuler, IntegratorKind::kSymplecticEuler,
        IntegratorKind::kLinearizedImplicitEuler, IntegratorKind::kImplicitEuler}) {
    TestScene scene = pair_forces_only<D>(kind);
    const Vector start = linear_momentum(scene.model, scene.state.v);
    double scale = 0.0;  // max m|v|: the size of the terms that cancel
    auto integrator = make_integrator(scene.model);
    for (int s = 0; s < 300; ++s) {
      integrator->step(scene.model, scene.state);
      for (const auto& [i, j] : {std::pair{0, 1}, std::pair{3, 4}, std::pair{4, 0}}) {
        const Vector d = scene.state.q.segment(D * j, D) - scene.state.q.segment(D * i, D);
        ASSERT_GT(d.norm(), 0.1) << integrator_name(kind) << ", step " << s;
      }
      for (int p = 0; p < 5; ++p) {
        scale = std::max(scale, scene.model.mass[D * p] * scene.state.v.segment(D * p, D).norm());
      }
    }
    const double drift = (linear_momentum(scene.model, scene.state.v) - start).norm();
    EXPECT_LE(drift, 1e-13 * scale) << integrator_name(kind) << ": momentum drift " << drift;
    std::printf("%dD %-26s momentum drift after 300 steps %.2e (max m|v| %.2f)\n", D,
                integrator_name(kind), drift, scale);
  }
}

}  // namespace
}  // namespace fosssim::testing
