#include "render/path_history.h"

#include <gtest/gtest.h>

#include "io/scene_loader.h"

namespace fosssim {
namespace {

TEST(TrailCapacity, IsCeilOfDurationOverTimeStep) {
  EXPECT_EQ(trail_capacity(1.0, 0.01), 100u);
  EXPECT_EQ(trail_capacity(0.05, 0.02), 3u);  // 2.5 rounds up
  EXPECT_EQ(trail_capacity(0.0, 0.01), 0u);
  EXPECT_EQ(trail_capacity(-1.0, 0.01), 0u);
}

// A ratio beyond any integer (or merely beyond what a picture needs) is capped, not converted
// with undefined behaviour.
TEST(TrailCapacity, IsCappedForHugeRatios) {
  EXPECT_EQ(trail_capacity(1e300, 1e-300), kMaxTrailPoints);  // infinite in double
  EXPECT_EQ(trail_capacity(5.0, 1e-320), kMaxTrailPoints);
  EXPECT_EQ(trail_capacity(1e9, 1.0), kMaxTrailPoints);
  EXPECT_EQ(trail_capacity(999999.0, 1.0), 999999u);
}

TEST(PathHistory, KeepsTheLastPositionsOfEachTracedParticle) {
  auto scene = load_scene_text(R"(<scene>
    <duration time="1"/><integrator type="explicit-euler" dt="0.1"/>
    <particle m="1" px="0" py="0" vx="0" vy="0" fixed="0"/>
    <particle m="1" px="1" py="0" vx="0" vy="0" fixed="0"/>
    <particlepath i="1" duration="0.3" r="1" g="0" b="0"/>
    <particlepath i="0" duration="0.0" r="0" g="0" b="1"/></scene>)",
                               "paths.xml");
  PathHistory paths(scene);
  ASSERT_EQ(paths.trails().size(), 2u);
  EXPECT_EQ(paths.trails()[0].particle, 1);
  EXPECT_EQ(paths.trails()[0].capacity, 3u);
  EXPECT_EQ(paths.trails()[0].color, (Color{1, 0, 0}));
  Vector q(4);
  for (int k = 0; k < 5; ++k) {
    q << 0.0, 0.0, 10.0 + k, -k;
    paths.record(q, 2);
  }
  const auto& points = paths.trails()[0].points;
  ASSERT_EQ(points.size(), 3u);
  EXPECT_DOUBLE_EQ(points.front().x, 12.0);  // the oldest kept
  EXPECT_DOUBLE_EQ(points.back().x, 14.0);
  EXPECT_DOUBLE_EQ(points.back().y, -4.0);
  EXPECT_TRUE(paths.trails()[1].points.empty());
  paths.clear();
  EXPECT_TRUE(paths.trails()[0].points.empty());
}

}  // namespace
}  // namespace fosssim
