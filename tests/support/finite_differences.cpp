#include "support/finite_differences.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <map>
#include <tuple>
#include <vector>

#include "core/analysis/derivative_check.h"
#include "support/dense.h"

namespace fosssim::testing {

namespace {

/// Perturbs coordinate k of x by ±t and returns both points and the actual step between them.
struct Perturbation {
  Vector plus, minus;
  double step;
};

Perturbation perturb(const Vector& x, int k, double t) {
  Perturbation p{x, x, 0.0};
  p.plus[k] = x[k] + t;
  p.minus[k] = x[k] - t;
  p.step = p.plus[k] - p.minus[k];  // exact: the two numbers are within a factor of 2
  return p;
}

MatrixComparison compare(const Eigen::MatrixXd& analytic, const Eigen::MatrixXd& numeric) {
  return {(analytic - numeric).norm(), std::max(analytic.norm(), numeric.norm()), 0.0};
}

}  // namespace

MatrixComparison compare_hessian_full(const Force& force, const Vector& q, const Vector& v,
                                      const Vector& mass, bool in_velocity, double t) {
  const int n = static_cast<int>(q.size());
  Eigen::MatrixXd numeric(n, n);
  for (int k = 0; k < n; ++k) {
    const Perturbation p = perturb(in_velocity ? v : q, k, t);
    const Vector g_plus =
        in_velocity ? gradient_of(force, q, p.plus, mass) : gradient_of(force, p.plus, v, mass);
    const Vector g_minus =
        in_velocity ? gradient_of(force, q, p.minus, mass) : gradient_of(force, p.minus, v, mass);
    numeric.col(k) = (g_plus - g_minus) / p.step;
  }
  const Eigen::MatrixXd analytic =
      in_velocity ? hessian_v_of(force, q, v, mass) : hessian_x_of(force, q, v, mass);
  return compare(analytic, numeric);
}

MatrixComparison compare_gradient_full(const Force& force, const Vector& q, const Vector& mass,
                                       double t) {
  const int n = static_cast<int>(q.size());
  const Vector rest = Vector::Zero(n);
  const auto central = [&](int k, double step) {
    const Perturbation p = perturb(q, k, step);
    return (energy_of(force, p.plus, rest, mass) - energy_of(force, p.minus, rest, mass)) / p.step;
  };
  Vector numeric(n);
  for (int k = 0; k < n; ++k) numeric[k] = (4.0 * central(k, 0.5 * t) - central(k, t)) / 3.0;
  MatrixComparison result = compare(gradient_of(force, q, rest, mass), numeric);
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  const double curvature = hessian_x_of(force, q, rest, mass).norm();
  result.noise_floor =
      100.0 * kEps * std::sqrt(static_cast<double>(n)) *
      (std::abs(energy_of(force, q, rest, mass)) / t + curvature * q.lpNorm<Eigen::Infinity>());
  return result;
}

double shortest_distance(const Vector& q, int dim) {
  const int n = static_cast<int>(q.size()) / dim;
  double shortest = std::numeric_limits<double>::infinity();
  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) {
      shortest = std::min(shortest, (q.segment(dim * a, dim) - q.segment(dim * b, dim)).norm());
    }
  }
  return shortest;
}

double configuration_length(const Vector& q, int dim) {
  const double shortest = shortest_distance(q, dim);
  return shortest > 0.0 ? std::min(1.0, shortest) : 1.0;
}

// ---------------------------------------------------------------------------------------------

namespace {

using ErrorKey = std::tuple<std::string, int, std::string, std::string, std::string>;

struct WorstCase {
  double error = -1.0;
  std::string detail;  ///< the configuration that produced it
};

std::map<ErrorKey, WorstCase>& error_table() {
  static std::map<ErrorKey, WorstCase> table;
  return table;
}

/// Prints the table of largest relative errors when the test program ends.
class ErrorTablePrinter : public ::testing::Environment {
 public:
  void TearDown() override {
    if (error_table().empty()) return;
    std::printf(
        "\nLargest finite-difference relative errors (library: the worst direction of\n"
        "core/analysis/derivative_check; full-matrix: central differences written in the\n"
        "test, relative in the Frobenius norm):\n");
    std::printf("%-14s %-3s %-16s %-9s %-12s %-9s %s\n", "force", "dim", "configuration",
                "quantity", "checker", "max error", "where");
    for (const auto& [key, worst] : error_table()) {
      const auto& [force, dim, configuration, derivative, checker] = key;
      std::printf("%-14s %dD  %-16s %-9s %-12s %.2e  %s\n", force.c_str(), dim,
                  configuration.c_str(), derivative.c_str(), checker.c_str(), worst.error,
                  worst.detail.c_str());
    }
  }
};

[[maybe_unused]] ::testing::Environment* const kErrorTablePrinter =
    ::testing::AddGlobalTestEnvironment(new ErrorTablePrinter);

}  // namespace

void record_fd_error(const DerivativeCase& what, int dim, const std::string& derivative,
                     const std::string& checker, double error) {
  if (what.configuration == kAtRest) return;  // relative errors of round-off mean nothing
  WorstCase& worst = error_table()[{what.force, dim, what.configuration, derivative, checker}];
  if (!(error <= worst.error)) worst = {error, what.detail};  // NaN is the worst of all
}

bool check_force_everywhere(const Force& force, int dim, const Vector& q, const Vector& v,
                            const Vector& mass, const DerivativeCase& what) {
  bool all_passed = true;
  const std::string where =
      what.force + " " + std::to_string(dim) + "D " + what.configuration + " (" + what.detail + ")";

  DerivativeCheckOptions options;
  options.step = suggest_finite_difference_step(q, dim);
  for (const DerivativeCheck& check : check_force_derivatives(force, q, v, mass, options)) {
    EXPECT_TRUE(check.passed()) << where << ": library check of " << derivative_name(check.which)
                                << " failed, relative error " << check.relative_error()
                                << ", allowance used " << check.allowance_used;
    all_passed = all_passed && check.passed();
    record_fd_error(what, dim, derivative_name(check.which), "library", check.relative_error());
  }

  // Independent check: whole matrices by central differences, steps relative to the
  // configuration's length (and to 1 for velocities).
  const double length = configuration_length(q, dim);
  struct Item {
    const char* name;
    MatrixComparison result;
  };
  std::vector<Item> items = {
      {"hessV", compare_hessian_full(force, q, v, mass, true, kHessianStep)}};
  if (force.has_jacobian()) {  // as the library's checker: a force may leave hessX out
    items.push_back(
        {"hessX", compare_hessian_full(force, q, v, mass, false, kHessianStep * length)});
  }
  if (force.has_potential()) {
    items.push_back({"gradient", compare_gradient_full(force, q, mass, kGradientStep * length)});
  }
  for (const Item& item : items) {
    const bool passed = item.result.passes(kFullMatrixTolerance);
    EXPECT_TRUE(passed) << where << ": full-matrix check of " << item.name << ", error "
                        << item.result.absolute_error << " against scale " << item.result.scale
                        << " and noise floor " << item.result.noise_floor;
    all_passed = all_passed && passed;
    record_fd_error(what, dim, item.name, "full-matrix", item.result.relative_error());
  }
  return all_passed;
}

}  // namespace fosssim::testing
