#pragma once
// Where a scene is now: the part that changes every step.

#include <cstdint>

#include "core/types.h"

namespace fosssim {

struct State {
  Vector q;               ///< positions, interleaved per particle
  Vector v;               ///< velocities, same layout
  std::int64_t step = 0;  ///< number of steps taken
  double time = 0.0;      ///< simulated time, step * dt
};

}  // namespace fosssim
