// Contact of 3D meshes under every 3D integrator: a cloth dropped on a floor half-space and on a
// sphere does not pass through, with penalty, simple and continuous-time handling; and the
// local/global solver's implicit obstacle contacts against implicit Euler.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/integrators/local_global.h"
#include "core/step/step_pipeline.h"
#include "support/scene_builder.h"

namespace fosssim {
namespace {

using testing::TestScene;
using testing::vec;

constexpr double kRadius = 0.05;     // of every cloth vertex
constexpr double kThickness = 0.01;  // of the penalty force
const Eigen::Vector3d kSphereCenter(0.0, 0.0, 0.5);
constexpr double kSphereRadius = 0.3;
constexpr double kFloor = -0.3;  // the half-space y ≤ kFloor, under the sphere

/// A free 6 × 6 cloth (1 m square, 0.1 kg) lying flat at height y0 over z ∈ [0, 1], on a floor
/// at y = kFloor, with the sphere under its middle when `sphere`.
TestScene cloth_over(const IntegratorMethod& method, const ContactMethod* collisions, bool sphere,
                     double y0) {
  // Explicit methods need a step well below the springs' period; implicit ones take 10× more,
  // but for simple impulses, which change no positions: a draped cloth's tension pushes its
  // vertices into the sphere by about h² a every step, 100 times more at 10 times the step.
  const bool small_step = !method.properties.implicit || collisions == &contact_method("simple");
  const double dt = small_step ? 5e-4 : 5e-3;
  TestScene scene = testing::cloth(6, 20.0, method.name, dt, /*horizontal=*/true, "none", 0.01);
  for (int p = 0; p < scene.model.num_particles(); ++p) scene.initial.q[3 * p + 1] += y0;
  scene.model.particle_radius.assign(scene.model.num_particles(), kRadius);
  scene.add_half_plane(vec({0, kFloor, 0}), vec({0, 1, 0}));
  if (sphere) scene.model.spheres.push_back({Vector(kSphereCenter), kSphereRadius});
  CollisionSettings& s = scene.model.collisions;
  s.method = collisions;
  s.cor = 0.0;
  s.stiffness = 1000.0;
  s.thickness = kThickness;
  s.penalty_jacobian = PenaltyJacobian::kExact;
  scene.model.duration = 0.8;
  return scene;
}

/// The deepest any vertex got: the least height of a centre over the floor and the least
/// distance of a centre from the sphere's surface, over every step.
struct Clearance {
  double floor = INFINITY, sphere = INFINITY;
};

Clearance run(TestScene& scene) {
  StepPipeline pipeline(scene.model);
  State state = scene.initial;
  Clearance c;
  for (std::int64_t step = 0; step < scene.model.num_steps(); ++step) {
    pipeline.step(state);
    for (int p = 0; p < scene.model.num_particles(); ++p) {
      const Eigen::Vector3d x = state.q.segment<3>(3 * p);
      c.floor = std::min(c.floor, x.y() - kFloor);
      if (!scene.model.spheres.empty()) {
        c.sphere = std::min(c.sphere, (x - kSphereCenter).norm() - kSphereRadius);
      }
    }
  }
  return c;
}

struct ClothContactCase {
  const ContactMethod* collisions;
  /// The least clearance allowed, as a fraction of the vertex radius: penalty contact lets
  /// objects sink in by m g / k (here far less than the thickness); simple impulses change no
  /// positions, so resting vertices creep in by about h² a per step.
  double least;
};

TEST(ClothContact, ClothOnAFloorAndOnASphereDoesNotPassThroughUnderEvery3DIntegrator) {
  const ClothContactCase cases[] = {{&contact_method("penalty"), 0.9},
                                    {&contact_method("continuous-time"), 0.9},
                                    {&contact_method("simple"), 0.1}};
  for (const IntegratorMethod* method : integrator_methods()) {
    if (!method->properties.runs_3d) continue;
    for (const ClothContactCase& c : cases) {
      const std::string what = std::string(method->name) + ", " + std::string(c.collisions->name);
      // Dropped from 0.2 m above the floor.
      TestScene flat = cloth_over(*method, c.collisions, false, kFloor + kRadius + 0.2);
      const Clearance on_floor = run(flat);
      EXPECT_GT(on_floor.floor, c.least * kRadius) << what << ": floor";
      EXPECT_LT(on_floor.floor, kRadius + kThickness) << what << ": reached the floor";
      // Dropped from 0.2 m above the sphere's top: drapes over it, corners toward the floor.
      TestScene draped = cloth_over(*method, c.collisions, true, kSphereRadius + kRadius + 0.2);
      const Clearance on_sphere = run(draped);
      EXPECT_GT(on_sphere.sphere, c.least * kRadius) << what << ": sphere";
      EXPECT_GT(on_sphere.floor, c.least * kRadius) << what << ": floor under the sphere";
      EXPECT_LT(on_sphere.sphere, kRadius + kThickness) << what << ": reached the sphere";
      std::printf("%-26s %-16s floor %.4f  sphere %.4f  (vertex radius %.2f)\n",
                  std::string(method->name).c_str(), std::string(c.collisions->name).c_str(),
                  on_floor.floor, on_sphere.sphere, kRadius);
    }
  }
}

/// One particle of mass 0.1 pressed onto the floor y ≤ 0 and the unit sphere by gravity, with a
/// stiff penalty (k = 10⁴, h = 0.01: h²k/m = 10), stepped by `integrator`.
TestScene stiff_contact(std::string_view integrator) {
  TestScene scene(3, integrator, 0.01);
  scene.add_particle(0.1, vec({0.3, 0.12, 0}), vec({0.5, -1, 0.2}), false, 0.1);
  scene.add_particle(0.1, vec({0.2, 1.05, 2.0}), vec({0, -1, 0}), false, 0.1);
  scene.add_half_plane(vec({0, 0, 0}), vec({0, 2, 0}));
  scene.model.spheres.push_back({vec({0, 0, 2}), 1.0});
  scene.add_simple_gravity(vec({0, -9.8, 0}));
  CollisionSettings& s = scene.model.collisions;
  s.method = &contact_method("penalty");
  s.stiffness = 1e4;
  s.thickness = 0.01;
  s.penalty_jacobian = PenaltyJacobian::kExact;
  return scene;
}

TEST(LocalGlobalContact, ConvergesToImplicitEulerWithTheExactPenaltyJacobian) {
  // Obstacle contacts are terms ½ k |p - t(p)|² of the local/global energy, so with enough
  // iterations each step is implicit Euler's step with the penalty's exact Jacobian (Newton).
  TestScene reference = stiff_contact("implicit-euler");
  TestScene tested = stiff_contact("local-global");
  tested.model.integrator.options.set("iterations", 400.0);
  State a = reference.initial, b = tested.initial;
  StepPipeline newton(reference.model), local_global(tested.model);
  double largest = 0.0;
  for (int step = 0; step < 50; ++step) {
    newton.step(a);
    local_global.step(b);
    largest = std::max(largest, (a.q - b.q).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(largest, 1e-8);
  // Both rest on their obstacles, sunk in by about m g / k = 10⁻⁴ beyond R + T.
  EXPECT_NEAR(b.q[1], 0.1 + 0.01 - 0.1 * 9.8 / 1e4, 2e-4);
}

TEST(LocalGlobalContact, RefactorsOnlyWhenTheContactSetChanges) {
  TestScene scene = stiff_contact("local-global");
  scene.model.spheres.clear();
  scene.initial.q = vec({0.3, 0.5, 0, 0.2, 3.0, 2.0});  // both well above the floor
  scene.initial.v.setZero();
  auto integrator = testing::bound_integrator<LocalGlobal<3>>(scene.model);
  const int at_start = integrator->factorizations();
  State state = scene.initial;
  int contacts_before = 0, changes = 0;
  for (int step = 0; step < 60; ++step) {
    integrator->step(state);
    changes += integrator->last_contacts() != contacts_before;
    contacts_before = integrator->last_contacts();
  }
  // Particle 0 lands and stays (its contact enters Q); particle 1 is still falling, far above.
  // Q is refactored exactly when the set of contacts changes, never otherwise.
  EXPECT_EQ(contacts_before, 1);
  EXPECT_GE(changes, 1);
  EXPECT_EQ(integrator->factorizations(), at_start + changes);
  EXPECT_GT(state.q[1], 0.1);
}

}  // namespace
}  // namespace fosssim
