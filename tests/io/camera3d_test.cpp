// The <camera3d> element: how pictures of a 3D scene first look at it.

#include <gtest/gtest.h>

#include <string>

#include "io/scene_loader.h"

namespace fosssim {
namespace {

std::string scene_with_camera(const std::string& camera, const char* dim = "3") {
  return std::string("<scene dim=\"") + dim + R"(">
  <duration time="1"/><integrator type="explicit-euler" dt="0.1"/>
  <particle m="1" px="0" py="0" pz="0" vx="0" vy="0" vz="0" fixed="0"/>
  )" + camera +
         "\n</scene>";
}

/// The error message of loading `text`, or "" when it loads.
std::string camera_error(const std::string& text) {
  try {
    load_scene_text(text, "camera.xml");
  } catch (const SceneError& error) {
    return error.what();
  }
  return "";
}

TEST(Camera3d, ReadsEveryAttribute) {
  auto scene = load_scene_text(
      scene_with_camera(
          R"(<camera3d yaw="-30" pitch="15.5" distance="4" tx="1" ty="2" tz="3" fov="45"
                        projection="orthographic"/>)"),
      "camera.xml");
  ASSERT_TRUE(scene.appearance.camera3d);
  const OrbitViewSettings& view = *scene.appearance.camera3d;
  EXPECT_EQ(view.yaw, -30.0);
  EXPECT_EQ(view.pitch, 15.5);
  EXPECT_EQ(view.distance, 4.0);
  ASSERT_TRUE(view.target);
  EXPECT_EQ(*view.target, (std::array<double, 3>{1.0, 2.0, 3.0}));
  EXPECT_EQ(view.fov, 45.0);
  EXPECT_TRUE(view.orthographic);
  EXPECT_TRUE(scene.warnings.empty());
}

TEST(Camera3d, LeavesWhatIsNotGivenToThePicture) {
  auto scene = load_scene_text(scene_with_camera(R"(<camera3d yaw="10"/>)"), "camera.xml");
  const OrbitViewSettings& view = *scene.appearance.camera3d;
  EXPECT_EQ(view.yaw, 10.0);
  EXPECT_FALSE(view.pitch || view.distance || view.target || view.fov);
  EXPECT_FALSE(view.orthographic);
  auto without = load_scene_text(scene_with_camera(""), "camera.xml");
  EXPECT_FALSE(without.appearance.camera3d);
}

TEST(Camera3d, RejectsBadValuesNamingLineAndAttribute) {
  EXPECT_NE(camera_error(scene_with_camera(R"(<camera3d yaw="1"/>)", "2")).find("3D scenes only"),
            std::string::npos);
  const std::string fov = camera_error(scene_with_camera(R"(<camera3d fov="180"/>)"));
  EXPECT_NE(fov.find("camera.xml:4"), std::string::npos) << fov;
  EXPECT_NE(fov.find("fov"), std::string::npos) << fov;
  EXPECT_NE(camera_error(scene_with_camera(R"(<camera3d distance="0"/>)")).find("distance"),
            std::string::npos);
  EXPECT_NE(
      camera_error(scene_with_camera(R"(<camera3d projection="fisheye"/>)")).find("orthographic"),
      std::string::npos);
  EXPECT_NE(camera_error(scene_with_camera(R"(<camera3d tx="1" ty="2"/>)")).find("tz"),
            std::string::npos);
  EXPECT_NE(camera_error(scene_with_camera(R"(<camera3d yaw="x"/>)")).find("yaw"),
            std::string::npos);
  EXPECT_NE(camera_error(scene_with_camera("<camera3d/><camera3d/>")).find("only once"),
            std::string::npos);
  const std::string unknown = "<camera3d zoom=\"2\"/>";
  auto scene = load_scene_text(scene_with_camera(unknown), "camera.xml");
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_NE(scene.warnings[0].find("zoom"), std::string::npos);
}

}  // namespace
}  // namespace fosssim
