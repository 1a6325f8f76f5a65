// Tests of SceneModel's derived quantities (core/scene_model.h).
//
// Checked: num_steps = ceil(duration / dt) in double precision (docs/scene-format.md: 4.0 / 0.01
// gives 400, and a duration that is not a multiple of dt rounds up); has_fixed_particles and
// is_fixed_dof; a model's ForceSet (core/force_set.h) has symmetric Jacobians when every force
// has (a damped spring or a vortex clears it), and sums interaction forces after the model's.

#include "core/scene_model.h"

#include <gtest/gtest.h>

#include "core/force_set.h"
#include "core/forces/drag_spring_force.h"
#include "core/forces/vortex_force.h"
#include "support/closed_forms.h"
#include "support/scene_builder.h"

namespace fosssim::testing {
namespace {

TEST(SceneModel, NumberOfStepsIsTheCeilingOfDurationOverDt) {
  SceneModel model;
  const std::pair<double, double> cases[] = {{4.0, 0.01}, {1.0, 0.1}, {1.05, 0.1}, {0.0, 0.01}};
  const std::int64_t expected[] = {400, 10, 11, 0};
  for (int c = 0; c < 4; ++c) {
    model.duration = cases[c].first;
    model.integrator.dt = cases[c].second;
    EXPECT_EQ(model.num_steps(), expected[c]) << cases[c].first << " / " << cases[c].second;
  }
}

TEST(SceneModel, FlagsAreDerivedFromParticlesAndForces) {
  TestScene scene(2);
  scene.add_particle(1.0, vec({0.0, 0.0}), vec({0.0, 0.0}));
  scene.add_particle(1.0, vec({1.0, 0.0}), vec({0.0, 0.0}));
  EXPECT_FALSE(scene.model.has_fixed_particles());
  EXPECT_TRUE(ForceSet(scene.model).has_symmetric_jacobians());  // no forces at all
  scene.add_spring(0, 1, 1.0, 1.0);
  scene.add_gravitation(0, 1, 1.0);
  scene.add_drag(0.1);
  EXPECT_TRUE(ForceSet(scene.model).has_symmetric_jacobians());
  scene.add_spring(0, 1, 1.0, 1.0, 0.5);
  EXPECT_FALSE(ForceSet(scene.model).has_symmetric_jacobians());

  TestScene vortex(2);
  vortex.add_particle(1.0, vec({0.0, 0.0}), vec({0.0, 0.0}), /*fixed=*/true);
  vortex.add_particle(1.0, vec({1.0, 0.0}), vec({0.0, 0.0}));
  vortex.add_force(std::make_unique<VortexForce<2>>(0, 1, 1.0, 1.0, rotation_2d()));
  EXPECT_TRUE(vortex.model.has_fixed_particles());
  EXPECT_TRUE(vortex.model.is_fixed_dof(1));
  EXPECT_FALSE(vortex.model.is_fixed_dof(2));
  EXPECT_FALSE(ForceSet(vortex.model).has_symmetric_jacobians());
}

TEST(ForceSet, InteractionForcesSumAfterTheModelsOwn) {
  TestScene scene(2);
  scene.add_particle(1.0, vec({0.0, 0.0}), vec({0.0, 0.0}));
  scene.add_particle(1.0, vec({1.0, 0.0}), vec({0.0, 0.0}));
  scene.add_spring(0, 1, 1.0, 1.0);
  scene.add_drag(0.1);
  DragSpringForce drag(2);
  const ForceSet forces(scene.model, {&drag});
  ASSERT_EQ(forces.forces().size(), 3u);
  EXPECT_EQ(forces.forces()[0], scene.model.forces[0].get());
  EXPECT_EQ(forces.forces()[1], scene.model.forces[1].get());
  EXPECT_EQ(forces.forces()[2], &drag);
  EXPECT_EQ(&forces.model(), &scene.model);
  EXPECT_EQ(ForceSet(scene.model).forces().size(), 2u);
  EXPECT_TRUE(forces.is_conservative() == false) << "drag is not conservative";
}

}  // namespace
}  // namespace fosssim::testing
