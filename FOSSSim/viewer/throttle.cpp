#include "viewer/throttle.h"

#include <algorithm>
#include <cmath>

namespace fosssim {

Throttle::Throttle(double steps_per_second, double max_backlog_seconds)
    : rate_(steps_per_second > 0.0 ? steps_per_second : 1.0),
      max_credit_(std::max(1.0, rate_ * max_backlog_seconds)) {}

void Throttle::restart(double now) {
  credit_ = 0.0;
  last_ = now;
}

std::int64_t Throttle::take_due(double now) {
  credit_ = std::min(max_credit_, credit_ + std::max(0.0, now - last_) * rate_);
  last_ = now;
  const double due = std::floor(credit_);
  credit_ -= due;
  return static_cast<std::int64_t>(due);
}

}  // namespace fosssim
