// Picking a particle under the cursor and pulling it with the drag spring, as the window does,
// without a window.

#include "viewer/particle_grab.h"

#include <gtest/gtest.h>

#include <numbers>
#include <string>
#include <string_view>

#include "core/forces/rigid_body_spring_force.h"
#include "core/rigid/rigid_bodies.h"
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


/// A rigid-body scene: a free 2 × 1 box (four unit vertex masses, centre at the origin) above a
/// fixed floor, no gravity; the viewport maps world (x, y) to pixel (256 + 51.2 x, 256 − 51.2 y).
Scene box_over_floor() {
  return load_scene_text(R"(<scene>
    <simtype type="rigid-body"/><duration time="1"/>
    <rigidbodyintegrator type="symplectic-euler" dt="0.01"/>
    <viewport cx="0" cy="0" size="5"/>
    <rigidbodyvertex x="-1" y="0.5" m="1"/><rigidbodyvertex x="1" y="0.5" m="1"/>
    <rigidbodyvertex x="1" y="-0.5" m="1"/><rigidbodyvertex x="-1" y="-0.5" m="1"/>
    <rigidbodyvertex x="-4" y="-2" m="1"/><rigidbodyvertex x="4" y="-2" m="1"/>
    <rigidbodyvertex x="4" y="-3" m="1"/><rigidbodyvertex x="-4" y="-3" m="1"/>
    <rigidbody p="0" p="1" p="2" p="3" vx="0" vy="0" omega="0" r="0.05"/>
    <rigidbody p="4" p="5" p="6" p="7" vx="0" vy="0" omega="0" r="0.05" fixed="1"/>
    </scene>)",
                         "box.xml");
}

/// The pixel of world point (x, y) in box_over_floor's view.
Point2 box_pixel(double x, double y) { return {256.0 + 51.2 * x, 256.0 - 51.2 * y}; }

TEST(RigidBodyGrab, PicksTheBodyUnderTheCursorAndGrabsItsPointThere) {
  Scene scene = box_over_floor();
  State state = scene.initial;
  state.q[2] = std::numbers::pi / 2;  // the box turned a quarter: now 1 wide and 2 high
  const SceneView view(scene, state, 512, 512);
  ParticleGrab grab(scene);
  EXPECT_EQ(&grab.interaction_force(), &grab.rigid_force());
  const RigidBodyDragForce& spring = grab.rigid_force();
  // (0.3, 0.8) lies in the turned box (not in the unturned one): its body point is R(−π/2) of
  // it, (0.8, −0.3).
  const Point2 inside = box_pixel(0.3, 0.8);
  ASSERT_TRUE(grab.press(view, state, inside.x, inside.y));
  EXPECT_EQ(spring.body(), 0);
  EXPECT_TRUE(spring.body_point().isApprox(Vec<2>(0.8, -0.3), 1e-9)) << spring.body_point();
  EXPECT_TRUE(spring.target().isApprox(Vec<2>(0.3, 0.8), 1e-9));
  // The stiffness is the mass felt at the point over h²: M = 4, I = 4 (1 + 0.25) = 5.
  EXPECT_NEAR(spring.stiffness(), 1.0 / (0.25 + 0.73 / 5.0) / 1e-4, 1e-6);
  // The drag line starts at the grabbed point of the body.
  ASSERT_TRUE(grab.guide());
  EXPECT_EQ(grab.guide()->particle, 0);
  ASSERT_TRUE(grab.guide()->body_point);
  grab.move(view, box_pixel(2.3, 1.8).x, box_pixel(2.3, 1.8).y);
  EXPECT_TRUE(spring.target().isApprox(Vec<2>(2.3, 1.8), 1e-9));
  grab.release();
  EXPECT_FALSE(spring.active());
  EXPECT_FALSE(grab.active());
  // Outside the turned box but inside where the unturned one was: nothing. Within its radius
  // (0.05) plus 8 pixels of an edge: the box. The fixed floor cannot be pulled.
  EXPECT_FALSE(grab.press(view, state, box_pixel(0.9, 0.3).x, box_pixel(0.9, 0.3).y));
  EXPECT_TRUE(grab.press(view, state, box_pixel(0.5 + 0.15, 0.3).x, box_pixel(0.65, 0.3).y));
  grab.release();
  EXPECT_FALSE(grab.press(view, state, box_pixel(0.0, -2.5).x, box_pixel(0.0, -2.5).y));
  EXPECT_FALSE(spring.active());
}

TEST(RigidBodyGrab, TheDragIsTheRigidSpringToAWorldPoint) {
  // Energy and gradient (F and τ) equal those of the scene's own rigid-body spring from the
  // grabbed point to the target, rest length 0, on a moved and turned state.
  Scene scene = box_over_floor();
  RigidBodyDragForce drag;
  drag.grab(0, Vec<2>(0.7, -0.2), Vec<2>(1.5, 2.0), 250.0);
  drag.move_target(Vec<2>(-1.0, 3.0));
  const RigidBodySpringForce spring(0, Vec<2>(0.7, -0.2), -1, Vec<2>(-1.0, 3.0), 250.0, 0.0);
  State state = scene.initial;
  state.q.segment<3>(0) << 0.4, -0.3, 0.9;
  const ForceInput in{state.q, state.v, scene.model.mass};
  double e_drag = 0.0, e_spring = 0.0;
  drag.add_energy(in, e_drag);
  spring.add_energy(in, e_spring);
  EXPECT_GT(e_drag, 0.0);
  EXPECT_EQ(e_drag, e_spring);
  Vector g_drag = Vector::Zero(6), g_spring = Vector::Zero(6);
  drag.add_gradient(in, g_drag);
  spring.add_gradient(in, g_spring);
  EXPECT_EQ(g_drag, g_spring);
  EXPECT_NE(g_drag[2], 0.0);  // a torque: the point is off the centre
  drag.release();
  double idle = 0.0;
  drag.add_energy(in, idle);
  EXPECT_EQ(idle, 0.0);
}

TEST(RigidBodyGrab, PullsTheGrabbedPointToTheCursorInAHeadlessRun) {
  // The box grabbed at (0.8, 0.3) through the window's picking and pulled to (2.3, 1.8), no
  // gravity, symplectic Euler. First step by hand: F = k (1.5, 1.5), τ = (0.8, 0.3) × F =
  // 0.75 k, V = h F / M, ω = h τ / I (M = 4, I = 5). Then 300 steps stay bounded (the
  // stiffness keeps symplectic Euler stable: an unstable spring would grow every step) and the
  // grabbed point passes near the cursor. An idle grab leaves the box at rest.
  for (const bool pull : {true, false}) {
    Scene scene = box_over_floor();
    ParticleGrab grab(scene);
    SimulationStepper stepper(scene, {&grab.interaction_force()});
    const SceneView view(scene, stepper.state(), 512, 512);
    const Vec<2> start(0.8, 0.3), goal(2.3, 1.8);
    if (pull) {
      ASSERT_TRUE(grab.press(view, stepper.state(), box_pixel(0.8, 0.3).x, box_pixel(0.8, 0.3).y));
      grab.move(view, box_pixel(2.3, 1.8).x, box_pixel(2.3, 1.8).y);
      ASSERT_TRUE(grab.rigid_force().target().isApprox(goal, 1e-9));
    }
    const double k = grab.rigid_force().stiffness(), h = 0.01;
    stepper.step();
    const Vector& v1 = stepper.state().v;
    const Vec<2> pull_vector = pull ? Vec<2>(goal - start) : Vec<2>::Zero();
    EXPECT_NEAR(v1[0], h * k * pull_vector.x() / 4.0, 1e-9 * (1 + k));
    EXPECT_NEAR(v1[1], h * k * pull_vector.y() / 4.0, 1e-9 * (1 + k));
    EXPECT_NEAR(v1[2], h * k * (0.8 * pull_vector.y() - 0.3 * pull_vector.x()) / 5.0,
                1e-9 * (1 + k));
    double closest = (start - goal).norm(), farthest = 0.0;
    for (int step = 1; step < 300; ++step) {
      stepper.step();
      const State& s = stepper.state();
      const Vec<2> point = rotate(body_angle(s.q, 0), start) + body_center(s.q, 0);
      closest = std::min(closest, (point - goal).norm());
      farthest = std::max(farthest, (point - goal).norm());
    }
    if (pull) {
      EXPECT_LT(farthest, 3.0 * (start - goal).norm());  // bounded: stable
      EXPECT_LT(closest, 0.5 * (start - goal).norm());   // it came to the cursor
    } else {
      EXPECT_EQ(stepper.state().q.head<3>(), scene.initial.q.head<3>());  // no pull, no motion
    }
  }
}

}  // namespace
}  // namespace fosssim
