// Analytic solutions and convergence orders of every integrator of the registry, in 2D and 3D.
//
// Math checked (h = 1/64, 1/128, 1/256, 1/512, end time T = 1, exact in binary):
// - an elliptic orbit on a zero-rest-length spring k from a fixed anchor at the origin,
//   m x'' = -k x: x(t) = A cos ωt e₁ + (B/ω) sin ωt e₂, ω = √(k/m) (in 3D in a tilted plane);
// - free fall with gravity g: x(t) = x₀ + v₀ t + ½ g t². Each method's result is known exactly:
//   velocities are exact for every method (vₙ = v₀ + n h g); explicit Euler's position is
//   x(t) - ½ g t h (it moves with the old velocity), every other method's is x(t) + ½ g t h
//   (they move with the new one; A = M, one solve is exact, and local/global's global step is
//   exact without springs);
// - drag toward terminal velocity, m v' = m g - b v: v(t) = v_T + (v₀ - v_T) e^{-bt/m},
//   v_T = m g / b. Discretely vₙ - v_T = (1 - hb/m)ⁿ (v₀ - v_T) for the methods that take drag
//   explicitly (explicit and symplectic Euler, local/global) and (1 + hb/m)⁻ⁿ (v₀ - v_T) for
//   those that take it implicitly, checked to round-off;
// - a circular Kepler orbit around a fixed sun (nonlinear): uniform rotation at ω = √(GM/r³).
// For every method of the registry and every problem the error ‖q - q(T)‖ + ‖v - v(T)‖/ω at T
// decreases with h and the observed order log₂(e(h)/e(h/2)) lies within 0.1 of the order the
// method declares (IntegratorProperties::order), unless the method is exact on the problem (all
// four errors at round-off, below 1e-12 of the state's size). The closed forms of free fall and drag are
// each method's own: they are listed here per method, and a method without one is skipped.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>

#include "support/closed_forms.h"
#include "support/scene_builder.h"
#include "support/typed_tests.h"

namespace fosssim::testing {
namespace {

FOSSSIM_TEST_SUITE_IN_2D_AND_3D(ConvergenceTest);

constexpr double kEndTime = 1.0;

/// A problem with a known solution: its scene for a method and step, the exact state at T, and
/// the frequency that makes velocity errors comparable to position errors.
struct Problem {
  const char* name;
  std::function<TestScene(std::string_view, double)> scene;
  State exact;
  double omega;
};

double error_at_end(const Problem& problem, std::string_view kind, double h) {
  TestScene scene = problem.scene(kind, h);
  const auto steps = static_cast<std::int64_t>(std::llround(kEndTime / h));
  const State end = run_steps(scene.model, scene.initial, steps);
  return (end.q - problem.exact.q).norm() + (end.v - problem.exact.v).norm() / problem.omega;
}

/// Measures the errors at h, h/2, h/4, h/8 and asserts convergence of the declared order.
void expect_order(const Problem& problem, const IntegratorMethod& method, int dim) {
  const std::string_view kind = method.name;
  const int declared = method.properties.order;
  SCOPED_TRACE(std::string(problem.name) + ", " + std::string(kind));
  double errors[4];
  for (int r = 0; r < 4; ++r) errors[r] = error_at_end(problem, kind, 1.0 / (64 << r));
  std::printf("%dD %-14s %-26s errors %.3e %.3e %.3e %.3e  orders", dim, problem.name,
              std::string(kind).c_str(), errors[0], errors[1], errors[2], errors[3]);
  // A method that is exact on the problem (a second-order method on free fall) leaves only
  // round-off, which has no order: every error below 1e-12 of the state's size counts as exact.
  const double scale = problem.exact.q.norm() + problem.exact.v.norm() / problem.omega;
  if (*std::max_element(errors, errors + 4) < 1e-12 * scale) {
    std::printf(" (exact: round-off only)\n");
    return;
  }
  for (int r = 0; r < 3; ++r) {
    const double order = std::log2(errors[r] / errors[r + 1]);
    std::printf(" %.4f", order);
    EXPECT_LT(errors[r + 1], errors[r]);
    EXPECT_GE(order, declared - 0.1);
    EXPECT_LE(order, declared + 0.1);
  }
  std::printf("\n");
}

template <int D>
Problem oscillator_problem() {
  const double m = 1.5, k = 6.0, omega = std::sqrt(k / m), A = 1.0, B = 0.7;
  const auto [e1, e2] = plane_axes<D>();
  State exact;
  exact.q.resize(2 * D);
  exact.v.resize(2 * D);
  exact.q << Vector::Zero(D),
      A * std::cos(omega * kEndTime) * e1 + (B / omega) * std::sin(omega * kEndTime) * e2;
  exact.v << Vector::Zero(D),
      -A * omega * std::sin(omega * kEndTime) * e1 + B * std::cos(omega * kEndTime) * e2;
  const auto scene = [=, e1 = e1, e2 = e2](std::string_view kind, double h) {
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
  const auto scene = [=](std::string_view kind, double h) {
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
  const auto scene = [=](std::string_view kind, double h) {
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
  const auto scene = [=, e1 = e1, e2 = e2](std::string_view kind, double h) {
    TestScene s(D, kind, h);
    s.add_particle(sun, Vector::Zero(D), Vector::Zero(D), /*fixed=*/true);
    s.add_particle(0.01, r * e1, r * omega * e2);
    s.add_gravitation(0, 1, G);
    return s;
  };
  return {"circular orbit", scene, exact, omega};
}

/// The relative tolerance of a closed-form result after `steps` steps: 1e-13, plus, for a
/// method whose velocities are position differences (IntegratorProperties::
/// velocity_from_positions), their round-off of up to 4ε max|q|/h per step, accumulated.
double round_off_tolerance(std::string_view method, int steps, double h, const State& end) {
  if (!integrator_method(method).properties.velocity_from_positions) return 1e-13;
  const double eps = std::numeric_limits<double>::epsilon();
  return 1e-13 + steps * 4.0 * eps * end.q.cwiseAbs().maxCoeff() / h /
                     std::max(1.0, end.v.cwiseAbs().maxCoeff());
}

TYPED_TEST(ConvergenceTest, EveryMethodHasItsDeclaredOrderOnEveryProblem) {
  constexpr int D = TypeParam::value;
  for (const Problem& problem :
       {oscillator_problem<D>(), free_fall<D>(), drag<D>(), circular_orbit<D>()}) {
    for (const IntegratorMethod* method : all_integrators()) expect_order(problem, *method, D);
  }
}

TYPED_TEST(ConvergenceTest, FreeFallResultsAreKnownExactly) {
  constexpr int D = TypeParam::value;
  const Problem problem = free_fall<D>();
  Vector g(D);
  g.setLinSpaced(-1.0, -9.81);
  // Which velocity each method moves with: -1 the old one, +1 the new one.
  const std::pair<std::string_view, double> kPositionLag[] = {
      {"explicit-euler", -1.0}, {"symplectic-euler", 1.0}, {"linearized-implicit-euler", 1.0},
      {"implicit-euler", 1.0},  {"local-global", 1.0},     {"linearly-implicit-euler", 1.0}};
  for (const auto& [kind, sign] : kPositionLag) {
    const double h = 1.0 / 128;
    TestScene scene = problem.scene(kind, h);
    const State end = run_steps(scene.model, scene.initial, 128);
    const double tolerance = round_off_tolerance(kind, 128, h, end);
    expect_close(end.v, problem.exact.v, tolerance, std::string(kind) + ": v");
    expect_close(end.q, problem.exact.q + sign * 0.5 * g * kEndTime * h, tolerance,
                 std::string(kind) + ": q");
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
  // Whether each method takes drag implicitly.
  const std::pair<std::string_view, bool> kImplicitDrag[] = {
      {"explicit-euler", false}, {"symplectic-euler", false}, {"linearized-implicit-euler", true},
      {"implicit-euler", true},  {"local-global", false},     {"linearly-implicit-euler", true}};
  for (const auto& [kind, implicit] : kImplicitDrag) {
    TestScene scene = problem.scene(kind, h);
    const State end = run_steps(scene.model, scene.initial, 64);
    const double factor = implicit ? 1.0 / (1.0 + h * b / m) : 1.0 - h * b / m;
    expect_close(end.v, terminal + std::pow(factor, 64) * (v0 - terminal),
                 round_off_tolerance(kind, 64, h, end), std::string(kind));
  }
}

}  // namespace
}  // namespace fosssim::testing
