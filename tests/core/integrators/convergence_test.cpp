// Analytic solutions and convergence orders of the four Euler methods, in 2D and 3D.
//
// Math checked (h = 1/64, 1/128, 1/256, 1/512, end time T = 1, exact in binary):
// - an elliptic orbit on a zero-rest-length spring k from a fixed anchor at the origin,
//   m x'' = -k x: x(t) = A cos ωt e₁ + (B/ω) sin ωt e₂, ω = √(k/m) (in 3D in a tilted plane);
// - free fall with gravity g: x(t) = x₀ + v₀ t + ½ g t². Each method's result is known exactly:
//   velocities are exact for all four (vₙ = v₀ + n h g); explicit Euler's position is
//   x(t) - ½ g t h (it moves with the old velocity), symplectic, linearized implicit and implicit
//   Euler's is x(t) + ½ g t h (they move with the new one; A = M, one solve is exact);
// - drag toward terminal velocity, m v' = m g - b v: v(t) = v_T + (v₀ - v_T) e^{-bt/m},
//   v_T = m g / b. Discretely vₙ - v_T = (1 - hb/m)ⁿ (v₀ - v_T) for explicit and symplectic Euler
//   and (1 + hb/m)⁻ⁿ (v₀ - v_T) for the implicit ones, checked to round-off;
// - a circular Kepler orbit around a fixed sun (nonlinear): uniform rotation at ω = √(GM/r³).
// For every method and problem the error ‖q - q(T)‖ + ‖v - v(T)‖/ω at T decreases with h and
// the observed order log₂(e(h)/e(h/2)) lies in [0.9, 1.1]: all four are first order.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

#include "test_support.h"

namespace fosssim::testing {
namespace {

FOSSSIM_TEST_SUITE_IN_2D_AND_3D(ConvergenceTest);

constexpr double kEndTime = 1.0;

/// A problem with a known solution: its scene for a method and step, the exact state at T, and
/// the frequency that makes velocity errors comparable to position errors.
struct Problem {
  const char* name;
  std::function<TestScene(IntegratorKind, double)> scene;
  State exact;
  double omega;
};

double error_at_end(const Problem& problem, IntegratorKind kind, double h) {
  TestScene scene = problem.scene(kind, h);
  const auto steps = static_cast<std::int64_t>(std::llround(kEndTime / h));
  const State end = run_steps(scene.model, scene.state, steps);
  return (end.q - problem.exact.q).norm() + (end.v - problem.exact.v).norm() / problem.omega;
}

/// Measures the errors at h, h/2, h/4, h/8 and asserts first-order convergence.
void expect_first_order(const Problem& problem, IntegratorKind kind, int dim) {
  SCOPED_TRACE(std::string(problem.name) + ", " + integrator_name(kind));
  double errors[4];
  for (int r = 0; r < 4; ++r) errors[r] = error_at_end(problem, kind, 1.0 / (64 << r));
  std::printf("%dD %-14s %-26s errors %.3e %.3e %.3e %.3e  orders", dim, problem.name,
              integrator_name(kind), errors[0], errors[1], errors[2], errors[3]);
  for (int r = 0; r < 3; ++r) {
    const double order = std::log2(errors[r] / errors[r + 1]);
    std::printf(" %.4f", order);
    EXPECT_LT(errors[r + 1], errors[r]);
    EXPECT_GE(order, 0.9);
    EXPECT_LE(order, 1.1);
  }
  std::printf("\n");
}

template <int D>
Problem oscillator() {
  const double m = 1.5, k = 6.0, omega = std::sqrt(k / m), A = 1.0, B = 0.7;
  const auto [e1, e2] = plane_axes<D>();
  State exact;
  exact.q.resize(2 * D);
  exact.v.resize(2 * D);
  exact.q << Vector::Zero(D),
      A * std::cos(omega * kEndTime) * e1 + (B / omega) * std::sin(omega * kEndTime) * e2;
  exact.v << Vector::Zero(D),
      -A * omega * std::sin(omega * kEndTime) * e1 + B * std::cos(omega * kEndTime) * e2;
  const auto scene = [=](IntegratorKind kind, double h) {
    TestScene s(D, kind, h);
    s.add_particle(1.0, Vector::Zero(D), Vector::Zero(D), /*fixed=*/true);
    s.add_particle(m, A * e1, B * e2);
    s.add_spring(0, 1, k, 0.0);
    return s;
  };
  return {"oscillator", scene, exact, omega};
}

template <int D>
Problem free_fall() {
  Vector x0(D), v0(D), g(D);
  x0.setLinSpaced(0.3, -0.2);
  v0.setLinSpaced(1.0, 2.0);
  g.setLinSpaced(-1.0, -9.81);
  State exact;
  exact.q = x0 + v0 * kEndTime + 0.5 * g * kEndTime * kEndTime;
  exact.v = v0 + g * kEndTime;
  const auto scene = [=](IntegratorKind kind, double h) {
    TestScene s(D, kind, h);
    s.add_particle(2.0, x0, v0);
    s.add_simple_gravity(g);
    return s;
  };
  return {"free fall", scene, exact, 1.0};
}

template <int D>
Problem drag() {
  const double m = 2.0, b = 1.6;
  Vector v0(D), g(D);
  v0.setLinSpaced(3.0, -1.0);
  g.setLinSpaced(0.5, -9.81);
  const Vector terminal = m * g / b;
  const double decay = std::exp(-b * kEndTime / m);
  State exact;
  exact.v = terminal + (v0 - terminal) * decay;
  // x(t) = x₀ + v_T t + (v₀ - v_T)(m/b)(1 - e^{-bt/m}), from x₀ = 0.
  exact.q = terminal * kEndTime + (v0 - terminal) * (m / b) * (1.0 - decay);
  const auto scene = [=](IntegratorKind kind, double h) {
    TestScene s(D, kind, h);
    s.add_particle(m, Vector::Zero(D), v0);
    s.add_simple_gravity(g);
    s.add_drag(b);
    return s;
  };
  return {"drag", scene, exact, b / m};
}

template <int D>
Problem circular_orbit() {
  const double G = 1.3, sun = 2.0, r = 1.2;
  const double omega = std::sqrt(G * sun / (r * r * r));
  const auto [e1, e2] = plane_axes<D>();
  const double angle = omega * kEndTime;
  State exact;
  exact.q.resize(2 * D);
  exact.v.resize(2 * D);
  exact.q << Vector::Zero(D), r * (std::cos(angle) * e1 + std::sin(angle) * e2);
  exact.v << Vector::Zero(D), r * omega * (-std::sin(angle) * e1 + std::cos(angle) * e2);
  const auto scene = [=](IntegratorKind kind, double h) {
    TestScene s(D, kind, h);
    s.add_particle(sun, Vector::Zero(D), Vector::Zero(D), /*fixed=*/true);
    s.add_particle(0.01, r * e1, r * omega * e2);
    s.add_gravitation(0, 1, G);
    return s;
  };
  return {"circular orbit", scene, exact, omega};
}

TYPED_TEST(ConvergenceTest, EveryMethodIsFirstOrderOnEveryProblem) {
  constexpr int D = TypeParam::value;
  for (const Problem& problem : {oscillator<D>(), free_fall<D>(), drag<D>(), circular_orbit<D>()}) {
    for (IntegratorKind kind : kAllIntegrators) expect_first_order(problem, kind, D);
  }
}

TYPED_TEST(ConvergenceTest, FreeFallResultsAreKnownExactly) {
  constexpr int D = TypeParam::value;
  const Problem problem = free_fall<D>();
  Vector g(D);
  g.setLinSpaced(-1.0, -9.81);
  for (IntegratorKind kind : kAllIntegrators) {
    const double h = 1.0 / 128;
    TestScene scene = problem.scene(kind, h);
    const State end = run_steps(scene.model, scene.state, 128);
    const double sign = kind == IntegratorKind::kExplicitEuler ? -1.0 : 1.0;
    expect_close(end.v, problem.exact.v, 1e-13, std::string(integrator_name(kind)) + ": v");
    expect_close(end.q, problem.exact.q + sign * 0.5 * g * kEndTime * h, 1e-13,
                 std::string(integrator_name(kind)) + ": q");
  }
}

TYPED_TEST(ConvergenceTest, DragFollowsTheDiscreteDecayFactors) {
  constexpr int D = TypeParam::value;
  const double m = 2.0, b = 1.6, h = 1.0 / 64;
  Vector v0(D), g(D);
  v0.setLinSpaced(3.0, -1.0);
  g.setLinSpaced(0.5, -9.81);
  const Vector terminal = m * g / b;
  const Problem problem = drag<D>();
  for (IntegratorKind kind : kAllIntegrators) {
    TestScene scene = problem.scene(kind, h);
    const State end = run_steps(scene.model, scene.state, 64);
    const bool implicit =
        kind == IntegratorKind::kLinearizedImplicitEuler || kind == IntegratorKind::kImplicitEuler;
    const double factor = implicit ? 1.0 / (1.0 + h * b / m) : 1.0 - h * b / m;
    expect_close(end.v, terminal + std::pow(factor, 64) * (v0 - terminal), 1e-13,
                 integrator_name(kind));
  }
}

}  // namespace
}  // namespace fosssim::testing
