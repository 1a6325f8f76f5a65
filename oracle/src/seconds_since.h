#pragma once
// Wall time of the oracle's own work: the candidate's run, grading, the whole command.

#include <chrono>

namespace fosssim {

/// Seconds of std::chrono::steady_clock elapsed since `start`.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace fosssim
