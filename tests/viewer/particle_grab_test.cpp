// Picking a particle under the cursor and pulling it with the drag spring, as the window does,
// without a window.

#include "viewer/particle_grab.h"

#include <gtest/gtest.h>

#include <numbers>
#include <string>
#include <string_view>

#include "core/step/simulation.h"
#include "io/scene_loader.h"
#include "support/scene_builder.h"
#include "support/tiny_scenes.h"
#include "viewer/particle_grab.h"
#include "viewer/stepper.h"

namespace fosssim {
namespace {

/// Three particles on the view axis of testing::front_camera() and one beside it; a fixed one.
Scene row_of_particles() {
  return testing::particles_at({{0, 0, -1}, {0, 0, 1}, {0, 0, 0}, {1, 0, 0}, {-1, 0, 0}});
}

/// A view of `scene` through testing::front_camera().
SceneView front_view(const Scene& scene) {
  SceneView view(scene, scene.initial, 512, 512);
  view.orbit_camera() = testing::front_camera();
  return view;
}

TEST(ParticleGrab, PicksTheNearestParticleUnderTheCursorThroughTheCamerasRay) {
  Scene scene = row_of_particles();
  scene.model.fixed[4] = true;
  const SceneView view = front_view(scene);
  ParticleGrab grab(scene);
  const DragSpringForce& spring = grab.force();
  // The centre pixel: particles 1, 2 and 0 lie on its ray; 1 is nearest the eye.
  ASSERT_TRUE(grab.press(view, scene.initial, 256.0, 256.0));
  EXPECT_EQ(spring.particle(), 1);
  EXPECT_EQ(spring.target(), Eigen::Vector3d(0, 0, 1)) << "the pull starts at the particle";
  grab.release();
  EXPECT_FALSE(grab.active());
  // Particle 3 is at pixel (256 + 256/5, 256); 5 pixels off still picks it (kPickPixels = 8).
  ASSERT_TRUE(grab.press(view, scene.initial, 256.0 + 51.2 + 5.0, 256.0));
  EXPECT_EQ(spring.particle(), 3);
  grab.release();
  // Empty space picks nothing; a fixed particle cannot be pulled.
  EXPECT_FALSE(grab.press(view, scene.initial, 100.0, 400.0));
  EXPECT_FALSE(grab.press(view, scene.initial, 256.0 - 51.2, 256.0));
  EXPECT_FALSE(spring.active());
}

TEST(ParticleGrab, PullsTowardTheCursorOnThePlaneFacingTheCamera) {
  Scene scene = row_of_particles();
  SceneView view = front_view(scene);
  ParticleGrab grab(scene);
  const DragSpringForce& spring = grab.force();
  // Grab particle 3 two pixels off its centre: the offset is kept.
  ASSERT_TRUE(grab.press(view, scene.initial, 256.0 + 51.2 + 2.0, 256.0));
  // 64 pixels right and 32 down at depth 5 (256 pixels per unit at depth 1).
  grab.move(view, 256.0 + 51.2 + 2.0 + 64.0, 256.0 + 32.0);
  EXPECT_TRUE(spring.target().isApprox(Eigen::Vector3d(1.0 + 1.25, -0.625, 0.0)));
  const auto guide = grab.guide();
  ASSERT_TRUE(guide);
  EXPECT_EQ(guide->particle, 3);
  EXPECT_EQ(guide->target, spring.target());
  // Turned a quarter round, the plane through the particle faces the new view: a sideways move
  // on screen moves the target along -z.
  grab.release();
  view.orbit_camera().yaw = 0.5 * std::numbers::pi;  // the eye on +x
  const ProjectedPoint seen = OrbitProjection(view.orbit_camera(), 512, 512).project({0, 0, 0});
  ASSERT_TRUE(grab.press(view, scene.initial, seen.pixel.x, seen.pixel.y));
  const int picked = spring.particle();
  grab.move(view, seen.pixel.x + 10.0, seen.pixel.y);
  const Eigen::Vector3d moved = spring.target() - scene.initial.q.segment<3>(3 * picked);
  EXPECT_NEAR(moved.x(), 0.0, 1e-12);
  EXPECT_LT(moved.z(), 0.0);
}

TEST(ParticleGrab, PicksTheParticleNearestTheCursorIn2D) {
  auto scene = load_scene_text(R"(<scene>
    <duration time="1"/><integrator type="symplectic-euler" dt="0.01"/>
    <particle m="1" px="0" py="0" vx="0" vy="0" fixed="0" radius="0.1"/>
    <particle m="1" px="0.15" py="0" vx="0" vy="0" fixed="0" radius="0.1"/>
    <viewport cx="0" cy="0" size="1"/></scene>)",
                               "two.xml");
  const SceneView view(scene, scene.initial, 512, 512);
  ParticleGrab grab(scene);
  const DragSpringForce& spring = grab.force();
  // World (0.08, 0): within both particles' radius (the pick distance), nearer particle 1.
  ASSERT_TRUE(grab.press(view, scene.initial, 256.0 + 20.48, 256.0));
  EXPECT_EQ(spring.particle(), 1);
  grab.move(view, 256.0 + 20.48 + 128.0, 256.0);  // half a unit right
  EXPECT_TRUE(spring.target().isApprox(Eigen::Vector3d(0.65, 0.0, 0.0)));
  EXPECT_DOUBLE_EQ(spring.stiffness(), 1.0 / (0.01 * 0.01));  // m / h², explicit
}

TEST(DragStiffness, IsStableForExplicitIntegratorsAndStiffForImplicitOnes) {
  Scene scene = testing::particles_at({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}});
  scene.model.mass.segment<3>(3).setConstant(2.0);
  scene.model.fixed[2] = true;
  scene.model.integrator.use(integrator_method("symplectic-euler"));
  EXPECT_DOUBLE_EQ(drag_stiffness(scene.model, 1), 2.0 / 1e-4);
  scene.model.integrator.use(integrator_method("local-global"));  // the free mass: 1 + 2
  EXPECT_DOUBLE_EQ(drag_stiffness(scene.model, 1), 3.0 / 1e-4);
}

/// Steps a cloth hanging from two corners with a vertex grabbed through the window's picking
/// (or not), and returns the vertex's final distance to where the cursor pulls it.
double distance_after_pulling(const char* integrator, bool pull) {
  std::string text = R"(<scene dim="3">
    <duration time="2"/><integrator type=")";
  text += integrator;
  text += R"(" dt="0.01"/>
    <generate type="cloth" nx="7" ny="7" plane="xy" pin="corners" k="200" mass="total" total="0.2"/>
    <simplegravity fx="0" fy="-9.8" fz="0"/></scene>)";
  auto scene = load_scene_text(text, "cloth.xml");
  ParticleGrab grab(scene);
  const DragSpringForce& spring = grab.force();
  SimulationStepper stepper(scene, {&spring});
  const SceneView view(scene, stepper.state(), 512, 512);
  const int vertex = 6 * 7 + 3;  // the middle of the bottom row
  const Eigen::Vector3d start = stepper.state().q.segment<3>(3 * vertex);
  const OrbitProjection projection(view.orbit_camera(), 512, 512);
  const Point2 pixel = projection.project(start).pixel;
  // Pull it 60 pixels up and 40 to the right, on the plane through it facing the camera.
  const Ray ray = view.ray_through(pixel.x + 40.0, pixel.y - 60.0);
  const Eigen::Vector3d goal = *drag_target(ray, start, -view.view_direction());
  if (pull) {
    EXPECT_TRUE(grab.press(view, stepper.state(), pixel.x, pixel.y));
    EXPECT_EQ(spring.particle(), vertex);
    grab.move(view, pixel.x + 40.0, pixel.y - 60.0);
    EXPECT_TRUE(spring.target().isApprox(goal, 1e-9));
  }
  for (int k = 0; k < 100; ++k) stepper.step();
  return (stepper.state().q.segment<3>(3 * vertex) - goal).norm() / (goal - start).norm();
}

TEST(ParticleGrab, PullsTheVertexToTheCursorInAHeadlessRun) {
  for (const char* integrator : {"local-global", "linearly-implicit-euler", "implicit-euler"}) {
    const double pulled = distance_after_pulling(integrator, true);
    const double left = distance_after_pulling(integrator, false);
    EXPECT_LT(pulled, 0.1) << integrator;  // within a tenth of the way
    EXPECT_GT(left, 0.9) << integrator;
  }
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
