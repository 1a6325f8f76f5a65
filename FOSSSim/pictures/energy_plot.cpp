#include "pictures/energy_plot.h"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/scene.h"
#include "pictures/cairo_painter.h"

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

/// The plotting area inside the picture and the data range it shows.
struct Frame {
  double left, top, right, bottom;  // pixels
  double t0, t1, e0, e1;            // data
  double x(double t) const { return left + (t - t0) / (t1 - t0) * (right - left); }
  double y(double e) const { return bottom - (e - e0) / (e1 - e0) * (bottom - top); }
};

bool finite(const EnergySample& s) {
  return std::isfinite(s.time) && std::isfinite(s.kinetic) && std::isfinite(s.potential) &&
         std::isfinite(s.total());
}

Frame make_frame(const std::vector<EnergySample>& samples, const EnergyPlotStyle& style) {
  Frame f{78.0,
          style.title.empty() ? 20.0 : 44.0,
          style.width - 20.0,
          style.height - 56.0,
          std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()};
  for (const EnergySample& s : samples) {
    if (!finite(s)) continue;
    f.t0 = std::min(f.t0, s.time);
    f.t1 = std::max(f.t1, s.time);
    for (const Series& series : kSeries) {
      f.e0 = std::min(f.e0, series.value(s));
      f.e1 = std::max(f.e1, series.value(s));
    }
  }
  if (!(f.t0 <= f.t1)) f.t0 = 0.0, f.t1 = 1.0;
  if (f.t1 - f.t0 <= 0.0) f.t1 = f.t0 + 1.0;
  if (!(f.e0 <= f.e1)) f.e0 = 0.0, f.e1 = 1.0;
  const double span = f.e1 - f.e0;
  const double pad = span > 1e-12 * std::max(1.0, std::abs(f.e1))
                         ? 0.06 * span
                         : std::max(1.0, std::abs(f.e1)) * 0.05;
  f.e0 -= pad;
  f.e1 += pad;
  return f;
}

std::string tick_label(double value, double step) {
  if (std::abs(value) < 1e-9 * step) value = 0.0;
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

void show_text(cairo_t* cr, const std::string& text, double x, double y, double align_x,
               double align_y) {
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  cairo_move_to(cr, x - align_x * extents.width - extents.x_bearing,
                y - align_y * extents.height - extents.y_bearing);
  cairo_show_text(cr, text.c_str());
}

void draw_axes(cairo_t* cr, const Frame& f) {
  cairo_set_font_size(cr, 12.0);
  cairo_set_line_width(cr, 1.0);
  const auto time_ticks = nice_ticks(f.t0, f.t1);
  const auto energy_ticks = nice_ticks(f.e0, f.e1);
  const double time_step = time_ticks.size() > 1 ? time_ticks[1] - time_ticks[0] : 1.0;
  const double energy_step = energy_ticks.size() > 1 ? energy_ticks[1] - energy_ticks[0] : 1.0;
  for (double t : time_ticks) {  // grid and labels
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, std::round(f.x(t)) + 0.5, f.top);
    cairo_line_to(cr, std::round(f.x(t)) + 0.5, f.bottom);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    show_text(cr, tick_label(t, time_step), f.x(t), f.bottom + 6.0, 0.5, 0.0);
  }
  for (double e : energy_ticks) {
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, f.left, std::round(f.y(e)) + 0.5);
    cairo_line_to(cr, f.right, std::round(f.y(e)) + 0.5);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    show_text(cr, tick_label(e, energy_step), f.left - 6.0, f.y(e), 1.0, 0.5);
  }
  cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
  cairo_rectangle(cr, f.left + 0.5, f.top + 0.5, f.right - f.left - 1.0, f.bottom - f.top - 1.0);
  cairo_stroke(cr);
  cairo_set_font_size(cr, 13.0);
  show_text(cr, "time (s)", 0.5 * (f.left + f.right), f.bottom + 26.0, 0.5, 0.0);
  cairo_save(cr);
  cairo_translate(cr, 18.0, 0.5 * (f.top + f.bottom));
  cairo_rotate(cr, -M_PI / 2.0);
  show_text(cr, "energy (J)", 0.0, 0.0, 0.5, 0.5);
  cairo_restore(cr);
}

void draw_series(cairo_t* cr, const std::vector<EnergySample>& samples, const Frame& f) {
  cairo_save(cr);
  cairo_rectangle(cr, f.left, f.top, f.right - f.left, f.bottom - f.top);
  cairo_clip(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (const Series& series : kSeries) {
    cairo_new_path(cr);
    for (const EnergySample& s : samples) {
      if (finite(s)) {
        cairo_line_to(cr, f.x(s.time), f.y(series.value(s)));
      } else {
        cairo_new_sub_path(cr);
      }
    }
    cairo_set_source_rgb(cr, series.color.r, series.color.g, series.color.b);
    cairo_set_line_width(cr, series.width);
    cairo_stroke(cr);
  }
  cairo_restore(cr);
}

void draw_legend(cairo_t* cr, const Frame& f) {
  cairo_set_font_size(cr, 12.0);
  const double row = 18.0, width = 112.0, height = row * 3 + 10.0;
  const double x = f.right - width - 10.0, y = f.top + 10.0;
  cairo_rectangle(cr, x, y, width, height);
  cairo_set_source_rgba(cr, 1.0, 1.0, 1.0, 0.9);
  cairo_fill_preserve(cr);
  cairo_set_source_rgb(cr, 0.6, 0.6, 0.6);
  cairo_set_line_width(cr, 1.0);
  cairo_stroke(cr);
  double line_y = y + 5.0 + 0.5 * row;
  for (const Series& series : kSeries) {
    cairo_set_source_rgb(cr, series.color.r, series.color.g, series.color.b);
    cairo_set_line_width(cr, series.width);
    cairo_move_to(cr, x + 10.0, line_y);
    cairo_line_to(cr, x + 40.0, line_y);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.15, 0.15, 0.15);
    show_text(cr, series.name, x + 48.0, line_y, 0.0, 0.5);
    line_y += row;
  }
}

void paint_plot(cairo_t* cr, const std::vector<EnergySample>& samples,
                const EnergyPlotStyle& style) {
  cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
  cairo_paint(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  const Frame f = make_frame(samples, style);
  if (!style.title.empty()) {
    cairo_set_font_size(cr, 15.0);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    show_text(cr, style.title, 0.5 * (f.left + f.right), 14.0, 0.5, 0.0);
  }
  draw_axes(cr, f);
  draw_series(cr, samples, f);
  draw_legend(cr, f);
}

}  // namespace

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

void write_energy_plot(const std::vector<EnergySample>& samples, const std::string& path,
                       const EnergyPlotStyle& style) {
  write_picture(path, picture_format_for(path), style.width, style.height,
                [&](cairo_t* cr) { paint_plot(cr, samples, style); });
}

}  // namespace fosssim
