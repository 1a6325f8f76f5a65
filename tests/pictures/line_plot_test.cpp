#include "pictures/line_plot.h"

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cmath>
#include <limits>

#include "pictures/cairo_painter.h"
#include "support/pixel_counts.h"
#include "support/scratch_folder.h"

namespace fosssim {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const Color kReferenceRed{0.84, 0.15, 0.16};
const Color kBlue{0.12, 0.47, 0.71};

using testing::coverage;

/// Pixels showing at least half of `color` in row `y` between columns x0 and x1 (exclusive), or
/// in column `x` between rows y0 and y1.
int in_row(const Image& image, const Color& color, int y, int x0, int x1) {
  int n = 0;
  for (int x = x0; x < x1; ++x) n += coverage(image.color_at(x, y), color) >= 0.5;
  return n;
}
int in_column(const Image& image, const Color& color, int x, int y0, int y1) {
  int n = 0;
  for (int y = y0; y < y1; ++y) n += coverage(image.color_at(x, y), color) >= 0.5;
  return n;
}

std::vector<std::string> labels(const std::vector<PlotTick>& ticks) {
  std::vector<std::string> out;
  for (const PlotTick& t : ticks) out.push_back(t.label);
  return out;
}

TEST(NiceTicks, AreRoundNumbersInsideTheRange) {
  EXPECT_EQ(nice_ticks(0.0, 1.0, 5), (std::vector<double>{0.0, 0.2, 0.4, 0.6, 0.8, 1.0}));
  EXPECT_EQ(nice_ticks(-3.0, 7.0, 6), (std::vector<double>{-2.0, 0.0, 2.0, 4.0, 6.0}));
  const auto small = nice_ticks(0.00123, 0.00177, 5);
  ASSERT_FALSE(small.empty());
  for (double t : small) {
    EXPECT_GE(t, 0.00123);
    EXPECT_LE(t, 0.00177);
  }
  EXPECT_TRUE(nice_ticks(1.0, 1.0).empty());
}

TEST(AxisTicks, LinearAxesGetNiceTicksWithShortLabels) {
  PlotAxis axis;
  axis.low = -0.1;
  axis.high = 0.5;
  EXPECT_EQ(labels(axis_ticks(axis)),
            (std::vector<std::string>{"-0.1", "0", "0.1", "0.2", "0.3", "0.4", "0.5"}));
}

TEST(AxisTicks, LogAxesGetOneTickPerDecadeAndAboutTenLabels) {
  PlotAxis axis;
  axis.scale = AxisScale::kLog10;
  axis.low = 1e-16;
  axis.high = 1e-12;
  EXPECT_EQ(labels(axis_ticks(axis)),
            (std::vector<std::string>{"1e-16", "1e-15", "1e-14", "1e-13", "1e-12"}));
  axis.zero_at_low = true;  // the bottom decade stands for exact zeros
  EXPECT_EQ(labels(axis_ticks(axis)),
            (std::vector<std::string>{"0", "1e-15", "1e-14", "1e-13", "1e-12"}));
  // 32 decades: a grid line each, a label every 4th counted from the top.
  axis.zero_at_low = false;
  axis.low = 1e-31;
  axis.high = 1.0;
  const auto ticks = axis_ticks(axis);
  ASSERT_EQ(ticks.size(), 32u);
  EXPECT_EQ(ticks.back().label, "1e0");
  EXPECT_EQ(ticks[ticks.size() - 5].label, "1e-4");
  EXPECT_EQ(ticks[ticks.size() - 2].label, "");
  EXPECT_EQ(ticks[3].label, "1e-28");
  EXPECT_EQ(ticks.front().label, "");  // 1e-31 is not a multiple of 4 decades below 1e0
}

TEST(PlotFrame, MapsLogValuesAndClampsToTheEdges) {
  LinePlot plot;
  plot.y.scale = AxisScale::kLog10;
  plot.y.low = 1e-16;
  plot.y.high = 1e-6;
  plot.x.high = 10.0;
  const PlotFrame f(plot);
  EXPECT_NEAR(f.y(1e-11), 0.5 * (f.top + f.bottom), 1e-9);
  EXPECT_NEAR(f.x(2.5), f.left + 0.25 * (f.right - f.left), 1e-9);
  EXPECT_EQ(f.y(kInfinity), f.top);
  EXPECT_EQ(f.y(1.0), f.top);
  EXPECT_EQ(f.y(0.0), f.bottom);
  EXPECT_EQ(f.y(-1.0), f.bottom);
  EXPECT_TRUE(std::isnan(f.y(kNaN)));
  EXPECT_EQ(f.x(-kInfinity), f.left);
}

/// A plot of one blue curve at y = 0.5 on [0, 1] with a gap at x = 0.5, a red dashed
/// horizontal line at y = 0.25 and a red vertical line at x = 0.75.
LinePlot gapped_line() {
  LinePlot plot;
  plot.width = 400;
  plot.height = 300;
  plot.title = "gapped";
  plot.curves.push_back(
      {"curve", kBlue, 2.0, {{0.0, 0.5}, {0.4, 0.5}, {0.5, kNaN}, {0.6, 0.5}, {1.0, 0.5}}});
  plot.references.push_back(
      {ReferenceLine::Direction::kHorizontal, 0.25, "quarter", kReferenceRed, {6.0, 4.0}});
  plot.references.push_back({ReferenceLine::Direction::kVertical, 0.75, "mark", kReferenceRed, {}});
  return plot;
}

TEST(WriteLinePlot, DrawsCurvesWithTheirGapsAndTheReferenceLines) {
  const testing::ScratchFolder folder;
  const LinePlot plot = gapped_line();
  write_line_plot(plot, folder / "plot.png");
  EXPECT_FALSE(std::filesystem::exists(folder / "plot.png.partial"));
  const Image image = read_png(folder / "plot.png");
  ASSERT_EQ(image.width, 400);
  ASSERT_EQ(image.height, 300);
  const PlotFrame f(plot);
  const auto row = [&](double y) { return static_cast<int>(std::lround(f.y(y))); };
  const auto column = [&](double x) { return static_cast<int>(std::lround(f.x(x))); };
  const int top = static_cast<int>(f.top), bottom = static_cast<int>(f.bottom);
  // The curve runs along its row, except across the gap around x = 0.5.
  const int left_part = column(0.35) - column(0.05), right_part = column(0.95) - column(0.65);
  EXPECT_GT(in_row(image, kBlue, row(0.5), column(0.05), column(0.35)), 0.9 * left_part);
  EXPECT_GT(in_row(image, kBlue, row(0.5), column(0.65), column(0.95)), 0.9 * right_part);
  EXPECT_EQ(in_column(image, kBlue, column(0.5), top, bottom), 0);
  // The dashed line (6 on, 4 off) covers about 60% of its row; the solid one its column.
  const int dashed_part = column(0.7) - column(0.0) - 2;
  const int dashed = in_row(image, kReferenceRed, row(0.25), column(0.0) + 2, column(0.7));
  EXPECT_GT(dashed, 0.5 * dashed_part);
  EXPECT_LT(dashed, 0.7 * dashed_part);
  EXPECT_GT(in_column(image, kReferenceRed, column(0.75), row(0.5) + 3, bottom),
            0.95 * (bottom - row(0.5) - 3));
  EXPECT_LE(in_column(image, kReferenceRed, column(0.65), row(0.5) + 3, bottom),
            1);  // the dashed line
}

TEST(WriteLinePlot, DrawsInfiniteValuesOnTheEdgeAndWritesSvg) {
  const testing::ScratchFolder folder;
  LinePlot plot;
  plot.curves.push_back({"", kBlue, 2.0, {{0.0, kInfinity}, {1.0, kInfinity}}});
  write_line_plot(plot, folder / "edge.png");
  const Image image = read_png(folder / "edge.png");
  const PlotFrame f(plot);
  const int x0 = static_cast<int>(f.left) + 5, x1 = static_cast<int>(f.right) - 5;
  EXPECT_GT(in_row(image, kBlue, static_cast<int>(std::lround(f.top)), x0, x1), 0.9 * (x1 - x0));
  // An unnamed curve has no legend entry: no blue below the plot area.
  int below = 0;
  for (int y = static_cast<int>(f.bottom) + 2; y < image.height; ++y)
    below += in_row(image, kBlue, y, 0, image.width);
  EXPECT_EQ(below, 0);

  write_line_plot(gapped_line(), folder / "plot.svg");
  tinyxml2::XMLDocument document;
  ASSERT_EQ(document.LoadFile((folder / "plot.svg").c_str()), tinyxml2::XML_SUCCESS);
  EXPECT_STREQ(document.RootElement()->Name(), "svg");
  EXPECT_STREQ(document.RootElement()->Attribute("width"), "400px");
}

}  // namespace
}  // namespace fosssim
