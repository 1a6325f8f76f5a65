// Picking a particle under a ray, and where a ray meets the plane it is dragged in.

#include "render/picking.h"

#include <gtest/gtest.h>

namespace fosssim {
namespace {

TEST(PickParticle, ChoosesTheNearestParticleAlongTheRayWithinTheRadius) {
  Vector q(12);
  q << 0.0, 0.0, 0.0,  // on the ray, 5 from the origin
      0.05, 0.0, 2.0,  // 0.05 off the ray, 3 from the origin: nearer
      0.0, 0.0, 9.0,   // behind the origin
      1.0, 0.0, 4.0;   // too far off the ray
  const Ray ray{Eigen::Vector3d(0.0, 0.0, 5.0), Eigen::Vector3d(0.0, 0.0, -2.0)};
  EXPECT_EQ(pick_particle(q, 3, ray, 0.1), 1);
  EXPECT_EQ(pick_particle(q, 3, ray, 0.01), 0);
  EXPECT_EQ(
      pick_particle(q, 3, Ray{Eigen::Vector3d(0.0, 3.0, 5.0), -Eigen::Vector3d::UnitZ()}, 0.1),
      std::nullopt);
}

TEST(PickParticle, WorksFor2DScenesSeenFromAbove) {
  Vector q(4);
  q << 1.0, 2.0, -1.0, 0.5;
  const Ray mouse{Eigen::Vector3d(-0.98, 0.51, 1.0), -Eigen::Vector3d::UnitZ()};
  EXPECT_EQ(pick_particle(q, 2, mouse, 0.05), 1);
}

TEST(PickParticle, BreaksTiesAlongTheRayByTheDistanceToIt) {
  // Seen from above, every particle of a 2D scene is equally far along the ray.
  Vector q(6);
  q << 0.0, 0.0, 0.2, 0.0, 0.1, 0.05;
  const Ray mouse{Eigen::Vector3d(0.17, 0.0, 1.0), -Eigen::Vector3d::UnitZ()};
  EXPECT_EQ(pick_particle(q, 2, mouse, 0.5), 1);
  const Ray other{Eigen::Vector3d(0.09, 0.06, 1.0), -Eigen::Vector3d::UnitZ()};
  EXPECT_EQ(pick_particle(q, 2, other, 0.5), 2);
}

TEST(DragTarget, IntersectsTheRayWithThePlaneThroughTheGrabbedParticle) {
  const Ray ray{Eigen::Vector3d(1.0, 2.0, 10.0), Eigen::Vector3d(0.0, 0.0, -1.0)};
  const auto target =
      drag_target(ray, Eigen::Vector3d(7.0, 7.0, 3.0), Eigen::Vector3d(0.0, 0.0, 1.0));
  ASSERT_TRUE(target);
  EXPECT_EQ(*target, Eigen::Vector3d(1.0, 2.0, 3.0));
  EXPECT_FALSE(drag_target(ray, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()));  // parallel
  EXPECT_FALSE(
      drag_target(ray, Eigen::Vector3d(0.0, 0.0, 20.0), Eigen::Vector3d::UnitZ()));  // behind
}

}  // namespace
}  // namespace fosssim
