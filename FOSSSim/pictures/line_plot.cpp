#include "pictures/line_plot.h"


#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "pictures/cairo_painter.h"
#include "pictures/cairo_library.h"

namespace fosssim {

namespace {

// Layout, in pixels: margins of the plot area, and where the texts below it sit.
constexpr double kLeftMargin = 78.0, kRightMargin = 20.0;
constexpr double kTopMargin = 20.0, kTopMarginWithTitle = 44.0, kBottomMargin = 76.0;
constexpr double kTickLabelGap = 6.0;      // between the plot area and the tick labels
constexpr double kAxisTitleOffset = 26.0;  // below the plot area, to the x axis title
constexpr double kLegendFromBottom = 20.0;

const Color kText{0.2, 0.2, 0.2};
const Color kGrid{0.88, 0.88, 0.88};
const Color kNote{0.33, 0.33, 0.33};

/// Shows `text` so that the point (align_x, align_y) of its box, each in [0, 1] from the left
/// and the top, lies at (x, y). Returns how far the text advances along x.
double show_text(cairo_t* cr, const std::string& text, double x, double y, double align_x,
                 double align_y) {
  cairo_text_extents_t extents;
  cairo().text_extents(cr, text.c_str(), &extents);
  cairo().move_to(cr, x - align_x * extents.width - extents.x_bearing,
                y - align_y * extents.height - extents.y_bearing);
  cairo().show_text(cr, text.c_str());
  return extents.x_advance;
}

/// Where `value` lies on an axis from `low` to `high` (log10 of the range on a kLog10 axis), as
/// a fraction of the axis clamped to [0, 1]; NaN for NaN.
double axis_fraction(AxisScale scale, double low, double high, double value) {
  if (std::isnan(value)) return value;
  if (scale == AxisScale::kLog10) value = value > 0.0 ? std::log10(value) : -HUGE_VAL;
  return std::clamp((value - low) / (high - low), 0.0, 1.0);
}

std::string linear_tick_label(double value, double step) {
  if (std::abs(value) < 1e-9 * step) value = 0.0;
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

void draw_axes(cairo_t* cr, const LinePlot& plot, const PlotFrame& f) {
  cairo().set_font_size(cr, 12.0);
  cairo().set_line_width(cr, 1.0);
  for (const PlotTick& tick : axis_ticks(plot.x)) {
    const double x = std::round(f.x(tick.value)) + 0.5;
    set_color(cr, kGrid);
    cairo().move_to(cr, x, f.top);
    cairo().line_to(cr, x, f.bottom);
    cairo().stroke(cr);
    set_color(cr, kText);
    show_text(cr, tick.label, f.x(tick.value), f.bottom + kTickLabelGap, 0.5, 0.0);
  }
  for (const PlotTick& tick : axis_ticks(plot.y)) {
    const double y = std::round(f.y(tick.value)) + 0.5;
    set_color(cr, kGrid);
    cairo().move_to(cr, f.left, y);
    cairo().line_to(cr, f.right, y);
    cairo().stroke(cr);
    set_color(cr, kText);
    show_text(cr, tick.label, f.left - kTickLabelGap, f.y(tick.value), 1.0, 0.5);
  }
  set_color(cr, kText);
  cairo().rectangle(cr, f.left + 0.5, f.top + 0.5, f.right - f.left - 1.0, f.bottom - f.top - 1.0);
  cairo().stroke(cr);
  cairo().set_font_size(cr, 13.0);
  show_text(cr, plot.x.title, 0.5 * (f.left + f.right), f.bottom + kAxisTitleOffset, 0.5, 0.0);
  cairo().save(cr);
  cairo().translate(cr, 18.0, 0.5 * (f.top + f.bottom));
  cairo().rotate(cr, -std::numbers::pi / 2.0);
  show_text(cr, plot.y.title, 0.0, 0.0, 0.5, 0.5);
  cairo().restore(cr);
}

void draw_references(cairo_t* cr, const LinePlot& plot, const PlotFrame& f) {
  cairo().set_font_size(cr, 12.0);
  cairo().set_line_width(cr, 1.2);
  for (const ReferenceLine& line : plot.references) {
    set_color(cr, line.color);
    cairo().set_dash(cr, line.dashes.data(), static_cast<int>(line.dashes.size()), 0.0);
    if (line.direction == ReferenceLine::Direction::kHorizontal) {
      const double y = std::round(f.y(line.value)) + 0.5;  // on a row of pixels, like the grid
      cairo().move_to(cr, f.left, y);
      cairo().line_to(cr, f.right, y);
      cairo().stroke(cr);
      show_text(cr, line.label, f.right - 4.0, y - 4.0, 1.0, 1.0);  // above, at the right end
    } else {
      const double x = std::round(f.x(line.value)) + 0.5;
      cairo().move_to(cr, x, f.top);
      cairo().line_to(cr, x, f.bottom);
      cairo().stroke(cr);
      // At the top, beside the line, on whichever side has room.
      const bool on_the_left = x > f.left + 0.7 * (f.right - f.left);
      show_text(cr, line.label, on_the_left ? x - 4.0 : x + 4.0, f.top + 4.0,
                on_the_left ? 1.0 : 0.0, 0.0);
    }
  }
  cairo().set_dash(cr, nullptr, 0, 0.0);
}

void draw_curves(cairo_t* cr, const LinePlot& plot, const PlotFrame& f) {
  // Clipped to the plot area and a margin, so that a curve on an edge is seen whole.
  constexpr double kMargin = 2.0;
  cairo().save(cr);
  cairo().rectangle(cr, f.left - kMargin, f.top - kMargin, f.right - f.left + 2 * kMargin,
                  f.bottom - f.top + 2 * kMargin);
  cairo().clip(cr);
  cairo().set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (const PlotCurve& curve : plot.curves) {
    cairo().new_path(cr);
    for (const PlotPoint& p : curve.points) {
      if (std::isnan(p.x) || std::isnan(p.y)) {
        cairo().new_sub_path(cr);  // the next point starts a new piece
      } else {
        cairo().line_to(cr, f.x(p.x), f.y(p.y));
      }
    }
    set_color(cr, curve.color);
    cairo().set_line_width(cr, curve.width);
    cairo().stroke(cr);
  }
  cairo().restore(cr);
}

/// One row below the axes: a sample of each named curve with its name, then the note.
void draw_legend(cairo_t* cr, const LinePlot& plot, const PlotFrame& f) {
  cairo().set_font_size(cr, 12.0);
  const double y = plot.height - kLegendFromBottom;
  double x = f.left;
  for (const PlotCurve& curve : plot.curves) {
    if (curve.name.empty()) continue;
    set_color(cr, curve.color);
    cairo().set_line_width(cr, std::max(curve.width, 2.0));
    cairo().move_to(cr, x, y);
    cairo().line_to(cr, x + 24.0, y);
    cairo().stroke(cr);
    set_color(cr, kText);
    x += 30.0 + show_text(cr, curve.name, x + 30.0, y, 0.0, 0.5) + 20.0;
  }
  if (!plot.note.empty()) {
    set_color(cr, kNote);
    show_text(cr, plot.note, x, y, 0.0, 0.5);
  }
}

void paint_line_plot(cairo_t* cr, const LinePlot& plot) {
  cairo().set_source_rgb(cr, 1.0, 1.0, 1.0);
  cairo().paint(cr);
  cairo().select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  const PlotFrame f(plot);
  if (!plot.title.empty()) {
    cairo().set_font_size(cr, 15.0);
    set_color(cr, {0.1, 0.1, 0.1});
    show_text(cr, plot.title, 0.5 * (f.left + f.right), 14.0, 0.5, 0.0);
  }
  draw_axes(cr, plot, f);
  draw_references(cr, plot, f);
  draw_curves(cr, plot, f);
  draw_legend(cr, plot, f);
}

}  // namespace

PlotFrame::PlotFrame(const LinePlot& plot)
    : left(kLeftMargin),
      top(plot.title.empty() ? kTopMargin : kTopMarginWithTitle),
      right(plot.width - kRightMargin),
      bottom(plot.height - kBottomMargin),
      x_scale_(plot.x.scale),
      y_scale_(plot.y.scale) {
  const auto range = [](const PlotAxis& axis, double& low, double& high) {
    const bool log = axis.scale == AxisScale::kLog10;
    low = log ? std::log10(axis.low) : axis.low;
    high = log ? std::log10(axis.high) : axis.high;
  };
  range(plot.x, x_low_, x_high_);
  range(plot.y, y_low_, y_high_);
}

double PlotFrame::x(double value) const {
  return left + (right - left) * axis_fraction(x_scale_, x_low_, x_high_, value);
}

double PlotFrame::y(double value) const {
  return bottom - (bottom - top) * axis_fraction(y_scale_, y_low_, y_high_, value);
}

std::vector<PlotTick> axis_ticks(const PlotAxis& axis) {
  std::vector<PlotTick> ticks;
  if (axis.scale == AxisScale::kLinear) {
    const std::vector<double> values = nice_ticks(axis.low, axis.high);
    const double step = values.size() > 1 ? values[1] - values[0] : 1.0;
    for (double v : values) ticks.push_back({v, linear_tick_label(v, step)});
    return ticks;
  }
  if (!(axis.low > 0.0 && axis.high > axis.low)) return ticks;
  const int low = static_cast<int>(std::ceil(std::log10(axis.low) - 1e-9));
  const int high = static_cast<int>(std::floor(std::log10(axis.high) + 1e-9));
  const int label_every = std::max(1, (high - low + 9) / 10);
  for (int e = low; e <= high; ++e) {
    std::string label;
    if (e == low && axis.zero_at_low) {
      label = "0";
    } else if ((high - e) % label_every == 0) {
      label = "1e" + std::to_string(e);
    }
    ticks.push_back({std::pow(10.0, e), label});
  }
  return ticks;
}

std::vector<double> nice_ticks(double low, double high, int target) {
  std::vector<double> ticks;
  if (!(high > low) || target < 1) return ticks;
  const double raw = (high - low) / target;
  int exponent = static_cast<int>(std::floor(std::log10(raw)));
  double multiple = 10.0;
  for (double m : {1.0, 2.0, 5.0}) {
    if (raw <= m * std::pow(10.0, exponent)) {
      multiple = m;
      break;
    }
  }
  if (multiple == 10.0) multiple = 1.0, ++exponent;
  // Tick k is k · multiple · 10^exponent; dividing by an exact power of ten gives the double
  // nearest to 0.6, where multiplying by 0.1 would give 0.6000000000000001.
  const double power = std::pow(10.0, std::abs(exponent));
  const auto value = [&](double k) {
    const double v = exponent < 0 ? k * multiple / power : k * multiple * power;
    return v == 0.0 ? 0.0 : v;  // no "-0" labels
  };
  const double step = value(1.0);
  for (double k = std::ceil(low / step - 1e-9); value(k) <= high + 1e-9 * step; k += 1.0) {
    ticks.push_back(value(k));
  }
  return ticks;
}

void write_line_plot(const LinePlot& plot, const std::string& path) {
  write_picture(path, picture_format_for(path), plot.width, plot.height,
                [&plot](cairo_t* cr) { paint_line_plot(cr, plot); });
}

}  // namespace fosssim
