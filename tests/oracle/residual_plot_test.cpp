#include "residual_plot.h"

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cmath>
#include <limits>

#include "pictures/cairo_painter.h"
#include "support/pixel_counts.h"
#include "test_support.h"

namespace fosssim {
namespace {

/// Steps 1..steps: position residual 0 up to step 9, then 10^(-16 + 0.1 k); velocity 1e-12.
std::vector<StepResidual> ramp(int steps) {
  std::vector<StepResidual> per_step;
  for (int k = 1; k <= steps; ++k) {
    StepResidual r;
    r.step = k;
    r.max_position = k < 10 ? 0.0 : std::pow(10.0, -16.0 + 0.1 * k);
    r.max_velocity = 1e-12;
    per_step.push_back(r);
  }
  return per_step;
}

ResidualPlotOptions ramp_options() {
  ResidualPlotOptions options;
  options.title = "scene <&> \"quoted\"";
  options.dt = 0.01;
  options.marked_step = 60;
  return options;
}

std::vector<std::string> tick_labels(const PlotAxis& axis) {
  std::vector<std::string> labels;
  for (const PlotTick& t : axis_ticks(axis)) labels.push_back(t.label);
  return labels;
}

bool plot_contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(ResidualPlot, ShowsBothSeriesTheLimitAndTheMarkerOnALogAxis) {
  const LinePlot plot = residual_plot(ramp(100), ramp_options());
  EXPECT_EQ(plot.title, "scene <&> \"quoted\"");
  ASSERT_EQ(plot.curves.size(), 2u);
  EXPECT_EQ(plot.curves[0].name, "position");
  EXPECT_EQ(plot.curves[1].name, "velocity");
  ASSERT_EQ(plot.curves[0].points.size(), 100u);
  ASSERT_EQ(plot.curves[1].points.size(), 100u);
  EXPECT_DOUBLE_EQ(plot.curves[0].points[59].x, 0.6);  // step 60 at 0.01 s per step
  EXPECT_EQ(plot.curves[0].points[0].y, 0.0);
  EXPECT_EQ(plot.curves[1].points[99].y, 1e-12);
  EXPECT_DOUBLE_EQ(plot.x.high, 1.0);
  // The limit, dashed, and the first divergence, a vertical line at its time.
  ASSERT_EQ(plot.references.size(), 2u);
  EXPECT_EQ(plot.references[0].direction, ReferenceLine::Direction::kHorizontal);
  EXPECT_EQ(plot.references[0].value, 1e-10);
  EXPECT_EQ(plot.references[0].label, "maximum limit 1e-10");
  EXPECT_FALSE(plot.references[0].dashes.empty());
  EXPECT_EQ(plot.references[1].direction, ReferenceLine::Direction::kVertical);
  EXPECT_DOUBLE_EQ(plot.references[1].value, 0.6);
  EXPECT_EQ(plot.references[1].label, "first divergence: step 60");
  // Decades from 1e-15 (the smallest non-zero residual) to 1e-6 (the largest), with the zeros
  // of steps 1 to 9 on a line of their own below.
  EXPECT_EQ(plot.y.scale, AxisScale::kLog10);
  EXPECT_EQ(tick_labels(plot.y),
            (std::vector<std::string>{"0", "1e-15", "1e-14", "1e-13", "1e-12", "1e-11", "1e-10",
                                      "1e-9", "1e-8", "1e-7", "1e-6"}));
  EXPECT_TRUE(plot_contains(plot.note, "Exact zeros are drawn on the bottom line")) << plot.note;
  EXPECT_FALSE(plot_contains(plot.note, "NaN")) << plot.note;
}

TEST(ResidualPlot, AThemeFourVelocityLimitIsASecondDashedLine) {
  ResidualPlotOptions options = ramp_options();
  options.velocity_limit = 1e-9;
  const LinePlot plot = residual_plot(ramp(100), options);
  ASSERT_EQ(plot.references.size(), 3u);
  EXPECT_EQ(plot.references[0].value, 1e-10);
  EXPECT_EQ(plot.references[0].label, "maximum position limit 1e-10");
  EXPECT_EQ(plot.references[1].direction, ReferenceLine::Direction::kHorizontal);
  EXPECT_EQ(plot.references[1].value, 1e-9);
  EXPECT_EQ(plot.references[1].label, "maximum velocity limit 1e-9");
  EXPECT_FALSE(plot.references[1].dashes.empty());
  EXPECT_EQ(plot.references[2].direction, ReferenceLine::Direction::kVertical);
  // A velocity limit equal to the position limit is the one line of Theme 1.
  options.velocity_limit = 1e-10;
  const LinePlot theme1 = residual_plot(ramp(100), options);
  ASSERT_EQ(theme1.references.size(), 2u);
  EXPECT_EQ(theme1.references[0].label, "maximum limit 1e-10");
}

TEST(ResidualPlot, WithoutZerosOrMarkerThereIsNoZeroLineAndNoVerticalLine) {
  std::vector<StepResidual> per_step = ramp(100);
  per_step.erase(per_step.begin(), per_step.begin() + 9);  // the zeros
  ResidualPlotOptions options = ramp_options();
  options.marked_step.reset();
  const LinePlot plot = residual_plot(per_step, options);
  ASSERT_EQ(plot.references.size(), 1u);
  EXPECT_EQ(tick_labels(plot.y).front(), "1e-15");
  EXPECT_EQ(plot.note, "");
}

TEST(ResidualPlot, LongRunsAreReducedKeepingTheLargestResidual) {
  std::vector<StepResidual> per_step(100000);
  for (std::size_t k = 0; k < per_step.size(); ++k) {
    per_step[k].step = static_cast<std::int64_t>(k + 1);
    per_step[k].max_position = 1e-14;
    per_step[k].max_velocity = 1e-14;
  }
  per_step[77777].max_position = 1e-3;
  per_step[500].max_velocity = std::numeric_limits<double>::quiet_NaN();
  ResidualPlotOptions options;
  options.max_points = 1000;
  const LinePlot plot = residual_plot(per_step, options);
  ASSERT_EQ(plot.curves.size(), 2u);
  ASSERT_EQ(plot.curves[0].points.size(), 1000u);
  EXPECT_EQ(plot.curves[0].points[777].y, 1e-3);  // the spike survives in its column
  EXPECT_EQ(plot.curves[0].points[776].y, 1e-14);
  EXPECT_EQ(plot.curves[1].points[5].y, std::numeric_limits<double>::infinity());  // the NaN
  EXPECT_EQ(tick_labels(plot.y).back(), "1e-3");  // the spike set the top decade
  EXPECT_TRUE(plot_contains(plot.note, "NaN or infinite residuals are drawn on the top edge"));
}

// Grading streams its steps: columns are filled as steps come, sized from the steps announced,
// and a grading that stops early plots the columns it reached.
TEST(ResidualColumns, ReduceStepsAsTheyComeAndStopWhereTheGradingStopped) {
  ResidualColumns columns(10, 4);  // columns of 3, 3, 2 and 2 steps
  for (const StepResidual& r : ramp(5)) columns.add(r);
  ASSERT_EQ(columns.columns().size(), 2u);
  EXPECT_EQ(columns.columns()[0].last_step, 3);
  EXPECT_EQ(columns.columns()[1].last_step, 5);
  EXPECT_EQ(columns.columns()[1].velocity, 1e-12);
  for (const StepResidual& r : ramp(10)) {
    if (r.step > 5) columns.add(r);
  }
  ASSERT_EQ(columns.columns().size(), 4u);
  EXPECT_EQ(columns.columns()[2].last_step, 8);
  EXPECT_EQ(columns.columns()[3].last_step, 10);
  EXPECT_EQ(columns.columns()[3].position, std::pow(10.0, -16.0 + 0.1 * 10));  // the larger
  const LinePlot plot = residual_plot(columns, ramp_options());
  EXPECT_EQ(plot.curves[0].points.size(), 4u);
  EXPECT_DOUBLE_EQ(plot.x.high, 0.1);
}

TEST(ResidualPlot, IsDrawnWithTheLimitTheMarkerAndBothCurvesWhereTheyBelong) {
  const testing::TemporaryFolder folder;
  const LinePlot plot = residual_plot(ramp(100), ramp_options());
  write_line_plot(plot, folder / "plot.png");
  const Image image = read_png(folder / "plot.png");
  EXPECT_EQ(image.width, plot.width);
  const PlotFrame f(plot);
  const auto row = [&](double residual) { return static_cast<int>(std::lround(f.y(residual))); };
  const auto column = [&](double time) { return static_cast<int>(std::lround(f.x(time))); };
  /// Whether a pixel next to (time, residual) shows at least half of `color`.
  const auto drawn_at = [&](double time, double residual, const Color& color) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const Color shown = image.color_at(column(time) + dx, row(residual) + dy);
        if (testing::coverage(shown, color) >= 0.5) return true;
      }
    }
    return false;
  };
  const Color red{0.839, 0.153, 0.157}, grey{0.333, 0.333, 0.333};
  const Color blue{0.122, 0.467, 0.706}, orange{1.0, 0.498, 0.055};
  // The limit at 1e-10 is dashed (6 on, 4 off): about 60% of its row, from t = 0.1 to 0.5.
  int red_pixels = 0;
  for (int x = column(0.1); x < column(0.5); ++x)
    red_pixels += testing::coverage(image.color_at(x, row(1e-10)), red) >= 0.5;
  EXPECT_GT(red_pixels, 0.5 * (column(0.5) - column(0.1)));
  EXPECT_LT(red_pixels, 0.7 * (column(0.5) - column(0.1)));
  // The first divergence, dotted (2 on, 3 off): about 40% of the column of step 60 below its
  // label, and nothing grey in the column of step 40.
  const auto grey_in_column = [&](double time) {
    int n = 0;
    for (int y = row(1e-8); y < row(1e-15); ++y)
      n += testing::coverage(image.color_at(column(time), y), grey) >= 0.5;
    return n;
  };
  EXPECT_GT(grey_in_column(0.6), 0.3 * (row(1e-15) - row(1e-8)));
  EXPECT_EQ(grey_in_column(0.4), 0);
  // The curves: position 10^(-16 + 0.1 k) at step k, zeros on the bottom line; velocity 1e-12.
  EXPECT_TRUE(drawn_at(0.5, 1e-11, blue));
  EXPECT_TRUE(drawn_at(0.8, 1e-8, blue));
  EXPECT_TRUE(drawn_at(0.05, 0.0, blue));
  EXPECT_FALSE(drawn_at(0.5, 1e-9, blue));
  EXPECT_TRUE(drawn_at(0.3, 1e-12, orange));
  EXPECT_FALSE(drawn_at(0.3, 1e-9, orange));
}

TEST(ResidualPlot, EmptyRunStillGivesAnSvgDocument) {
  const testing::TemporaryFolder folder;
  write_line_plot(residual_plot({}, {}), folder / "empty.svg");
  tinyxml2::XMLDocument document;
  ASSERT_EQ(document.LoadFile((folder / "empty.svg").c_str()), tinyxml2::XML_SUCCESS);
  EXPECT_STREQ(document.RootElement()->Name(), "svg");
}

}  // namespace
}  // namespace fosssim
