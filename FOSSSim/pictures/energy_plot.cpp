#include "pictures/energy_plot.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pictures/line_plot.h"

namespace fosssim {

namespace {

struct Series {
  const char* name;
  double (*value)(const EnergySample&);
  Color color;
  double width;
};

const Series kSeries[] = {
    {"kinetic", [](const EnergySample& s) { return s.kinetic; }, {0.122, 0.467, 0.706}, 1.6},
    {"potential", [](const EnergySample& s) { return s.potential; }, {1.0, 0.498, 0.055}, 1.6},
    {"total", [](const EnergySample& s) { return s.total(); }, {0.1, 0.1, 0.1}, 2.2},
};

bool finite(const EnergySample& s) {
  return std::isfinite(s.time) && std::isfinite(s.kinetic) && std::isfinite(s.potential) &&
         std::isfinite(s.total());
}

/// The axes: the time and energy of the finite points, energy padded by 6% of its span (or 5%
/// of its size when it is constant), so that no curve runs along the frame.
void set_ranges(const std::vector<PlotCurve>& curves, PlotAxis& time, PlotAxis& energy) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  double t0 = kInfinity, t1 = -kInfinity, e0 = kInfinity, e1 = -kInfinity;
  for (const PlotCurve& curve : curves) {
    for (const PlotPoint& p : curve.points) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
      t0 = std::min(t0, p.x);
      t1 = std::max(t1, p.x);
      e0 = std::min(e0, p.y);
      e1 = std::max(e1, p.y);
    }
  }
  if (!(t0 <= t1)) t0 = 0.0, t1 = 1.0;
  if (t1 - t0 <= 0.0) t1 = t0 + 1.0;
  if (!(e0 <= e1)) e0 = 0.0, e1 = 1.0;
  const double span = e1 - e0;
  const double pad =
      span > 1e-12 * std::max(1.0, std::abs(e1)) ? 0.06 * span : std::max(1.0, std::abs(e1)) * 0.05;
  time.low = t0;
  time.high = t1;
  energy.low = e0 - pad;
  energy.high = e1 + pad;
}

}  // namespace

void EnergyHistory::merge(Bucket& into, const Bucket& from) {
  for (int c = 0; c < kCurves; ++c) {
    Extremes& a = into.curves[c];
    const Extremes& b = from.curves[c];
    if (!b.any) continue;
    if (!a.any || b.low < a.low) a.low = b.low, a.low_time = b.low_time;
    // Ties: the earliest lowest and the latest highest, so that a bucket of two equal samples
    // keeps both and a flat stretch keeps its ends (`from` follows `into` in time).
    if (!a.any || b.high >= a.high) a.high = b.high, a.high_time = b.high_time;
    a.any = true;
  }
  into.samples += from.samples;
  into.broken = into.broken || from.broken;
}

void EnergyHistory::add(const EnergySample& sample) {
  if (buckets_.empty() || buckets_.back().samples == width_) {
    if (buckets_.size() == static_cast<std::size_t>(kBuckets)) {  // all full: merge neighbours
      for (int k = 0; k < kBuckets / 2; ++k) {
        buckets_[k] = buckets_[2 * k];
        merge(buckets_[k], buckets_[2 * k + 1]);
      }
      buckets_.resize(kBuckets / 2);
      width_ *= 2;
    }
    if (buckets_.capacity() == 0) buckets_.reserve(kBuckets);
    buckets_.emplace_back();
  }
  Bucket single;
  single.samples = 1;
  if (finite(sample)) {
    for (int c = 0; c < kCurves; ++c) {
      const double value = kSeries[c].value(sample);
      single.curves[c] = Extremes{sample.time, value, sample.time, value, true};
    }
  } else {
    single.broken = true;
  }
  merge(buckets_.back(), single);
  ++count_;
}

std::vector<std::array<double, 2>> EnergyHistory::points(int c) const {
  std::vector<std::array<double, 2>> out;
  out.reserve(2 * buckets_.size());
  for (const Bucket& bucket : buckets_) {
    const Extremes& e = bucket.curves[c];
    if (e.any) {
      const bool low_first = e.low_time <= e.high_time;
      out.push_back(low_first ? std::array<double, 2>{e.low_time, e.low}
                              : std::array<double, 2>{e.high_time, e.high});
      if (e.low_time != e.high_time) {
        out.push_back(low_first ? std::array<double, 2>{e.high_time, e.high}
                                : std::array<double, 2>{e.low_time, e.low});
      }
    }
    if (bucket.broken) {
      out.push_back(
          {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()});
    }
  }
  return out;
}

void write_energy_plot(const std::vector<EnergySample>& samples, const std::string& path,
                       const EnergyPlotStyle& style) {
  EnergyHistory history;
  for (const EnergySample& s : samples) history.add(s);
  write_energy_history_plot(history, path, style);
}

void write_energy_history_plot(const EnergyHistory& history, const std::string& path,
                               const EnergyPlotStyle& style) {
  LinePlot plot;
  plot.width = style.width;
  plot.height = style.height;
  plot.title = style.title;
  plot.x.title = "time (s)";
  plot.y.title = "energy (J)";
  for (int c = 0; c < EnergyHistory::kCurves; ++c) {
    const Series& series = kSeries[c];
    PlotCurve curve{series.name, series.color, series.width, {}};
    for (const auto& [t, value] : history.points(c)) curve.points.push_back({t, value});
    plot.curves.push_back(std::move(curve));
  }
  set_ranges(plot.curves, plot.x, plot.y);
  write_line_plot(plot, path);
}

}  // namespace fosssim
