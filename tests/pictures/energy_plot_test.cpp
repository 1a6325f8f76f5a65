#include "pictures/energy_plot.h"

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "app_render/program_runner.h"
#include "pictures/cairo_painter.h"

namespace fosssim {
namespace {

std::vector<EnergySample> oscillator(int n) {
  std::vector<EnergySample> samples;
  for (int k = 0; k < n; ++k) {
    const double t = 0.01 * k;
    samples.push_back({t, std::pow(std::sin(3 * t), 2), std::pow(std::cos(3 * t), 2) - 0.5});
  }
  return samples;
}

/// Number of pixels within `tolerance` of `color`.
int count_color(const Image& image, const Color& color, double tolerance = 0.08) {
  int n = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x)
      n += color_distance(image.color_at(x, y), color) < tolerance;
  }
  return n;
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

TEST(WriteEnergyPlot, DrawsEveryCurveOnAPictureOfTheRequestedSize) {
  const testing::ScratchFolder folder;
  EnergyPlotStyle style;
  style.width = 640;
  style.height = 400;
  style.title = "oscillator";
  write_energy_plot(oscillator(300), folder / "energy.png", style);
  EXPECT_FALSE(std::filesystem::exists(folder / "energy.png.partial"));
  const Image image = read_png(folder / "energy.png");
  EXPECT_EQ(image.width, 640);
  EXPECT_EQ(image.height, 400);
  EXPECT_GT(count_color(image, {0.122, 0.467, 0.706}), 300);  // kinetic, blue
  EXPECT_GT(count_color(image, {1.0, 0.498, 0.055}), 300);    // potential, orange
  EXPECT_GT(count_color(image, {0.1, 0.1, 0.1}), 300);        // total, near black
}

TEST(WriteEnergyPlot, TheTotalOfAConservedRunIsAFlatLine) {
  // Total = 0.5 throughout: the total's dark pixels in the plot area lie on one row (give or
  // take anti-aliasing), while kinetic and potential swing over many rows.
  const testing::ScratchFolder folder;
  write_energy_plot(oscillator(300), folder / "flat.png");
  const Image image = read_png(folder / "flat.png");
  int top = image.height, bottom = -1;
  for (int y = 60; y < image.height - 70; ++y) {
    for (int x = 200; x < 600; ++x) {  // inside the plot, clear of the legend and axes
      if (color_distance(image.color_at(x, y), {0.1, 0.1, 0.1}) < 0.05) {
        top = std::min(top, y);
        bottom = std::max(bottom, y);
      }
    }
  }
  ASSERT_GE(bottom, 0);
  EXPECT_LE(bottom - top, 3);
}

TEST(WriteEnergyPlot, SkipsNonFiniteSamplesAndWritesSvg) {
  const testing::ScratchFolder folder;
  auto samples = oscillator(100);
  samples[50].kinetic = std::numeric_limits<double>::quiet_NaN();
  samples[60].potential = std::numeric_limits<double>::infinity();
  write_energy_plot(samples, folder / "energy.svg");
  tinyxml2::XMLDocument document;
  ASSERT_EQ(document.LoadFile((folder / "energy.svg").c_str()), tinyxml2::XML_SUCCESS);
  EXPECT_STREQ(document.RootElement()->Name(), "svg");
  EXPECT_STREQ(document.RootElement()->Attribute("width"), "800px");
}

TEST(WriteEnergyPlot, HandlesNoSamplesAndConstantEnergy) {
  const testing::ScratchFolder folder;
  EXPECT_NO_THROW(write_energy_plot({}, folder / "empty.png"));
  EXPECT_NO_THROW(write_energy_plot({{0.0, 1.0, 1.0}, {1.0, 1.0, 1.0}}, folder / "constant.png"));
  EXPECT_TRUE(std::filesystem::exists(folder / "constant.png"));
}

}  // namespace
}  // namespace fosssim
