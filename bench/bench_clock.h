#pragma once
// What every benchmark prints its timings with: a steady clock, and the machine's load.

#include <chrono>
#include <ctime>
#include <fstream>
#include <string>

namespace fosssim::bench {

using Clock = std::chrono::steady_clock;

/// Milliseconds from `start` to now.
inline double milliseconds_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// CPU seconds this thread has used: on a shared machine steadier than wall time, which grows
/// with the other processes' load (for single-threaded work).
inline double thread_cpu_milliseconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

/// The load averages of /proc/loadavg (1, 5 and 15 minutes): timings on a busy machine are
/// slower and noisier.
inline std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string one, five, fifteen;
  in >> one >> five >> fifteen;
  return one + " " + five + " " + fifteen;
}

}  // namespace fosssim::bench
