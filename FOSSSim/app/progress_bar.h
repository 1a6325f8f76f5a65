#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

namespace fosssim {

/// A one-line progress bar on standard error, drawn only when standard error is a terminal and
/// redrawn at most ten times a second, so that it costs nothing in batch runs and logs.
class ProgressBar {
 public:
  /// label: what is progressing ("simulating", "grading"); enabled: false to stay silent.
  ProgressBar(std::string label, std::int64_t total, bool enabled);
  ~ProgressBar();

  /// Reports that `done` of `total` units are finished.
  void update(std::int64_t done);
  /// Draws the final state and ends the line.
  void finish();

 private:
  void draw(std::int64_t done);

  std::string label_;
  std::int64_t total_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

/// True when standard error is an interactive terminal.
bool stderr_is_terminal();

}  // namespace fosssim
