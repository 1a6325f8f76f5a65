#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "pictures/cairo_painter.h"
#include "support/pixel_counts.h"
#include "support/run_program.h"
#include "support/scratch_folder.h"

namespace fosssim {
namespace {

// A particle of mass 2 thrown sideways under gravity g = (0, -10), five explicit Euler steps
// of h = 0.1. By hand: v_k = (1, -10 k h), y_k = -10 h² k(k-1)/2, so
// T_k = ½ m (1 + (10 k h)²) and U_k = -m g·x_k = 10 m y_k.
constexpr const char* kThrow = R"(<scene>
  <duration time="0.5"/><integrator type="explicit-euler" dt="0.1"/>
  <particle m="2" px="0" py="0" vx="1" vy="0" fixed="0"/>
  <simplegravity fx="0" fy="-10"/>
</scene>)";

TEST(CliEnergy, CsvHoldsTheEnergiesOfEveryState) {
  const testing::ScratchFolder folder;
  folder.write("throw.xml", kThrow);
  const auto result = testing::run_command(folder, testing::quoted(testing::fosssim_program()) +
                                                       " -s throw.xml -d 0 --energy-csv e.csv");
  ASSERT_EQ(result.status, 0) << result.err;
  std::istringstream csv(testing::read_file(folder / "e.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "time,kinetic,potential,total");
  const double m = 2.0, h = 0.1;
  int k = 0;
  while (std::getline(csv, line)) {
    double t, kinetic, potential, total;
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf", &t, &kinetic, &potential, &total), 4);
    const double vy = -10.0 * k * h;
    const double y = -10.0 * h * h * k * (k - 1) / 2.0;
    EXPECT_NEAR(t, k * h, 1e-12);
    EXPECT_NEAR(kinetic, 0.5 * m * (1.0 + vy * vy), 1e-12) << "state " << k;
    EXPECT_NEAR(potential, 10.0 * m * y, 1e-12) << "state " << k;
    EXPECT_DOUBLE_EQ(total, kinetic + potential);
    ++k;
  }
  EXPECT_EQ(k, 6);
}

TEST(CliEnergy, PlotIsAPicture) {
  const testing::ScratchFolder folder;
  folder.write("throw.xml", kThrow);
  const auto result = testing::run_command(folder, testing::quoted(testing::fosssim_program()) +
                                                       " -s throw.xml -d 0 --energy-plot e.png");
  ASSERT_EQ(result.status, 0) << result.err;
  const Image plot = read_png(folder / "e.png");
  EXPECT_EQ(plot.width, 800);
  EXPECT_EQ(plot.height, 500);
  // The three curves are drawn (each spans the plot; the legend alone has a few dozen pixels).
  EXPECT_GT(testing::count_color(plot, {0.122, 0.467, 0.706}), 200);  // kinetic, blue
  EXPECT_GT(testing::count_color(plot, {1.0, 0.498, 0.055}), 200);    // potential, orange
  EXPECT_GT(testing::count_color(plot, {0.1, 0.1, 0.1}), 200);        // total, near black
}

}  // namespace
}  // namespace fosssim
