#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

namespace fosssim {

/// How a long run reports its progress on standard error.
enum class ProgressStyle {
  kOff,    ///< nothing (--quiet, --progress off)
  kBar,    ///< one line redrawn in place at most ten times a second (a terminal)
  kLines,  ///< a full line every few seconds (logs, nohup, batch systems)
};

/// The style of `--progress auto|bar|lines|off`: auto is a bar when standard error is a
/// terminal and lines otherwise; quiet turns every style off.
ProgressStyle choose_progress_style(const std::string& option, bool quiet);

/// Progress of a run on standard error: a bar redrawn in place at a terminal, or, in logs, a
/// line every ten seconds (by default) from the tenth second on, so that short runs print nothing and a
/// long one under nohup or a batch system shows it is alive and how long it has left.
class ProgressBar {
 public:
  /// label: what is progressing ("simulating", "grading"); total: units of work (steps);
  /// line_interval: seconds between two lines of the kLines style.
  ProgressBar(std::string label, std::int64_t total, ProgressStyle style,
              double line_interval = 10.0);
  ~ProgressBar();

  /// Reports that `done` of `total` units are finished.
  void update(std::int64_t done);
  /// Draws the final state and ends the line (a bar), or writes a last line when lines were
  /// written before (lines).
  void finish();

 private:
  void draw(std::int64_t done);
  void write_line(std::int64_t done);

  std::string label_;
  std::int64_t total_;
  ProgressStyle style_;
  std::chrono::duration<double> line_interval_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

/// True when standard error is an interactive terminal.
bool stderr_is_terminal();

}  // namespace fosssim
