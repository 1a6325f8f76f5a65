#include "core/analysis/derivative_check.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>

namespace fosssim {

namespace {

constexpr double kMachineEpsilon = std::numeric_limits<double>::epsilon();

/// Richardson-extrapolated central difference of f along u: (4 D(ε/2) - D(ε)) / 3.
template <typename Value>
Value directional_difference(const std::function<Value(double)>& f, double eps) {
  const Value d_full = (f(eps) - f(-eps)) / (2.0 * eps);
  const Value d_half = (f(0.5 * eps) - f(-0.5 * eps)) / eps;
  return (4.0 * d_half - d_full) / 3.0;
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

Vector gradient_at(const Force& force, const Vector& q, const Vector& v, const Vector& mass) {
  Vector g = Vector::Zero(q.size());
  force.add_gradient({q, v, mass}, g);
  return g;
}

double energy_at(const Force& force, const Vector& q, const Vector& v, const Vector& mass) {
  double energy = 0.0;
  force.add_energy({q, v, mass}, energy);
  return energy;
}

/// Keeps the direction whose error uses most of its allowance rtol·scale + floor.
void record(DerivativeCheck& check, double error, double scale, double floor, double rtol) {
  const double allowance = rtol * scale + floor;
  const double ratio = allowance > 0.0 ? error / allowance : (error > 0.0 ? INFINITY : 0.0);
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
  const Vector g = gradient_at(force, q, rest, mass);
  const double energy_size = std::abs(energy_at(force, q, rest, mass)) + g.norm() * options.step;
  const double floor = 1e3 * kMachineEpsilon * energy_size / options.step;
  for (const Vector& u : directions) {
    const std::function<double(double)> f = [&](double t) {
      return energy_at(force, q + t * u, rest, mass);
    };
    const double numeric = directional_difference(f, options.step);
    const double analytic = g.dot(u);
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
  if (which == Derivative::kHessianX) {
    force.add_hessian_x(in, builder);
  } else {
    force.add_hessian_v(in, builder);
  }
  const SparseMatrix H = builder.build(static_cast<int>(q.size()));
  const double floor = 1e3 * kMachineEpsilon * gradient_at(force, q, v, mass).norm() / options.step;
  for (const Vector& u : directions) {
    const std::function<Vector(double)> f = [&](double t) {
      return which == Derivative::kHessianX ? gradient_at(force, q + t * u, v, mass)
                                            : gradient_at(force, q, v + t * u, mass);
    };
    const Vector numeric = directional_difference(f, options.step);
    const Vector analytic = H * u;
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
  checks.push_back(check_hessian(force, Derivative::kHessianX, q, v, mass, directions, options));
  checks.push_back(check_hessian(force, Derivative::kHessianV, q, v, mass, directions, options));
  return checks;
}

std::vector<DerivativeCheck> check_model_derivatives(const SceneModel& model, const Vector& q,
                                                     const Vector& v,
                                                     const DerivativeCheckOptions& options) {
  std::vector<DerivativeCheck> checks;
  for (const auto& force : model.forces) {
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
