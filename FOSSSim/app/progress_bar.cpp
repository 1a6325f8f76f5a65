#include "app/progress_bar.h"

#include <unistd.h>

#include <algorithm>

namespace fosssim {

namespace {

/// Fraction done, elapsed and estimated remaining seconds.
struct Progress {
  double fraction, elapsed, remaining;
};

Progress progress_of(std::int64_t done, std::int64_t total,
                     std::chrono::steady_clock::time_point start) {
  const double fraction = total > 0 ? std::clamp(double(done) / double(total), 0.0, 1.0) : 1.0;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double remaining = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  return {fraction, elapsed, remaining};
}

}  // namespace

bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

ProgressStyle choose_progress_style(const std::string& option, bool quiet) {
  if (quiet || option == "off") return ProgressStyle::kOff;
  if (option == "bar") return ProgressStyle::kBar;
  if (option == "lines") return ProgressStyle::kLines;
  return stderr_is_terminal() ? ProgressStyle::kBar : ProgressStyle::kLines;
}

ProgressBar::ProgressBar(std::string label, std::int64_t total, ProgressStyle style,
                         double line_interval)
    : label_(std::move(label)),
      total_(total),
      style_(style),
      line_interval_(line_interval),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

ProgressBar::~ProgressBar() {
  if (drawn_ && style_ == ProgressStyle::kBar) std::fputc('\n', stderr);
}

void ProgressBar::update(std::int64_t done) {
  const auto now = std::chrono::steady_clock::now();
  switch (style_) {
    case ProgressStyle::kOff:
      return;
    case ProgressStyle::kBar:
      if (drawn_ && now - last_draw_ < std::chrono::milliseconds(100)) return;
      last_draw_ = now;
      draw(done);
      return;
    case ProgressStyle::kLines:
      if (now - last_draw_ < line_interval_) return;
      last_draw_ = now;
      write_line(done);
      return;
  }
}

void ProgressBar::finish() {
  if (style_ == ProgressStyle::kBar) {
    draw(total_);
    std::fputc('\n', stderr);
    drawn_ = false;
  } else if (style_ == ProgressStyle::kLines && drawn_) {
    write_line(total_);
  }
}

void ProgressBar::draw(std::int64_t done) {
  constexpr int kWidth = 30;
  const Progress p = progress_of(done, total_, start_);
  const int filled = static_cast<int>(p.fraction * kWidth);
  char bar[kWidth + 1];
  for (int k = 0; k < kWidth; ++k) bar[k] = k < filled ? '#' : '.';
  bar[kWidth] = '\0';
  std::fprintf(stderr, "\r%s [%s] %3.0f%%  %lld/%lld  %.1fs elapsed, %.1fs left ", label_.c_str(),
               bar, 100.0 * p.fraction, static_cast<long long>(done),
               static_cast<long long>(total_), p.elapsed, p.remaining);
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressBar::write_line(std::int64_t done) {
  const Progress p = progress_of(done, total_, start_);
  std::fprintf(stderr, "FOSSSim: %s: step %lld of %lld (%.0f%%), %.0f s elapsed, about %.0f s left\n",
               label_.c_str(), static_cast<long long>(done), static_cast<long long>(total_),
               100.0 * p.fraction, p.elapsed, p.remaining);
  std::fflush(stderr);
  drawn_ = true;
}

}  // namespace fosssim
