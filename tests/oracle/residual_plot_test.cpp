#include "residual_plot.h"

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cmath>
#include <limits>

namespace fosssim {
namespace {

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

/// Counts the points of the n-th polyline of an SVG document.
int polyline_points(const tinyxml2::XMLElement* svg, int n) {
  const tinyxml2::XMLElement* line = svg->FirstChildElement("polyline");
  for (int k = 0; k < n && line; ++k) line = line->NextSiblingElement("polyline");
  if (!line) return -1;
  const std::string points = line->Attribute("points");
  int count = 0;
  for (char c : points) count += c == ',';
  return count;
}

TEST(ResidualPlot, IsWellFormedSvgWithBothSeriesTheLimitAndTheMarker) {
  ResidualPlotOptions options;
  options.title = "scene <&> \"quoted\"";
  options.dt = 0.01;
  options.marked_step = 60;
  const std::string svg = residual_plot_svg(ramp(100), options);
  tinyxml2::XMLDocument document;
  ASSERT_EQ(document.Parse(svg.c_str()), tinyxml2::XML_SUCCESS) << svg;
  const tinyxml2::XMLElement* root = document.RootElement();
  EXPECT_STREQ(root->Name(), "svg");
  EXPECT_EQ(polyline_points(root, 0), 100);
  EXPECT_EQ(polyline_points(root, 1), 100);
  EXPECT_NE(svg.find("scene &lt;&amp;&gt; &quot;quoted&quot;"), std::string::npos);
  EXPECT_NE(svg.find("maximum limit 1e-10"), std::string::npos);
  EXPECT_NE(svg.find("first divergence: step 60"), std::string::npos);
  EXPECT_NE(svg.find("Exact zeros are drawn on the bottom line"), std::string::npos);
  // Decades from 1e-15 (the smallest non-zero residual) to 1e-6 (the largest).
  EXPECT_NE(svg.find(">1e-15<"), std::string::npos);
  EXPECT_EQ(svg.find(">1e-16<"), std::string::npos);
  EXPECT_NE(svg.find(">1e-6<"), std::string::npos);
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
  const std::string svg = residual_plot_svg(per_step, options);
  tinyxml2::XMLDocument document;
  ASSERT_EQ(document.Parse(svg.c_str()), tinyxml2::XML_SUCCESS);
  EXPECT_EQ(polyline_points(document.RootElement(), 0), 1000);
  EXPECT_NE(svg.find(">1e-3<"), std::string::npos);  // the spike set the top decade
  EXPECT_NE(svg.find("NaN or infinite residuals are drawn on the top edge"), std::string::npos);
}

TEST(ResidualPlot, EmptyRunStillGivesADocument) {
  tinyxml2::XMLDocument document;
  EXPECT_EQ(document.Parse(residual_plot_svg({}, {}).c_str()), tinyxml2::XML_SUCCESS);
}

}  // namespace
}  // namespace fosssim
