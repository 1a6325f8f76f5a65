#include "render/orbit_camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "io/scene_loader.h"

namespace fosssim {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

/// A camera on +z looking along -z at (1, 2, 3) from 4 units, 90° field of view: the focal
/// length is 256 pixels on a 512 × 512 picture.
OrbitCamera camera_on_z_axis() {
  OrbitCamera camera;
  camera.target = {1.0, 2.0, 3.0};
  camera.distance = 4.0;
  camera.fov = 90.0 * kDegree;
  return camera;
}

TEST(OrbitProjection, PutsKnownPointsAtKnownPixels) {
  const OrbitProjection view(camera_on_z_axis(), 512, 512);
  EXPECT_TRUE(view.eye().isApprox(Eigen::Vector3d(1.0, 2.0, 7.0)));
  const ProjectedPoint target = view.project({1.0, 2.0, 3.0});
  EXPECT_DOUBLE_EQ(target.pixel.x, 256.0);
  EXPECT_DOUBLE_EQ(target.pixel.y, 256.0);
  EXPECT_DOUBLE_EQ(target.depth, 4.0);
  // One unit right of and one above the target, 4 units deep: 256 · 1/4 = 64 pixels off.
  EXPECT_NEAR(view.project({2.0, 2.0, 3.0}).pixel.x, 256.0 + 64.0, 1e-9);
  EXPECT_NEAR(view.project({1.0, 3.0, 3.0}).pixel.y, 256.0 - 64.0, 1e-9);
  // Twice as far, half as far off the centre.
  EXPECT_NEAR(view.project({2.0, 2.0, -1.0}).pixel.x, 256.0 + 32.0, 1e-9);
  EXPECT_DOUBLE_EQ(view.pixels_per_unit(4.0), 64.0);
  // Behind the eye and behind the near plane: not visible.
  EXPECT_FALSE(view.project({1.0, 2.0, 8.0}).visible);
  EXPECT_FALSE(view.project({1.0, 2.0, 6.99}).visible);
  EXPECT_TRUE(view.project({1.0, 2.0, 6.9}).visible);
}

TEST(OrbitProjection, YawAndPitchMoveTheEyeAroundTheTarget) {
  OrbitCamera camera = camera_on_z_axis();
  camera.yaw = 90.0 * kDegree;  // the eye on +x: -z is to the right
  const OrbitProjection side(camera, 512, 512);
  EXPECT_TRUE(side.eye().isApprox(Eigen::Vector3d(5.0, 2.0, 3.0)));
  EXPECT_NEAR(side.project({1.0, 2.0, 2.0}).pixel.x, 256.0 + 64.0, 1e-9);
  camera.yaw = 0.0;
  camera.pitch = 90.0 * kDegree - 1e-9;  // from above, almost: -z is up in the picture
  const OrbitProjection top(camera, 512, 512);
  EXPECT_TRUE(top.eye().isApprox(Eigen::Vector3d(1.0, 6.0, 3.0), 1e-6));
  EXPECT_NEAR(top.project({1.0, 2.0, 2.0}).pixel.y, 256.0 - 64.0, 1e-6);
  EXPECT_NEAR(top.project({2.0, 2.0, 3.0}).pixel.x, 256.0 + 64.0, 1e-6);
}

TEST(OrbitProjection, ParallelViewIgnoresDepth) {
  OrbitCamera camera = camera_on_z_axis();
  camera.projection = Projection::kOrthographic;
  const OrbitProjection view(camera, 512, 512);
  // The visible half height is distance · tan(45°) = 4 units: 64 pixels per unit everywhere.
  EXPECT_NEAR(view.project({2.0, 2.0, 3.0}).pixel.x, 256.0 + 64.0, 1e-9);
  EXPECT_NEAR(view.project({2.0, 2.0, -100.0}).pixel.x, 256.0 + 64.0, 1e-9);
  EXPECT_TRUE(view.project({2.0, 2.0, 100.0}).visible);
  EXPECT_DOUBLE_EQ(view.pixels_per_unit(1.0), view.pixels_per_unit(50.0));
}

TEST(OrbitProjection, TheRayThroughAPointsPixelPassesThroughThePoint) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> any(-1.0, 1.0);
  for (Projection projection : {Projection::kPerspective, Projection::kOrthographic}) {
    OrbitCamera camera;
    camera.target = {0.3, -0.2, 0.1};
    camera.yaw = 0.7;
    camera.pitch = -0.4;
    camera.distance = 5.0;
    camera.projection = projection;
    const OrbitProjection view(camera, 640, 480);
    for (int k = 0; k < 20; ++k) {
      const Eigen::Vector3d point(any(random), any(random), any(random));
      const ProjectedPoint seen = view.project(point);
      const Ray ray = view.ray_through(seen.pixel.x, seen.pixel.y);
      const Eigen::Vector3d u = ray.direction.normalized();
      const Eigen::Vector3d w = point - ray.origin;
      EXPECT_GT(w.dot(u), 0.0) << "the point lies ahead of the ray";
      EXPECT_LT((w - w.dot(u) * u).norm(), 1e-9);
    }
  }
}

TEST(FitDistance, ShowsEveryCornerOfTheBoxInsideTheMargin) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> any(-2.0, 2.0), angle(-1.5, 1.5);
  for (Projection projection : {Projection::kPerspective, Projection::kOrthographic}) {
    for (int k = 0; k < 50; ++k) {
      const Eigen::Vector3d a(any(random), any(random), any(random));
      const Eigen::Vector3d b(any(random), any(random), any(random));
      const Eigen::Vector3d low = a.cwiseMin(b), high = a.cwiseMax(b);
      OrbitCamera camera;
      camera.yaw = 2.0 * angle(random);
      camera.pitch = angle(random);
      camera.projection = projection;
      camera.target = 0.5 * (low + high);
      const int width = k % 2 ? 800 : 400, height = 600;
      camera.distance = fit_distance(camera, low, high, width, height);
      const OrbitProjection view(camera, width, height);
      double widest = 0.0;  // the largest relative distance of a corner from the centre
      for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d c((corner & 1) ? high.x() : low.x(),
                                (corner & 2) ? high.y() : low.y(),
                                (corner & 4) ? high.z() : low.z());
        const ProjectedPoint seen = view.project(c);
        ASSERT_TRUE(seen.visible);
        const double across = std::abs(seen.pixel.x - 0.5 * width) / (0.5 * width);
        const double down = std::abs(seen.pixel.y - 0.5 * height) / (0.5 * height);
        EXPECT_LE(across, 1.0 / 1.3 + 1e-9);
        EXPECT_LE(down, 1.0 / 1.3 + 1e-9);
        widest = std::max({widest, across, down});
      }
      EXPECT_NEAR(widest, 1.0 / 1.3, 1e-6) << "the fit is tight";
    }
  }
}

TEST(FitDistance, ASinglePointGetsAVisibleHalfHeightOfOne) {
  OrbitCamera camera;
  const Eigen::Vector3d point(1.0, 2.0, 3.0);
  camera.target = point;
  const double distance = fit_distance(camera, point, point, 512, 512);
  EXPECT_DOUBLE_EQ(distance * std::tan(0.5 * camera.fov), 1.0);
}

TEST(InitialOrbitCamera, DefaultsToAFittedThreeQuarterView) {
  auto scene = load_scene_text(R"(<scene dim="3">
    <duration time="1"/><integrator type="explicit-euler" dt="0.1"/>
    <particle m="1" px="0" py="0" pz="0" vx="0" vy="0" vz="0" fixed="0"/>
    <particle m="1" px="2" py="1" pz="-4" vx="0" vy="0" vz="0" fixed="0"/></scene>)",
                               "two.xml");
  const OrbitCamera camera = initial_orbit_camera(scene, scene.initial, 512, 512);
  EXPECT_DOUBLE_EQ(camera.yaw, kDefaultYawDegrees * kDegree);
  EXPECT_DOUBLE_EQ(camera.pitch, kDefaultPitchDegrees * kDegree);
  EXPECT_DOUBLE_EQ(camera.fov, kDefaultFovDegrees * kDegree);
  EXPECT_EQ(camera.projection, Projection::kPerspective);
  EXPECT_TRUE(camera.target.isApprox(Eigen::Vector3d(1.0, 0.5, -2.0)));
  EXPECT_DOUBLE_EQ(camera.distance, fit_distance(camera, Eigen::Vector3d(0, 0, -4),
                                                 Eigen::Vector3d(2, 1, 0), 512, 512));
}

TEST(InitialOrbitCamera, FollowsCamera3dAndFitsWhatItLeavesOut) {
  auto scene = load_scene_text(R"(<scene dim="3">
    <duration time="1"/><integrator type="explicit-euler" dt="0.1"/>
    <particle m="1" px="0" py="0" pz="0" vx="0" vy="0" vz="0" fixed="0"/>
    <particle m="1" px="2" py="1" pz="-4" vx="0" vy="0" vz="0" fixed="0"/>
    <camera3d yaw="-45" pitch="95" fov="50" projection="orthographic"/></scene>)",
                               "camera.xml");
  OrbitCamera camera = initial_orbit_camera(scene, scene.initial, 512, 512);
  EXPECT_DOUBLE_EQ(camera.yaw, -45.0 * kDegree);
  EXPECT_DOUBLE_EQ(camera.pitch, kMaxPitchDegrees * kDegree);  // clamped
  EXPECT_DOUBLE_EQ(camera.fov, 50.0 * kDegree);
  EXPECT_EQ(camera.projection, Projection::kOrthographic);
  EXPECT_TRUE(camera.target.isApprox(Eigen::Vector3d(1.0, 0.5, -2.0)));
  EXPECT_DOUBLE_EQ(camera.distance, fit_distance(camera, Eigen::Vector3d(0, 0, -4),
                                                 Eigen::Vector3d(2, 1, 0), 512, 512));
  scene.appearance.camera3d->target = std::array<double, 3>{5.0, 6.0, 7.0};
  scene.appearance.camera3d->distance = 9.0;
  camera = initial_orbit_camera(scene, scene.initial, 512, 512);
  EXPECT_EQ(camera.target, Eigen::Vector3d(5.0, 6.0, 7.0));
  EXPECT_DOUBLE_EQ(camera.distance, 9.0);
}

TEST(InitialOrbitCamera, AViewportGivesTheTwoDimensionalCamerasView) {
  auto scene = load_scene_text(R"(<scene dim="3">
    <duration time="1"/><integrator type="explicit-euler" dt="0.1"/>
    <particle m="1" px="0" py="0" pz="1" vx="0" vy="0" vz="0" fixed="0"/>
    <particle m="1" px="0.7" py="-0.3" pz="-2" vx="0" vy="0" vz="0" fixed="0"/>
    <viewport cx="0.5" cy="0.25" size="2"/></scene>)",
                               "viewport.xml");
  const OrbitCamera camera = initial_orbit_camera(scene, scene.initial, 640, 480);
  EXPECT_EQ(camera.projection, Projection::kOrthographic);
  const OrbitProjection view(camera, 640, 480);
  const PixelMapping flat(Camera{0.5, 0.25, 2.0}, 640, 480);
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(0.7, -0.3, -2.0), Eigen::Vector3d(-1, 2, 5)}) {
    EXPECT_NEAR(view.project(p).pixel.x, flat.to_pixel(p.x(), p.y()).x, 1e-9);
    EXPECT_NEAR(view.project(p).pixel.y, flat.to_pixel(p.x(), p.y()).y, 1e-9);
  }
}

TEST(OrbitControls, PanKeepsPointsAtTheTargetsDepthUnderTheCursor) {
  for (Projection projection : {Projection::kPerspective, Projection::kOrthographic}) {
    OrbitCamera camera;
    camera.yaw = 0.5;
    camera.pitch = 0.3;
    camera.distance = 3.0;
    camera.projection = projection;
    const Eigen::Vector3d point = camera.target;  // at the target's depth
    const Point2 before = OrbitProjection(camera, 400, 300).project(point).pixel;
    pan_orbit_camera(camera, 25.0, -10.0, 300);
    const Point2 after = OrbitProjection(camera, 400, 300).project(point).pixel;
    EXPECT_NEAR(after.x, before.x + 25.0, 1e-9);
    EXPECT_NEAR(after.y, before.y - 10.0, 1e-9);
  }
}

TEST(OrbitControls, DraggingRightTurnsTheSceneRightAndPitchStaysBelowTheLimit) {
  OrbitCamera camera;
  camera.distance = 3.0;
  const Eigen::Vector3d front(0.0, 0.0, 1.0);  // the point nearest the eye
  turn_orbit_camera(camera, 20.0, 0.0, 512);
  EXPECT_LT(camera.yaw, 0.0);
  EXPECT_GT(OrbitProjection(camera, 512, 512).project(front).pixel.x, 256.0);
  turn_orbit_camera(camera, 0.0, 20.0, 512);  // down: the eye goes up
  EXPECT_GT(camera.pitch, 0.0);
  EXPECT_GT(OrbitProjection(camera, 512, 512).project(front).pixel.y, 256.0);
  turn_orbit_camera(camera, 0.0, 5000.0, 512);
  EXPECT_DOUBLE_EQ(camera.pitch, kMaxPitchDegrees * kDegree);
  zoom_orbit_camera(camera, 2.0);
  EXPECT_DOUBLE_EQ(camera.distance, 6.0);
}

}  // namespace
}  // namespace fosssim
