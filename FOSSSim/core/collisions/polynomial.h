#pragma once
// Polynomials in the time t of a step, as continuous-time detection builds and logs them.

#include <vector>

namespace fosssim {

/// A real polynomial, coefficients stored highest degree first. Construction drops leading
/// coefficients below kNegligibleLeadingCoefficient in absolute value (course-compatible: the
/// stripped polynomial is what is logged, written and graded), so its degree is what remains;
/// a polynomial all of whose coefficients are negligible is empty.
class Polynomial {
 public:
  /// Leading coefficients with |c| below this are dropped on construction.
  static constexpr double kNegligibleLeadingCoefficient = 1e-12;

  Polynomial() = default;
  explicit Polynomial(std::vector<double> highest_first);
  /// A polynomial with exactly these coefficients, nothing dropped (as read from a file, where
  /// a grader must see what was written).
  static Polynomial as_written(std::vector<double> highest_first);

  const std::vector<double>& coefficients() const { return coefficients_; }
  bool empty() const { return coefficients_.empty(); }
  /// The degree, -1 when empty.
  int degree() const { return static_cast<int>(coefficients_.size()) - 1; }
  /// p(t) by Horner's rule; 0 when empty.
  double operator()(double t) const;
  /// p'(t) by Horner's rule; 0 when the degree is below 1.
  double derivative_at(double t) const;

  bool operator==(const Polynomial&) const = default;

 private:
  std::vector<double> coefficients_;
};

}  // namespace fosssim
