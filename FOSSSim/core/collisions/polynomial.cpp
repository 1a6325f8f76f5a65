#include "core/collisions/polynomial.h"

#include <cmath>

namespace fosssim {

Polynomial::Polynomial(std::vector<double> highest_first)
    : coefficients_(std::move(highest_first)) {
  std::size_t first = 0;
  while (first < coefficients_.size() &&
         std::abs(coefficients_[first]) < kNegligibleLeadingCoefficient) {
    ++first;
  }
  coefficients_.erase(coefficients_.begin(), coefficients_.begin() + first);
}

Polynomial Polynomial::as_written(std::vector<double> highest_first) {
  Polynomial p;
  p.coefficients_ = std::move(highest_first);
  return p;
}

double Polynomial::operator()(double t) const {
  double value = 0.0;
  for (double c : coefficients_) value = value * t + c;
  return value;
}

double Polynomial::derivative_at(double t) const {
  const int n = degree();
  double value = 0.0;
  for (int k = 0; k < n; ++k) value = value * t + (n - k) * coefficients_[k];
  return value;
}

}  // namespace fosssim
