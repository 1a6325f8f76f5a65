#pragma once
// Dot products and norms with their sums in a fixed order, for the kernels that reproduce the
// course's floating-point results (docs/forces.md, 'Course-exact arithmetic').

#include <cmath>

#include "core/types.h"

namespace fosssim {

/// a·b summed over the coordinates in order, ((a_0 b_0 + a_1 b_1) + a_2 b_2), whatever the
/// vectoriser would do.
template <int D>
double ordered_dot(const Vec<D>& a, const Vec<D>& b) {
  double sum = a[0] * b[0];
  for (int c = 1; c < D; ++c) sum = sum + a[c] * b[c];
  return sum;
}

/// |d| = √(d·d), with the sum in coordinate order.
template <int D>
double ordered_norm(const Vec<D>& d) {
  return std::sqrt(ordered_dot<D>(d, d));
}

}  // namespace fosssim
