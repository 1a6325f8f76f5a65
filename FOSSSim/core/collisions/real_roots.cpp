#include "core/collisions/real_roots.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fosssim {

namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

double evaluate(const std::vector<double>& a, double t) {
  double value = 0.0;
  for (double c : a) value = value * t + c;
  return value;
}

double evaluate_derivative(const std::vector<double>& a, double t) {
  const int n = static_cast<int>(a.size()) - 1;
  double value = 0.0;
  for (int k = 0; k < n; ++k) value = value * t + (n - k) * a[k];
  return value;
}

/// A bound on the round-off of evaluating p at t by Horner's rule: 2n ε Σ |a_k| |t|^k.
double evaluation_error_bound(const std::vector<double>& a, double t) {
  double sum = 0.0;
  for (double c : a) sum = sum * std::abs(t) + std::abs(c);
  return 2.0 * static_cast<double>(a.size()) * kEpsilon * sum;
}

std::vector<double> derivative(const std::vector<double>& a) {
  const int n = static_cast<int>(a.size()) - 1;
  std::vector<double> d(n);
  for (int k = 0; k < n; ++k) d[k] = (n - k) * a[k];
  return d;
}

/// The one root of p in [lo, hi], where p is monotone and p(lo), p(hi) differ in sign.
double bracketed_root(const std::vector<double>& a, double lo, double hi, double f_lo) {
  double x = 0.5 * (lo + hi);
  for (int iteration = 0; iteration < 400; ++iteration) {
    const double fx = evaluate(a, x);
    if (fx == 0.0) return x;
    if ((fx < 0.0) == (f_lo < 0.0)) {
      lo = x;
      f_lo = fx;
    } else {
      hi = x;
    }
    const double mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) break;  // lo and hi are adjacent doubles
    // Newton from x when it lands inside the bracket and shrinks it well; else bisect.
    const double slope = evaluate_derivative(a, x);
    const double newton = slope != 0.0 ? x - fx / slope : mid;
    x = (newton > lo && newton < hi) ? newton : mid;
    if (hi - lo < 4.0 * kEpsilon * std::max(std::abs(lo), std::abs(hi))) {
      x = std::abs(evaluate(a, lo)) <= std::abs(evaluate(a, hi)) ? lo : hi;
      return x;
    }
  }
  return std::abs(evaluate(a, lo)) <= std::abs(evaluate(a, hi)) ? lo : hi;
}

/// Roots of a polynomial whose leading coefficient is nonzero and whose constant term is
/// nonzero.
std::vector<double> roots_without_zero(const std::vector<double>& a) {
  const int n = static_cast<int>(a.size()) - 1;
  if (n <= 0) return {};
  if (n == 1) return {-a[1] / a[0]};
  double bound = 0.0;
  for (int k = 1; k <= n; ++k) bound = std::max(bound, std::abs(a[k] / a[0]));
  bound += 1.0;
  std::vector<double> cuts = {-bound};
  for (double c : real_roots(derivative(a))) {
    if (c > -bound && c < bound) cuts.push_back(c);
  }
  cuts.push_back(bound);
  std::vector<double> roots;
  const auto add = [&roots](double r) {
    if (roots.empty() || roots.back() != r) roots.push_back(r);
  };
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double lo = cuts[k], hi = cuts[k + 1];
    const double f_lo = evaluate(a, lo), f_hi = evaluate(a, hi);
    if (k > 0 && std::abs(f_lo) <= evaluation_error_bound(a, lo)) add(lo);  // touches zero
    if (f_lo == 0.0 || f_hi == 0.0) continue;
    if ((f_lo < 0.0) != (f_hi < 0.0)) add(bracketed_root(a, lo, hi, f_lo));
  }
  return roots;
}

}  // namespace

std::vector<double> real_roots(const std::vector<double>& highest_first) {
  std::vector<double> a = highest_first;
  std::size_t first = 0;
  while (first < a.size() && a[first] == 0.0) ++first;
  a.erase(a.begin(), a.begin() + first);
  std::vector<double> roots;
  while (a.size() > 1 && a.back() == 0.0) {  // t divides p: a root at exactly 0
    a.pop_back();
    roots.push_back(0.0);
  }
  if (a.empty()) return {};
  std::vector<double> others = roots_without_zero(a);
  roots.insert(roots.end(), others.begin(), others.end());
  std::sort(roots.begin(), roots.end());
  return roots;
}

}  // namespace fosssim
