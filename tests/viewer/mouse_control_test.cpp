// The window's mouse bindings, applied to a view without a window.

#include "viewer/mouse_control.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"
#include "support/tiny_scenes.h"
#include "viewer/particle_grab.h"

namespace fosssim {
namespace {

constexpr KeyModifiers kNoKeys{};
constexpr KeyModifiers kShift{true, false};
constexpr KeyModifiers kCtrl{false, true};

TEST(MouseAction, KeepsTheCoursesBindingsIn2DAndOrbitsIn3D) {
  EXPECT_EQ(mouse_action(MouseButton::kLeft, kNoKeys, false), MouseAction::kPan);
  EXPECT_EQ(mouse_action(MouseButton::kRight, kNoKeys, false), MouseAction::kZoom);
  EXPECT_EQ(mouse_action(MouseButton::kMiddle, kNoKeys, false), MouseAction::kPan);
  EXPECT_EQ(mouse_action(MouseButton::kLeft, kShift, false), MouseAction::kPan);
  EXPECT_EQ(mouse_action(MouseButton::kLeft, kCtrl, false), MouseAction::kGrab);
  EXPECT_EQ(mouse_action(MouseButton::kLeft, kNoKeys, true), MouseAction::kOrbit);
  EXPECT_EQ(mouse_action(MouseButton::kLeft, kShift, true), MouseAction::kPan);
  EXPECT_EQ(mouse_action(MouseButton::kMiddle, kNoKeys, true), MouseAction::kPan);
  EXPECT_EQ(mouse_action(MouseButton::kRight, kNoKeys, true), MouseAction::kZoom);
  EXPECT_EQ(mouse_action(MouseButton::kLeft, kCtrl, true), MouseAction::kGrab);
}

TEST(MouseControl, PansAndZoomsA2DViewAsTheCoursesWindowDid) {
  const Scene scene = testing::tiny_scene();
  SceneView view(scene, scene.initial, 512, 512);
  MouseControl mouse(view, nullptr);
  Camera expected = view.camera();
  EXPECT_FALSE(mouse.press(MouseButton::kLeft, kNoKeys, 100, 100, scene.initial));
  EXPECT_TRUE(mouse.move(130, 90));
  drag_camera(expected, 30.0, -10.0, 512);
  EXPECT_DOUBLE_EQ(view.camera().cx, expected.cx);
  EXPECT_DOUBLE_EQ(view.camera().cy, expected.cy);
  // A second button during the drag is ignored.
  EXPECT_FALSE(mouse.press(MouseButton::kRight, kNoKeys, 0, 0, scene.initial));
  EXPECT_EQ(mouse.action(), MouseAction::kPan);
  mouse.release(MouseButton::kLeft);
  EXPECT_EQ(mouse.action(), MouseAction::kNone);
  EXPECT_FALSE(mouse.move(10, 10));
  mouse.press(MouseButton::kRight, kNoKeys, 100, 100, scene.initial);
  mouse.move(100, 356);
  zoom_camera(expected, zoom_factor_for_drag(0.0, 256.0, 512, 512));
  EXPECT_DOUBLE_EQ(view.camera().scale, expected.scale);
  mouse.release(MouseButton::kRight);
  mouse.wheel(true);
  EXPECT_DOUBLE_EQ(view.camera().scale, expected.scale / kZoomStep);
}

TEST(MouseControl, OrbitsPansAndZoomsA3DView) {
  const Scene scene = testing::particles_at({{0, 0, 0}, {1, 1, 1}});
  SceneView view(scene, scene.initial, 512, 512);
  MouseControl mouse(view, nullptr);
  const OrbitCamera start = view.orbit_camera();
  mouse.press(MouseButton::kLeft, kNoKeys, 200, 200, scene.initial);
  mouse.move(220, 200);
  EXPECT_LT(view.orbit_camera().yaw, start.yaw);
  EXPECT_EQ(view.orbit_camera().target, start.target);
  mouse.release(MouseButton::kLeft);
  mouse.press(MouseButton::kLeft, kShift, 200, 200, scene.initial);
  mouse.move(220, 200);
  EXPECT_NE(view.orbit_camera().target, start.target);
  mouse.release(MouseButton::kLeft);
  mouse.wheel(false);
  EXPECT_DOUBLE_EQ(view.orbit_camera().distance, start.distance * kZoomStep);
}

TEST(MouseControl, CtrlDragPullsAParticleAndLetsGoOnRelease) {
  Scene scene = testing::particles_at({{0, 0, 0}, {1, 0, 0}});
  SceneView view(scene, scene.initial, 512, 512);
  view.orbit_camera() = testing::front_camera();
  MouseControl without_grab(view, nullptr);
  EXPECT_FALSE(without_grab.press(MouseButton::kLeft, kCtrl, 256, 256, scene.initial));
  EXPECT_EQ(without_grab.action(), MouseAction::kNone);

  ParticleGrab grab(scene);
  const DragSpringForce& spring = grab.force();
  MouseControl mouse(view, &grab);
  const OrbitCamera camera = view.orbit_camera();
  EXPECT_FALSE(mouse.press(MouseButton::kLeft, kCtrl, 10, 10, scene.initial));  // nothing there
  EXPECT_TRUE(mouse.press(MouseButton::kLeft, kCtrl, 256, 256, scene.initial));
  EXPECT_EQ(spring.particle(), 0);
  EXPECT_TRUE(mouse.move(256, 200));
  EXPECT_GT(spring.target().y(), 0.0);
  EXPECT_EQ(view.orbit_camera().yaw, camera.yaw) << "grabbing does not turn the view";
  EXPECT_TRUE(mouse.release(MouseButton::kLeft));
  EXPECT_FALSE(spring.active());
}

}  // namespace
}  // namespace fosssim
