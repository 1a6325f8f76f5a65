#include "core/analysis/derivative_check.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>

#include "core/force_evaluation.h"
#include "core/force_set.h"

namespace fosssim {

namespace {

constexpr double kMachineEpsilon = std::numeric_limits<double>::epsilon();

/// The points x ± t u as doubles and the step actually taken between them. x ± t u are
/// rounded to doubles, which changes the step by ε_machine |x| (1e-6 of t = 1e-10 for a
/// 1e-6-long spring at distance 1 from the origin); comparing differences of f with the
/// analytic derivative applied to δ = fl(x + t u) - fl(x - t u) keeps that rounding out.
struct Stencil {
  Vector plus, minus, step;
};

Stencil make_stencil(const Vector& x, const Vector& u, double t) {
  Stencil s{x + t * u, x - t * u, Vector()};
  s.step = (s.plus - x) - (s.minus - x);
  return s;
}

/// A finite-difference estimate of a directional derivative and the analytic value it is
/// compared with.
template <typename Value>
struct Estimate {
  Value numeric, analytic;
};

/// Richardson-extrapolated central differences (4 D(ε/2) - D(ε)) / 3 of f along u (error
/// O(ε⁴)), and the same combination of the analytic derivative `apply` on the steps taken.
template <typename Value>
Estimate<Value> directional_difference(const Vector& x, const Vector& u, double eps,
                                       const std::function<Value(const Vector&)>& f,
                                       const std::function<Value(const Vector&)>& apply) {
  const auto central = [&](double t) {
    const Stencil s = make_stencil(x, u, t);
    return Estimate<Value>{(f(s.plus) - f(s.minus)) / (2.0 * t), apply(s.step) / (2.0 * t)};
  };
  const Estimate<Value> full = central(eps);
  const Estimate<Value> half = central(0.5 * eps);
  return {(4.0 * half.numeric - full.numeric) / 3.0, (4.0 * half.analytic - full.analytic) / 3.0};
}

std::vector<Vector> check_directions(int n, const DerivativeCheckOptions& options) {
  std::vector<Vector> directions;
  std::mt19937 rng(options.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (int k = 0; k < options.random_directions; ++k) {
    Vector u(n);
    for (int i = 0; i < n; ++i) u[i] = normal(rng);
    directions.push_back(u.normalized());
  }
  if (n <= options.all_directions_up_to) {
    for (int i = 0; i < n; ++i) directions.push_back(Vector::Unit(n, i));
  }
  return directions;
}

/// Keeps the direction whose error uses most of its allowance rtol·scale + floor. A NaN error
/// or allowance counts as an infinite excess, so a NaN derivative cannot pass.
void record(DerivativeCheck& check, double error, double scale, double floor, double rtol) {
  const double allowance = rtol * scale + floor;
  double ratio = INFINITY;
  if (!std::isnan(error) && !std::isnan(allowance)) {
    ratio = allowance > 0.0 ? error / allowance : (error > 0.0 ? INFINITY : 0.0);
  }
  if (ratio >= check.allowance_used) {
    check.absolute_error = error;
    check.scale = scale;
    check.noise_floor = floor;
    check.allowance_used = ratio;
  }
}

DerivativeCheck check_gradient(const Force& force, const Vector& q, const Vector& mass,
                               const std::vector<Vector>& directions,
                               const DerivativeCheckOptions& options) {
  DerivativeCheck check{force.label(), Derivative::kGradient};
  const Vector rest = Vector::Zero(q.size());
  const Vector g = gradient_of(force, q, rest, mass);
  const double energy_size = std::abs(energy_of(force, q, rest, mass)) + g.norm() * options.step;
  const double size = q.lpNorm<Eigen::Infinity>();
  const std::function<double(const Vector&)> energy = [&](const Vector& x) {
    return energy_of(force, x, rest, mass);
  };
  const std::function<double(const Vector&)> apply = [&](const Vector& delta) {
    return g.dot(delta);
  };
  for (const Vector& u : directions) {
    const auto [numeric, analytic] = directional_difference(q, u, options.step, energy, apply);
    // Round-off: the energy values carry ε|U|; and both sides carry the rounding of the
    // positions' differences, ε |q|_∞ ‖hessX u‖, which is all there is at an equilibrium
    // (a spring at its rest length), where gradE itself is round-off.
    const Stencil s = make_stencil(q, u, options.step);
    const double curvature =
        (gradient_of(force, s.plus, rest, mass) - gradient_of(force, s.minus, rest, mass)).norm() /
        (2.0 * options.step);
    const double floor = 1e3 * kMachineEpsilon * (energy_size / options.step + curvature * size);
    record(check, std::abs(analytic - numeric), std::max(std::abs(analytic), std::abs(numeric)),
           floor, options.relative_tolerance);
  }
  return check;
}

DerivativeCheck check_hessian(const Force& force, Derivative which, const Vector& q,
                              const Vector& v, const Vector& mass,
                              const std::vector<Vector>& directions,
                              const DerivativeCheckOptions& options) {
  DerivativeCheck check{force.label(), which};
  HessianBuilder builder;
  const ForceInput in{q, v, mass};
  const bool in_q = which == Derivative::kHessianX;
  if (in_q) {
    force.add_hessian_x(in, builder);
  } else {
    force.add_hessian_v(in, builder);
  }
  const SparseMatrix H = builder.build(static_cast<int>(q.size()));
  // Round-off: the gradient values carry ε‖gradE‖, and the rounding of the differences of the
  // coordinates, ε |x|_∞ ‖H‖; the latter is all there is in a direction where H u vanishes
  // (across a spring at rest).
  // The step in v is its own: a position step suited to a 1e-6-long spring (1e-10) would
  // drown hessV in the round-off of gradE.
  const double step = in_q ? options.step : options.velocity_step;
  const double size = (in_q ? q : v).lpNorm<Eigen::Infinity>();
  const double floor =
      1e3 * kMachineEpsilon * (gradient_of(force, q, v, mass).norm() / step + H.norm() * size);
  const std::function<Vector(const Vector&)> gradient = [&](const Vector& x) {
    return in_q ? gradient_of(force, x, v, mass) : gradient_of(force, q, x, mass);
  };
  const std::function<Vector(const Vector&)> apply = [&](const Vector& delta) {
    return Vector(H * delta);
  };
  for (const Vector& u : directions) {
    const auto [numeric, analytic] = directional_difference(in_q ? q : v, u, step, gradient, apply);
    record(check, (analytic - numeric).norm(), std::max(analytic.norm(), numeric.norm()), floor,
           options.relative_tolerance);
  }
  return check;
}

}  // namespace

const char* derivative_name(Derivative which) {
  switch (which) {
    case Derivative::kGradient:
      return "gradient";
    case Derivative::kHessianX:
      return "hessX";
    case Derivative::kHessianV:
      return "hessV";
  }
  return "?";
}

std::vector<DerivativeCheck> check_force_derivatives(const Force& force, const Vector& q,
                                                     const Vector& v, const Vector& mass,
                                                     const DerivativeCheckOptions& options) {
  const std::vector<Vector> directions = check_directions(static_cast<int>(q.size()), options);
  std::vector<DerivativeCheck> checks;
  if (force.has_potential()) checks.push_back(check_gradient(force, q, mass, directions, options));
  if (force.has_jacobian()) {
    checks.push_back(check_hessian(force, Derivative::kHessianX, q, v, mass, directions, options));
  }
  checks.push_back(check_hessian(force, Derivative::kHessianV, q, v, mass, directions, options));
  return checks;
}

std::vector<DerivativeCheck> check_model_derivatives(const SceneModel& model, const Vector& q,
                                                     const Vector& v,
                                                     const DerivativeCheckOptions& options) {
  std::vector<DerivativeCheck> checks;
  for (const Force* force : ForceSet(model)) {
    auto force_checks = check_force_derivatives(*force, q, v, model.mass, options);
    checks.insert(checks.end(), force_checks.begin(), force_checks.end());
  }
  return checks;
}

double suggest_finite_difference_step(const Vector& q, int dim) {
  const int n = static_cast<int>(q.size()) / dim;
  const int stride = std::max(1, n / 2000);
  double shortest = std::numeric_limits<double>::infinity();
  for (int a = 0; a < n; a += stride) {
    for (int b = a + 1; b < n; b += stride) {
      const double distance = (q.segment(dim * a, dim) - q.segment(dim * b, dim)).norm();
      if (distance > 0.0) shortest = std::min(shortest, distance);
    }
  }
  return std::isfinite(shortest) ? std::min(1e-4, 1e-4 * shortest) : 1e-4;
}

}  // namespace fosssim
