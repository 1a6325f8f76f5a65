#include "core/collisions/intervals.h"

#include <algorithm>
#include <limits>

#include "core/collisions/real_roots.h"

namespace fosssim {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
}  // namespace

std::vector<Interval> merge_intervals(std::vector<Interval> intervals) {
  std::sort(intervals.begin(), intervals.end(),
            [](const Interval& a, const Interval& b) { return a.start < b.start; });
  std::vector<Interval> merged;
  for (const Interval& interval : intervals) {
    if (!merged.empty() && interval.start <= merged.back().end) {
      merged.back().end = std::max(merged.back().end, interval.end);
    } else {
      merged.push_back(interval);
    }
  }
  return merged;
}

std::vector<Interval> positive_intervals(const Polynomial& p) {
  if (p.empty()) return {};
  if (p.degree() == 0) {
    if (p.coefficients()[0] > 0.0) return {{-kInfinity, kInfinity}};
    return {};
  }
  const std::vector<double> roots = real_roots(p.coefficients());
  if (roots.empty()) {
    if (p(0.0) > 0.0) return {{-kInfinity, kInfinity}};
    return {};
  }
  std::vector<Interval> intervals;
  if (p(roots.front() - 1.0) > 0.0) intervals.push_back({-kInfinity, roots.front()});
  for (std::size_t m = 0; m + 1 < roots.size(); ++m) {
    if (p((roots[m] + roots[m + 1]) / 2.0) > 0.0) intervals.push_back({roots[m], roots[m + 1]});
  }
  if (p(roots.back() + 1.0) > 0.0) intervals.push_back({roots.back(), kInfinity});
  return merge_intervals(std::move(intervals));
}

std::vector<Interval> intersect_intervals(const std::vector<Interval>& a,
                                          const std::vector<Interval>& b) {
  std::vector<Interval> overlaps;
  for (const Interval& x : a) {
    for (const Interval& y : b) {
      if (x.end >= y.start && y.end >= x.start) {
        overlaps.push_back({std::max(x.start, y.start), std::min(x.end, y.end)});
      }
    }
  }
  return merge_intervals(std::move(overlaps));
}

std::vector<Interval> all_positive_intervals(const std::vector<Polynomial>& polynomials) {
  if (polynomials.empty()) return {};
  std::vector<Interval> intervals = positive_intervals(polynomials.front());
  for (std::size_t k = 1; k < polynomials.size(); ++k) {
    intervals = intersect_intervals(intervals, positive_intervals(polynomials[k]));
  }
  return intervals;
}

double first_time(const std::vector<Interval>& intervals) {
  for (const Interval& interval : intervals) {  // sorted by start
    if (interval.end > 0.0) return std::max(interval.start, 0.0);
  }
  return kInfinity;
}

}  // namespace fosssim
