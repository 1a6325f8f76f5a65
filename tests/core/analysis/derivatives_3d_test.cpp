// Every force a 3D mass-spring scene uses, checked against finite differences in 3D.

#include <gtest/gtest.h>

#include <random>

#include "core/analysis/derivative_check.h"
#include "core/forces/constant_force.h"
#include "core/forces/drag_damping_force.h"
#include "core/forces/drag_spring_force.h"
#include "core/forces/gravitational_force.h"
#include "core/forces/vortex_force.h"
#include "support/scene_builder.h"

namespace fosssim {
namespace {

TEST(Derivatives3D, EveryForceOfAPerturbedMovingClothScenePasses) {
  Scene scene = testing::cloth(4, 60.0, "implicit-euler", 0.01, true, "corners", 0.3);
  scene.model.forces.push_back(std::make_unique<DragDampingForce<3>>(0.2));
  scene.model.forces.push_back(std::make_unique<ConstantForce<3>>(Vec<3>(0.1, -0.2, 0.3)));
  scene.model.forces.push_back(std::make_unique<GravitationalForce<3>>(0, 15, 0.5));
  Mat<3> rotation;
  rotation << 0.0, -1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0;
  scene.model.forces.push_back(std::make_unique<VortexForce<3>>(5, 10, 0.4, 0.7, rotation));
  auto drag = std::make_unique<DragSpringForce>(3);
  drag->grab(9, Eigen::Vector3d(0.1, 0.5, 0.2), 30.0);
  scene.model.forces.push_back(std::move(drag));
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.05);
  Vector q = scene.initial.q, v = scene.initial.v;
  for (int k = 0; k < q.size(); ++k) {
    q[k] += noise(rng);  // out of the plane, springs stretched and compressed
    v[k] = 10.0 * noise(rng);
  }
  DerivativeCheckOptions options;
  options.step = suggest_finite_difference_step(q, 3);
  const auto checks = check_model_derivatives(scene.model, q, v, options);
  EXPECT_EQ(checks.size(), 3 * scene.model.forces.size() - 1);  // the vortex has no potential
  for (const DerivativeCheck& check : checks) {
    EXPECT_TRUE(check.passed()) << check.force << " " << derivative_name(check.which) << ": "
                                << check.relative_error();
  }
}

}  // namespace
}  // namespace fosssim
