#pragma once
// Line plots drawn with Cairo: curves over linear or logarithmic axes, with a grid, tick labels,
// axis titles, reference lines and a legend, written as PNG or SVG. A plot is described as data
// (LinePlot) and then painted; the energy plot and the oracle's residual plot are two of them.

#include <string>
#include <vector>

#include "core/scene.h"

namespace fosssim {

enum class AxisScale { kLinear, kLog10 };

struct PlotAxis {
  std::string title;  ///< e.g. "time (s)"
  AxisScale scale = AxisScale::kLinear;
  double low = 0.0, high = 1.0;  ///< the range shown, low < high; kLog10: both > 0, and the
                                 ///< ticks are the powers of ten between them
  bool zero_at_low = false;      ///< kLog10: `low` is labelled 0, for plots whose zeros (drawn on
                             ///< the low edge, as every value ≤ 0 is) have a line of their own
};

struct PlotPoint {
  double x = 0.0, y = 0.0;  ///< in data units
};

struct PlotCurve {
  std::string name;  ///< shown in the legend; a curve without a name is not
  Color color;
  double width = 1.6;  ///< pixels
  /// Joined in order. A NaN coordinate breaks the line; values beyond an axis's range,
  /// infinities included, are drawn on the nearest edge of the plot area.
  std::vector<PlotPoint> points;
};

/// A straight line across the plot area at a value of one axis, e.g. a threshold.
struct ReferenceLine {
  enum class Direction { kHorizontal, kVertical };
  Direction direction = Direction::kHorizontal;  ///< kHorizontal: at y = value; kVertical: x
  double value = 0.0;
  std::string label;  ///< written beside the line, in its colour
  Color color;
  std::vector<double> dashes;  ///< on and off lengths in pixels; solid when empty
};

struct LinePlot {
  int width = 800, height = 500;  ///< pixels
  std::string title;              ///< drawn above the plot area
  PlotAxis x, y;
  std::vector<ReferenceLine> references;  ///< drawn under the curves
  std::vector<PlotCurve> curves;          ///< drawn in order, the last on top
  std::string note;                       ///< after the legend, e.g. how special values are drawn
};

/// Where a plot's data land in its picture: the plot area in pixels (origin top-left, y down)
/// and the mapping of data values to pixels, clamped to the area (NaN stays NaN).
class PlotFrame {
 public:
  explicit PlotFrame(const LinePlot& plot);

  double left, top, right, bottom;  ///< the plot area, pixels
  double x(double value) const;     ///< the column of an x value
  double y(double value) const;     ///< the row of a y value

 private:
  AxisScale x_scale_, y_scale_;
  double x_low_, x_high_, y_low_, y_high_;  // log10 of the range on a kLog10 axis
};

/// A tick of an axis: a grid line at `value`, labelled `label` unless that is empty.
struct PlotTick {
  double value = 0.0;
  std::string label;
};

/// The ticks of an axis. kLinear: nice_ticks(), labelled with up to 6 significant digits.
/// kLog10: every power of ten in the range, labelled "1e-15" (or 0, see zero_at_low); at most
/// about ten labels, every k-th decade counted from the top one when there are more decades.
std::vector<PlotTick> axis_ticks(const PlotAxis& axis);

/// Tick positions for an axis from `low` to `high`: multiples of 1, 2 or 5 × 10^k chosen so that
/// there are about `target` of them inside [low, high].
std::vector<double> nice_ticks(double low, double high, int target = 6);

/// Writes the plot as a PNG, or an SVG when `path` ends in ".svg": white background, title,
/// grid and tick labels, axis titles, reference lines, curves (clipped to the plot area), and
/// below the axes a legend of the named curves followed by the note. Written under a temporary
/// name and renamed. Throws Error (kCannotWrite) on an I/O error.
void write_line_plot(const LinePlot& plot, const std::string& path);

}  // namespace fosssim
