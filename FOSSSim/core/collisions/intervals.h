#pragma once
// Where polynomials are positive, as unions of intervals, and the first time of contact
// (course-compatible interval logic, docs/collisions.md).

#include <vector>

#include "core/collisions/polynomial.h"

namespace fosssim {

/// An interval of the real line; start and end may be infinite.
struct Interval {
  double start = 0.0;
  double end = 0.0;
  bool operator==(const Interval&) const = default;
};

/// Sorts by start and merges intervals that touch or overlap (next.start ≤ current.end).
std::vector<Interval> merge_intervals(std::vector<Interval> intervals);

/// Where p > 0, as merged intervals: none for an empty polynomial; everywhere or nowhere for a
/// constant one; otherwise from its sorted real roots r_1 ≤ ... ≤ r_k: (-∞, r_1) if
/// p(r_1 - 1) > 0, (r_m, r_m+1) if p at their midpoint is > 0, (r_k, ∞) if p(r_k + 1) > 0;
/// with no real root, everywhere if p(0) > 0.
std::vector<Interval> positive_intervals(const Polynomial& p);

/// Every overlap, in the closed sense (a.end ≥ b.start and b.end ≥ a.start), of an interval of
/// `a` with one of `b`, as [max start, min end] (zero-length results kept), merged.
std::vector<Interval> intersect_intervals(const std::vector<Interval>& a,
                                          const std::vector<Interval>& b);

/// Where all of `polynomials` are positive at once: their intervals intersected in order.
std::vector<Interval> all_positive_intervals(const std::vector<Polynomial>& polynomials);

/// The first time in the intervals that is not in the past: max(start, 0) of the first interval
/// (by start) whose end is > 0, or +∞ when there is none.
double first_time(const std::vector<Interval>& intervals);

}  // namespace fosssim
