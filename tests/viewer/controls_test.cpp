#include "viewer/controls.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/scene_builder.h"
#include "support/tiny_scenes.h"

namespace fosssim {
namespace {

TEST(CommandForKey, MapsTheCoursesKeys) {
  EXPECT_EQ(command_for_key(' '), Command::kTogglePause);
  EXPECT_EQ(command_for_key('s'), Command::kSingleStep);
  EXPECT_EQ(command_for_key('q'), Command::kQuit);
  EXPECT_EQ(command_for_key(27), Command::kQuit);
  EXPECT_EQ(command_for_key('c'), Command::kRecenter);
  EXPECT_EQ(command_for_key('-'), Command::kZoomOut);
  EXPECT_EQ(command_for_key('='), Command::kZoomIn);
  EXPECT_EQ(command_for_key('+'), Command::kZoomIn);
  EXPECT_EQ(command_for_key('x'), Command::kNone);
  EXPECT_EQ(command_for_arrow(ArrowKey::kLeft), Command::kPanLeft);
  EXPECT_EQ(command_for_arrow(ArrowKey::kUp), Command::kPanUp);
}

TEST(ApplyCameraCommand, ZoomsAndPansInStepsOfTheView) {
  Camera camera{1.0, 2.0, 4.0};
  EXPECT_TRUE(apply_camera_command(Command::kZoomOut, camera));
  EXPECT_DOUBLE_EQ(camera.scale, 4.0 * kZoomStep);
  EXPECT_TRUE(apply_camera_command(Command::kZoomIn, camera));
  EXPECT_DOUBLE_EQ(camera.scale, 4.0);
  EXPECT_TRUE(apply_camera_command(Command::kPanRight, camera));
  EXPECT_DOUBLE_EQ(camera.cx, 1.0 + kPanStep * 4.0);
  EXPECT_TRUE(apply_camera_command(Command::kPanDown, camera));
  EXPECT_DOUBLE_EQ(camera.cy, 2.0 - kPanStep * 4.0);
  EXPECT_FALSE(apply_camera_command(Command::kTogglePause, camera));
}

TEST(ZoomFactorForDrag, DraggingDownZoomsOutAndUpZoomsBackIn) {
  const double down = zoom_factor_for_drag(0.0, 256.0, 512, 512);  // half a picture down
  EXPECT_DOUBLE_EQ(down, std::exp(1.0));
  EXPECT_NEAR(down * zoom_factor_for_drag(0.0, -256.0, 512, 512), 1.0, 1e-15);
  EXPECT_LT(zoom_factor_for_drag(128.0, 10.0, 512, 512), 1.0);  // mostly right: zooms in
}

TEST(ApplyViewCommand, MovesA2DViewExactlyAsTheCameraCommand) {
  const Scene scene = testing::tiny_scene();
  SceneView view(scene, scene.initial, 512, 512);
  Camera expected = view.camera();
  for (Command command : {Command::kZoomOut, Command::kPanLeft, Command::kPanUp}) {
    EXPECT_TRUE(apply_view_command(command, view));
    apply_camera_command(command, expected);
  }
  EXPECT_DOUBLE_EQ(view.camera().cx, expected.cx);
  EXPECT_DOUBLE_EQ(view.camera().cy, expected.cy);
  EXPECT_DOUBLE_EQ(view.camera().scale, expected.scale);
  EXPECT_FALSE(apply_view_command(Command::kRecenter, view));
}

TEST(ApplyViewCommand, ZoomsAndPansA3DView) {
  const Scene scene = testing::particles_at({{0, 0, 0}, {1, 1, 1}});
  SceneView view(scene, scene.initial, 512, 512);
  const OrbitCamera start = view.orbit_camera();
  EXPECT_TRUE(apply_view_command(Command::kZoomIn, view));
  EXPECT_DOUBLE_EQ(view.orbit_camera().distance, start.distance / kZoomStep);
  // Panning left by a tenth of the half height moves the target to the left of the view: its
  // pixel moves right by 25.6 pixels.
  EXPECT_TRUE(apply_view_command(Command::kPanLeft, view));
  const Point2 pixel = OrbitProjection(view.orbit_camera(), 512, 512).project(start.target).pixel;
  EXPECT_NEAR(pixel.x, 256.0 + 25.6, 1e-9);
  EXPECT_NEAR(pixel.y, 256.0, 1e-9);
  EXPECT_FALSE(apply_view_command(Command::kTogglePause, view));
}

}  // namespace
}  // namespace fosssim
