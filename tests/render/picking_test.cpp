// Picking a particle under a ray and dragging it, without a window.

#include "render/picking.h"

#include <gtest/gtest.h>

#include "core/step/simulation.h"
#include "support/scene_builder.h"
#include "viewer/particle_grab.h"

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

TEST(DragSpring, TheSuggestedStiffnessIsMassOverHSquared) {
  Scene scene = testing::cloth(3, 10.0, "implicit-euler", 0.01);
  EXPECT_DOUBLE_EQ(suggest_drag_stiffness(scene.model, 4), (0.1 / 9) / (0.01 * 0.01));
}

/// Runs `steps` steps of the scene, with a particle grabbed from step `grab_at` on, and
/// returns its final distance to the target.
double drag_distance(std::string_view kind, bool installed_but_idle) {
  Scene scene = testing::cloth(5, 50.0, kind, 0.01);
  DragSpringForce drag(3);
  StepAdditions additions;
  additions.interaction_forces = {&drag};
  Simulation simulation(scene.model, scene.initial, std::move(additions));
  const int particle = 22;  // in the middle of the far row
  const Eigen::Vector3d target(0.0, 0.3, 0.5);
  for (int step = 0; step < 200; ++step) {
    if (step == 20 && !installed_but_idle) {
      drag.grab(particle, target, 10.0 * suggest_drag_stiffness(scene.model, particle));
    }
    simulation.step();
  }
  return (simulation.state().q.segment<3>(3 * particle) - target).norm();
}

TEST(DragSpring, PullsAGrabbedClothVertexToTheMouseWithEveryImplicitIntegrator) {
  for (std::string_view kind :
       {"implicit-euler", "linearized-implicit-euler", "linearly-implicit-euler", "local-global"}) {
    const double grabbed = drag_distance(kind, false);
    const double idle = drag_distance(kind, true);
    EXPECT_LT(grabbed, 0.05) << std::string(kind);
    EXPECT_GT(idle, 0.3) << std::string(kind);
  }
}

TEST(DragSpring, AnIdleDragSpringChangesNothing) {
  Scene plain = testing::cloth(4, 20.0, "implicit-euler", 0.01);
  DragSpringForce drag(3);
  StepAdditions additions;
  additions.interaction_forces = {&drag};
  Simulation a(plain.model, plain.initial), b(plain.model, plain.initial, std::move(additions));
  for (int step = 0; step < 10; ++step) {
    a.step();
    b.step();
  }
  EXPECT_EQ(a.state().q, b.state().q);
  EXPECT_EQ(a.state().v, b.state().v);
}

}  // namespace
}  // namespace fosssim
