#include "pictures/energy_plot.h"

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <utility>

#include "pictures/cairo_painter.h"
#include "support/pixel_counts.h"
#include "support/scratch_folder.h"

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

using testing::count_color;

/// The first and last rows of the plot area (default style, no title) with pixels near `color`,
/// in columns 200 to 600: clear of the axes, their labels and the legend. {height, -1} if none.
std::pair<int, int> rows_of_color(const Image& image, const Color& color, int first_row) {
  int top = image.height, bottom = -1;
  for (int y = first_row; y < image.height - 70; ++y) {
    for (int x = 200; x < 600; ++x) {
      if (color_distance(image.color_at(x, y), color) < 0.05) {
        top = std::min(top, y);
        bottom = std::max(bottom, y);
      }
    }
  }
  return {top, bottom};
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
  const auto [top, bottom] = rows_of_color(image, {0.1, 0.1, 0.1}, 60);
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
  // No samples: an empty plot of the default size.
  ASSERT_TRUE(std::filesystem::exists(folder / "empty.png"));
  const Image empty = read_png(folder / "empty.png");
  EXPECT_EQ(empty.width, EnergyPlotStyle{}.width);
  EXPECT_EQ(empty.height, EnergyPlotStyle{}.height);
  // Constant energy (kinetic = potential = 1, total = 2): each curve is a flat line on one row
  // (the total near the top of the plot, potential over kinetic near the bottom).
  const Image constant = read_png(folder / "constant.png");
  const auto [total_top, total_bottom] = rows_of_color(constant, {0.1, 0.1, 0.1}, 20);
  ASSERT_GE(total_bottom, 0);
  EXPECT_LE(total_bottom - total_top, 3);
  const auto [potential_top, potential_bottom] = rows_of_color(constant, {1.0, 0.498, 0.055}, 20);
  ASSERT_GE(potential_bottom, 0);
  EXPECT_LE(potential_bottom - potential_top, 3);
  EXPECT_GT(potential_top, total_bottom);
}

// Issue 24: --energy-plot kept every step's energies. The history keeps at most kBuckets
// buckets: a run of up to 2 kBuckets states exactly, a longer one as each bucket's extremes.
TEST(EnergyHistory, KeepsRunsOfUpToTwiceItsBucketsExactly) {
  const int n = 2 * EnergyHistory::kBuckets;
  const std::vector<EnergySample> samples = oscillator(n);
  EnergyHistory history;
  for (const EnergySample& s : samples) history.add(s);
  EXPECT_EQ(history.count(), n);
  EXPECT_EQ(history.bucket_size(), 2);
  const auto total = history.points(2);
  ASSERT_EQ(total.size(), static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    EXPECT_EQ(total[k][0], samples[k].time) << k;
    EXPECT_EQ(total[k][1], samples[k].total()) << k;
  }
}

TEST(EnergyHistory, AMillionStatesTakeBoundedPointsAndKeepAOneStepSpike) {
  EnergyHistory history;
  constexpr int kStates = 1'000'000, kSpike = 777'777;
  for (int k = 0; k < kStates; ++k) {
    const double t = 1e-3 * k;
    history.add({t, k == kSpike ? 50.0 : 1.0 + 0.5 * std::sin(t), k == kSpike + 1 ? -7.0 : 0.0});
  }
  EXPECT_EQ(history.count(), kStates);
  EXPECT_EQ(history.bucket_size(), 256);  // 1e6 / 256 < 4096 <= 1e6 / 128
  double highest = 0.0, highest_time = 0.0, lowest = 0.0;
  for (int c = 0; c < EnergyHistory::kCurves; ++c) {
    const auto points = history.points(c);
    EXPECT_LE(points.size(), 2u * EnergyHistory::kBuckets);
    for (std::size_t k = 1; k < points.size(); ++k) EXPECT_LE(points[k - 1][0], points[k][0]);
    if (c == 0) {
      for (const auto& p : points) {
        if (p[1] > highest) highest = p[1], highest_time = p[0];
      }
    }
    if (c == 1) {
      for (const auto& p : points) lowest = std::min(lowest, p[1]);
    }
  }
  EXPECT_EQ(highest, 50.0);
  EXPECT_EQ(highest_time, 1e-3 * kSpike);
  EXPECT_EQ(lowest, -7.0);
}

TEST(EnergyHistory, ANonFiniteSampleBreaksTheCurveAfterItsBucket) {
  EnergyHistory history;
  history.add({0.0, 1.0, 1.0});
  history.add({0.1, std::numeric_limits<double>::quiet_NaN(), 1.0});
  history.add({0.2, 2.0, 1.0});
  const auto kinetic = history.points(0);
  ASSERT_EQ(kinetic.size(), 3u);
  EXPECT_EQ(kinetic[0][1], 1.0);
  EXPECT_TRUE(std::isnan(kinetic[1][1]));
  EXPECT_EQ(kinetic[2][1], 2.0);
}

}  // namespace
}  // namespace fosssim
