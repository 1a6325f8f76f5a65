#pragma once
// The `maxsimfreq` throttle: the window takes at most this many steps per wall-clock second.

#include <cstdint>

namespace fosssim {

/// Counts the steps due as wall-clock time passes, at `steps_per_second`. A window that cannot
/// keep up does not build an ever-growing backlog: at most `max_backlog_seconds` worth of steps
/// are ever due at once.
class Throttle {
 public:
  explicit Throttle(double steps_per_second, double max_backlog_seconds = 0.1);

  /// Starts counting at wall time `now` (seconds), with nothing due (after a pause, say).
  void restart(double now);
  /// The whole number of steps due at wall time `now`; they count as taken once returned.
  std::int64_t take_due(double now);

  double steps_per_second() const { return rate_; }

 private:
  double rate_;
  double max_credit_;
  double credit_ = 0.0;
  double last_ = 0.0;
};

}  // namespace fosssim
