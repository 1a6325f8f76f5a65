#include "residual_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace fosssim {

namespace {

// Canvas and plot area, in SVG user units (pixels).
constexpr double kWidth = 760, kHeight = 440;
constexpr double kLeft = 80, kRight = 730, kTop = 56, kBottom = 360;

/// One plotted column: the time and the largest residual of the steps it stands for.
struct Column {
  double time = 0.0;
  double position = 0.0;
  double velocity = 0.0;
};

std::vector<Column> reduce(const std::vector<StepResidual>& per_step, double dt, int max_points) {
  const std::size_t n = per_step.size();
  const std::size_t columns = std::min<std::size_t>(n, std::max(max_points, 2));
  std::vector<Column> out(columns);
  for (std::size_t c = 0; c < columns; ++c) {
    const std::size_t begin = c * n / columns, end = (c + 1) * n / columns;
    Column& column = out[c];
    column.time = static_cast<double>(per_step[end - 1].step) * dt;
    for (std::size_t i = begin; i < end; ++i) {
      if (i == begin || replaces_maximum(per_step[i].max_position, column.position))
        column.position = per_step[i].max_position;
      if (i == begin || replaces_maximum(per_step[i].max_velocity, column.velocity))
        column.velocity = per_step[i].max_velocity;
    }
  }
  return out;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.2f", value);
  return text;
}

std::string short_number(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.4g", value);
  return text;
}

/// The decades shown: from below the smallest positive residual (or the limit) to above the
/// largest finite one, at least two decades.
std::pair<int, int> decade_range(const std::vector<Column>& columns, double limit) {
  double smallest = limit, largest = limit;
  for (const Column& c : columns) {
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

/// Escapes &, <, >, " and ' for XML text and attributes.
std::string escape_xml(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace

std::string residual_plot_svg(const std::vector<StepResidual>& per_step,
                              const ResidualPlotOptions& options) {
  const std::vector<Column> columns =
      per_step.empty() ? std::vector<Column>{} : reduce(per_step, options.dt, options.max_points);
  bool has_zero = false, has_non_finite = false;
  for (const Column& c : columns) {
    for (double v : {c.position, c.velocity}) {
      has_zero = has_zero || v == 0.0;
      has_non_finite = has_non_finite || !std::isfinite(v);
    }
  }
  const auto decades = decade_range(columns, options.limit);
  // Zeros get the bottom line of their own, one decade below the smallest residual.
  const int low = decades.first - (has_zero ? 1 : 0), high = decades.second;
  const double end_time =
      per_step.empty() ? options.dt
                       : std::max(static_cast<double>(per_step.back().step) * options.dt, 1e-300);
  const auto x_of = [&](double t) { return kLeft + (kRight - kLeft) * t / end_time; };
  const auto y_of = [&](double v) {
    if (!std::isfinite(v)) return kTop;
    if (v <= 0.0) return kBottom;
    const double e = std::clamp(std::log10(v), double(low), double(high));
    return kBottom - (kBottom - kTop) * (e - low) / (high - low);
  };

  std::ostringstream svg;
  svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << kHeight
      << "\" viewBox=\"0 0 " << kWidth << " " << kHeight
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << kWidth / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"14\">"
      << escape_xml(options.title) << "</text>\n";
  // Decade grid and labels; at most about ten labels, counted from the top decade.
  const int label_every = std::max(1, (high - low + 9) / 10);
  for (int e = low; e <= high; ++e) {
    const double y = y_of(std::pow(10.0, e));
    svg << "<line x1=\"" << kLeft << "\" y1=\"" << number(y) << "\" x2=\"" << kRight << "\" y2=\""
        << number(y) << "\" stroke=\"#e4e4e4\"/>\n";
    if (e == low && has_zero) {
      svg << "<text x=\"" << kLeft - 6 << "\" y=\"" << number(y + 4)
          << "\" text-anchor=\"end\">0</text>\n";
    } else if ((high - e) % label_every == 0) {
      svg << "<text x=\"" << kLeft - 6 << "\" y=\"" << number(y + 4) << "\" text-anchor=\"end\">1e"
          << e << "</text>\n";
    }
  }
  for (int k = 0; k <= 5; ++k) {
    const double t = end_time * k / 5.0;
    svg << "<text x=\"" << number(x_of(t)) << "\" y=\"" << kBottom + 18
        << "\" text-anchor=\"middle\">" << short_number(t) << "</text>\n";
  }
  svg << "<rect x=\"" << kLeft << "\" y=\"" << kTop << "\" width=\"" << kRight - kLeft
      << "\" height=\"" << kBottom - kTop << "\" fill=\"none\" stroke=\"black\"/>\n"
      << "<text x=\"" << (kLeft + kRight) / 2 << "\" y=\"" << kBottom + 38
      << "\" text-anchor=\"middle\">simulated time (s)</text>\n"
      << "<text transform=\"translate(18 " << (kTop + kBottom) / 2
      << ") rotate(-90)\" text-anchor=\"middle\">largest residual of the step</text>\n";
  // The course's maximum limit.
  const double limit_y = y_of(options.limit);
  svg << "<line x1=\"" << kLeft << "\" y1=\"" << number(limit_y) << "\" x2=\"" << kRight
      << "\" y2=\"" << number(limit_y) << "\" stroke=\"#d62728\" stroke-dasharray=\"6 4\"/>\n"
      << "<text x=\"" << kRight - 4 << "\" y=\"" << number(limit_y - 5)
      << "\" text-anchor=\"end\" fill=\"#d62728\">maximum limit " << short_number(options.limit)
      << "</text>\n";
  if (options.marked_step) {
    const double x = x_of(static_cast<double>(*options.marked_step) * options.dt);
    svg << "<line x1=\"" << number(x) << "\" y1=\"" << kTop << "\" x2=\"" << number(x) << "\" y2=\""
        << kBottom << "\" stroke=\"#555555\" stroke-dasharray=\"2 3\"/>\n"
        << "<text x=\"" << number(x + 4) << "\" y=\"" << kTop + 14
        << "\" fill=\"#555555\">first divergence: step " << *options.marked_step << "</text>\n";
  }
  const auto polyline = [&](double Column::*series, const char* color) {
    svg << "<polyline fill=\"none\" stroke=\"" << color << "\" stroke-width=\"1.5\" points=\"";
    for (const Column& c : columns)
      svg << number(x_of(c.time)) << "," << number(y_of(c.*series)) << " ";
    svg << "\"/>\n";
  };
  polyline(&Column::position, "#1f77b4");
  polyline(&Column::velocity, "#ff7f0e");
  // Legend.
  const double legend_y = kHeight - 18;
  svg << "<line x1=\"" << kLeft << "\" y1=\"" << legend_y - 4 << "\" x2=\"" << kLeft + 24
      << "\" y2=\"" << legend_y - 4 << "\" stroke=\"#1f77b4\" stroke-width=\"2\"/>\n"
      << "<text x=\"" << kLeft + 30 << "\" y=\"" << legend_y << "\">position</text>\n"
      << "<line x1=\"" << kLeft + 110 << "\" y1=\"" << legend_y - 4 << "\" x2=\"" << kLeft + 134
      << "\" y2=\"" << legend_y - 4 << "\" stroke=\"#ff7f0e\" stroke-width=\"2\"/>\n"
      << "<text x=\"" << kLeft + 140 << "\" y=\"" << legend_y << "\">velocity</text>\n";
  std::string notes;
  if (has_zero) notes += "Exact zeros are drawn on the bottom line. ";
  if (has_non_finite) notes += "NaN or infinite residuals are drawn on the top edge.";
  if (!notes.empty()) {
    svg << "<text x=\"" << kLeft + 230 << "\" y=\"" << legend_y << "\" fill=\"#555555\">"
        << escape_xml(notes) << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace fosssim
