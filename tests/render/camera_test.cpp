#include "render/camera.h"

#include <gtest/gtest.h>

#include "io/scene_loader.h"

namespace fosssim {
namespace {

Vector positions(std::initializer_list<double> xy) {
  Vector q(static_cast<Eigen::Index>(xy.size()));
  Eigen::Index k = 0;
  for (double x : xy) q[k++] = x;
  return q;
}

TEST(FitCamera, CentresOnTheBoundingBoxWithTheCoursesMargin) {
  // Box [0, 2] x [-1, 0]: centre (1, -0.5), half extents 1 and 0.5; square picture.
  const Camera camera = fit_camera(positions({0, 0, 2, -1, 1, -0.2}), 2, 512, 512);
  EXPECT_DOUBLE_EQ(camera.cx, 1.0);
  EXPECT_DOUBLE_EQ(camera.cy, -0.5);
  EXPECT_DOUBLE_EQ(camera.scale, 1.2 * 1.0);
}

TEST(FitCamera, CorrectsForTheAspectOfThePicture) {
  const Vector q = positions({-1, -0.5, 1, 0.5});  // half extents 1 and 0.5
  // Twice as wide as tall: the width needs scale 1 · 512/1024 = 0.5, the height 0.5.
  EXPECT_DOUBLE_EQ(fit_camera(q, 2, 1024, 512).scale, 1.2 * 0.5);
  // Twice as tall as wide: the width needs 1 · 1024/512 = 2.
  EXPECT_DOUBLE_EQ(fit_camera(q, 2, 512, 1024).scale, 1.2 * 2.0);
  // A tall box in a square picture: the height decides.
  EXPECT_DOUBLE_EQ(fit_camera(positions({0, -3, 0, 3}), 2, 512, 512).scale, 1.2 * 3.0);
}

TEST(FitCamera, ASinglePointGetsScaleOne) {
  const Camera camera = fit_camera(positions({4, 5}), 2, 512, 512);
  EXPECT_DOUBLE_EQ(camera.cx, 4.0);
  EXPECT_DOUBLE_EQ(camera.cy, 5.0);
  EXPECT_DOUBLE_EQ(camera.scale, 1.0);
}

TEST(FitCamera, ThreeDimensionalScenesAreSeenAlongZ) {
  const Camera camera = fit_camera(positions({0, 0, 100, 2, 2, -100}), 3, 512, 512);
  EXPECT_DOUBLE_EQ(camera.cx, 1.0);
  EXPECT_DOUBLE_EQ(camera.cy, 1.0);
  EXPECT_DOUBLE_EQ(camera.scale, 1.2);
}

TEST(FitCamera, NoParticlesGetTheDefaultCamera) {
  const Camera camera = fit_camera(Vector(), 2, 512, 512);
  EXPECT_EQ(camera.cx, 0.0);
  EXPECT_EQ(camera.cy, 0.0);
  EXPECT_EQ(camera.scale, 1.0);
}

TEST(BoundingBox, SpansTheParticlesWithZeroZIn2D) {
  Vector q(6);
  q << 1, -2, 3, 0, 4, -1;
  const auto [low, high] = compute_bounding_box(q, 2);
  EXPECT_EQ(low, Eigen::Vector3d(1, -2, 0));
  EXPECT_EQ(high, Eigen::Vector3d(4, 0, 0));
  const auto box3 = compute_bounding_box(q, 3);
  EXPECT_EQ(box3[0], Eigen::Vector3d(0, -2, -1));
  EXPECT_EQ(box3[1], Eigen::Vector3d(1, 4, 3));
}

TEST(InitialCamera, UsesTheViewportWhenTheSceneHasOne) {
  auto scene = load_scene_text(R"(<scene>
    <duration time="1"/><integrator type="explicit-euler" dt="0.1"/>
    <particle m="1" px="0" py="0" vx="0" vy="0" fixed="0"/>
    <particle m="1" px="1" py="0" vx="0" vy="0" fixed="0"/>
    <viewport cx="3" cy="-2" size="7.5"/></scene>)",
                               "viewport.xml");
  const Camera camera = initial_camera(scene, scene.initial, 512, 512);
  EXPECT_DOUBLE_EQ(camera.cx, 3.0);
  EXPECT_DOUBLE_EQ(camera.cy, -2.0);
  EXPECT_DOUBLE_EQ(camera.scale, 7.5);
  scene.appearance.viewport.reset();
  EXPECT_DOUBLE_EQ(initial_camera(scene, scene.initial, 512, 512).cx, 0.5);
}

TEST(PixelMapping, PutsTheCameraCentreInTheMiddleAndYDown) {
  const Camera camera{2.0, 1.0, 4.0};  // visible: y in [-3, 5], x in [-6, 10] at 2:1
  const PixelMapping mapping(camera, 400, 200);
  EXPECT_DOUBLE_EQ(mapping.pixels_per_unit(), 25.0);
  const Point2 centre = mapping.to_pixel(2.0, 1.0);
  EXPECT_DOUBLE_EQ(centre.x, 200.0);
  EXPECT_DOUBLE_EQ(centre.y, 100.0);
  const Point2 top_left = mapping.to_pixel(-6.0, 5.0);
  EXPECT_DOUBLE_EQ(top_left.x, 0.0);
  EXPECT_DOUBLE_EQ(top_left.y, 0.0);
  const Point2 bottom_right = mapping.to_pixel(10.0, -3.0);
  EXPECT_DOUBLE_EQ(bottom_right.x, 400.0);
  EXPECT_DOUBLE_EQ(bottom_right.y, 200.0);
  const Point2 back = mapping.to_world(123.0, 45.0);
  const Point2 again = mapping.to_pixel(back.x, back.y);
  EXPECT_NEAR(again.x, 123.0, 1e-12);
  EXPECT_NEAR(again.y, 45.0, 1e-12);
}

TEST(DragCamera, KeepsTheWorldPointUnderTheCursor) {
  Camera camera{0.5, -0.25, 2.0};
  const PixelMapping before(camera, 300, 200);
  const Point2 grabbed = before.to_world(100.0, 80.0);
  drag_camera(camera, 37.0, -12.0, 200);
  const Point2 now = PixelMapping(camera, 300, 200).to_pixel(grabbed.x, grabbed.y);
  EXPECT_NEAR(now.x, 137.0, 1e-9);
  EXPECT_NEAR(now.y, 68.0, 1e-9);
}

TEST(ZoomCamera, ScalesTheVisibleHeight) {
  Camera camera{1.0, 2.0, 3.0};
  zoom_camera(camera, 2.0);
  EXPECT_DOUBLE_EQ(camera.scale, 6.0);
  EXPECT_DOUBLE_EQ(camera.cx, 1.0);
  EXPECT_DOUBLE_EQ(camera.cy, 2.0);
}

}  // namespace
}  // namespace fosssim
