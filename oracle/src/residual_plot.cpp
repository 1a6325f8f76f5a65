#include "residual_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace fosssim {

namespace {

std::string short_number(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.4g", value);
  std::string out = text;
  // "1e-09" -> "1e-9", as the limits are written everywhere else.
  const std::size_t e = out.find('e');
  if (e != std::string::npos && e + 3 < out.size() && out[e + 2] == '0') out.erase(e + 2, 1);
  return out;
}

/// The decades shown: from below the smallest positive residual (or the limit) to above the
/// largest finite one, at least two decades.
std::pair<int, int> decade_range(const std::vector<ResidualColumns::Column>& columns,
                                 double limit, double other_limit) {
  double smallest = std::min(limit, other_limit), largest = std::max(limit, other_limit);
  for (const ResidualColumns::Column& c : columns) {
    for (double v : {c.position, c.velocity}) {
      if (std::isfinite(v) && v > 0.0) {
        smallest = std::min(smallest, v);
        largest = std::max(largest, v);
      }
    }
  }
  int low = static_cast<int>(std::floor(std::log10(smallest)));
  int high = static_cast<int>(std::ceil(std::log10(largest)));
  if (high - low < 2) high = low + 2;
  return {low, high};
}

}  // namespace

ResidualColumns::ResidualColumns(std::int64_t steps, int max_points) {
  max_columns_ = std::min<std::int64_t>(steps, std::max(max_points, 2));
  if (max_columns_ > 0) {
    base_size_ = steps / max_columns_;
    larger_ = steps % max_columns_;
  }
}

void ResidualColumns::add(const StepResidual& residual) {
  const auto column_size = [this](std::int64_t c) { return base_size_ + (c < larger_ ? 1 : 0); };
  const auto count = static_cast<std::int64_t>(columns_.size());
  if (columns_.empty() || (in_last_ >= column_size(count - 1) && count < max_columns_)) {
    columns_.push_back({residual.step, residual.max_position, residual.max_velocity});
    in_last_ = 1;
    return;
  }
  Column& column = columns_.back();  // more steps than announced join the last column
  column.last_step = residual.step;
  if (replaces_maximum(residual.max_position, column.position))
    column.position = residual.max_position;
  if (replaces_maximum(residual.max_velocity, column.velocity))
    column.velocity = residual.max_velocity;
  ++in_last_;
}

LinePlot residual_plot(const std::vector<StepResidual>& per_step,
                       const ResidualPlotOptions& options) {
  ResidualColumns columns(static_cast<std::int64_t>(per_step.size()), options.max_points);
  for (const StepResidual& residual : per_step) columns.add(residual);
  return residual_plot(columns, options);
}

LinePlot residual_plot(const ResidualColumns& reduced, const ResidualPlotOptions& options) {
  const std::vector<ResidualColumns::Column>& columns = reduced.columns();
  bool has_zero = false, has_non_finite = false;
  for (const ResidualColumns::Column& c : columns) {
    for (double v : {c.position, c.velocity}) {
      has_zero = has_zero || v == 0.0;
      has_non_finite = has_non_finite || !std::isfinite(v);
    }
  }
  LinePlot plot;
  plot.width = 760;
  plot.height = 460;
  plot.title = options.title;
  plot.x.title = "simulated time (s)";
  plot.x.high = columns.empty()
                    ? options.dt
                    : std::max(static_cast<double>(columns.back().last_step) * options.dt, 1e-300);
  const bool velocity_line = options.velocity_limit && *options.velocity_limit != options.limit;
  const auto [low, high] =
      decade_range(columns, options.limit, velocity_line ? *options.velocity_limit : options.limit);
  plot.y.title = "largest residual of the step";
  plot.y.scale = AxisScale::kLog10;
  plot.y.zero_at_low = has_zero;  // zeros get the bottom line of their own, a decade lower
  plot.y.low = std::pow(10.0, has_zero ? low - 1 : low);
  plot.y.high = std::pow(10.0, high);

  plot.references.push_back({ReferenceLine::Direction::kHorizontal,
                             options.limit,
                             (velocity_line ? "maximum position limit " : "maximum limit ") +
                                 short_number(options.limit),
                             {0.839, 0.153, 0.157},
                             {6.0, 4.0}});
  if (velocity_line) {
    plot.references.push_back({ReferenceLine::Direction::kHorizontal,
                               *options.velocity_limit,
                               "maximum velocity limit " + short_number(*options.velocity_limit),
                               {0.839, 0.153, 0.157},
                               {2.0, 2.0}});
  }
  if (options.marked_step) {
    plot.references.push_back({ReferenceLine::Direction::kVertical,
                               static_cast<double>(*options.marked_step) * options.dt,
                               "first divergence: step " + std::to_string(*options.marked_step),
                               {0.333, 0.333, 0.333},
                               {2.0, 3.0}});
  }
  // NaN residuals, like infinite ones, are drawn on the top edge rather than left out.
  const auto top_if_nan = [](double v) {
    return std::isnan(v) ? std::numeric_limits<double>::infinity() : v;
  };
  PlotCurve position{"position", {0.122, 0.467, 0.706}, 1.5, {}};
  PlotCurve velocity{"velocity", {1.0, 0.498, 0.055}, 1.5, {}};
  for (const ResidualColumns::Column& c : columns) {
    const double time = static_cast<double>(c.last_step) * options.dt;
    position.points.push_back({time, top_if_nan(c.position)});
    velocity.points.push_back({time, top_if_nan(c.velocity)});
  }
  plot.curves = {std::move(position), std::move(velocity)};
  if (has_zero) plot.note = "Exact zeros are drawn on the bottom line.";
  if (has_non_finite) {
    plot.note +=
        (has_zero ? " " : "") + std::string("NaN or infinite residuals are drawn on the top edge.");
  }
  return plot;
}

}  // namespace fosssim
