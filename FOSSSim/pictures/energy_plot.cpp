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

/// The axes: the time and energy of the finite samples, energy padded by 6% of its span (or 5%
/// of its size when it is constant), so that no curve runs along the frame.
void set_ranges(const std::vector<EnergySample>& samples, PlotAxis& time, PlotAxis& energy) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  double t0 = kInfinity, t1 = -kInfinity, e0 = kInfinity, e1 = -kInfinity;
  for (const EnergySample& s : samples) {
    if (!finite(s)) continue;
    t0 = std::min(t0, s.time);
    t1 = std::max(t1, s.time);
    for (const Series& series : kSeries) {
      e0 = std::min(e0, series.value(s));
      e1 = std::max(e1, series.value(s));
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

void write_energy_plot(const std::vector<EnergySample>& samples, const std::string& path,
                       const EnergyPlotStyle& style) {
  LinePlot plot;
  plot.width = style.width;
  plot.height = style.height;
  plot.title = style.title;
  plot.x.title = "time (s)";
  plot.y.title = "energy (J)";
  set_ranges(samples, plot.x, plot.y);
  for (const Series& series : kSeries) {
    PlotCurve curve{series.name, series.color, series.width, {}};
    curve.points.reserve(samples.size());
    for (const EnergySample& s : samples) {
      // A sample with a non-finite energy breaks every curve.
      curve.points.push_back(
          {s.time, finite(s) ? series.value(s) : std::numeric_limits<double>::quiet_NaN()});
    }
    plot.curves.push_back(std::move(curve));
  }
  write_line_plot(plot, path);
}

}  // namespace fosssim
