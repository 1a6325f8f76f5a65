// Tests of the global sums of core/force_evaluation.h in 2D and 3D.
//
// Math checked:
// - ForceSet::has_symmetric_jacobians() true ⇒ the assembled hessX and hessV of a model with
//   undamped springs, Newtonian gravity, drag, simple gravity and a constant force are symmetric
//   to round-off; adding a damped spring or a vortex turns the flag off, and then the assembled
//   hessX is non-symmetric by far more than round-off;
// - the sums: compute_force = -compute_gradient = -Σ gradE_f, potential energy = Σ U_f, kinetic
//   energy = ½ Σ m v²;
// - zero_fixed zeroes exactly the DOFs of fixed particles.
// (The step matrix is tested in systems/step_matrix_test.cpp.)

#include "core/force_evaluation.h"

#include <gtest/gtest.h>

#include "core/forces/constant_force.h"
#include "core/forces/vortex_force.h"
#include "support/closed_forms.h"
#include "support/dense.h"
#include "support/random.h"
#include "support/scene_builder.h"
#include "support/typed_tests.h"

namespace fosssim::testing {
namespace {

FOSSSIM_TEST_SUITE_IN_2D_AND_3D(ForceEvaluationTest);

/// Four particles (the second fixed) at random places with undamped springs, Newtonian gravity,
/// drag, simple gravity and a constant force: every Jacobian symmetric.
template <int D>
TestScene symmetric_scene(unsigned seed) {
  Random random(seed);
  TestScene scene = random_spring_chain(D, random);
  scene.add_simple_gravity(random.uniform_vector(D, -10.0, 10.0));
  scene.add_gravitation(0, 3, 0.8);
  scene.add_force(std::make_unique<ConstantForce<D>>(Vec<D>(random.uniform_vector(D, -1.0, 1.0))));
  scene.add_drag(0.4);
  return scene;
}

TYPED_TEST(ForceEvaluationTest, SymmetricJacobiansClaimHoldsForTheAssembledMatrices) {
  constexpr int D = TypeParam::value;
  for (unsigned seed = 81; seed <= 84; ++seed) {
    const TestScene scene = symmetric_scene<D>(seed);
    const ForceSet forces(scene.model);
    ASSERT_TRUE(forces.has_symmetric_jacobians());
    const auto& [q, v, step, time] = scene.initial;
    const Eigen::MatrixXd hx = dense(compute_hessian_x(forces, q, v));
    const Eigen::MatrixXd hv = dense(compute_hessian_v(forces, q, v));
    EXPECT_GT(hx.norm(), 0.0);
    EXPECT_LE(asymmetry(hx), 1e-15);
    EXPECT_LE(asymmetry(hv), 1e-15);
  }
}

TYPED_TEST(ForceEvaluationTest, DampedSpringsAndVorticesMakeHessXNonSymmetric) {
  constexpr int D = TypeParam::value;
  for (int variant = 0; variant < 2; ++variant) {
    TestScene scene = symmetric_scene<D>(85);
    if (variant == 0) {
      scene.add_spring(0, 2, 3.0, 0.5, 2.0);  // damped
    } else {
      scene.add_force(std::make_unique<VortexForce<D>>(0, 2, 2.0, 1.0,
                                                       vortex_rotation<D>(Vec<3>(0.0, 0.6, 0.8))));
    }
    const ForceSet forces(scene.model);
    EXPECT_FALSE(forces.has_symmetric_jacobians());
    const Eigen::MatrixXd hx = dense(compute_hessian_x(forces, scene.initial.q, scene.initial.v));
    EXPECT_GT(asymmetry(hx), 1e-3) << (variant == 0 ? "damped spring" : "vortex");
  }
}

TYPED_TEST(ForceEvaluationTest, SumsOverForcesAndEnergies) {
  constexpr int D = TypeParam::value;
  const TestScene scene = symmetric_scene<D>(86);
  const auto& model = scene.model;
  const Vector& q = scene.initial.q;
  const Vector& v = scene.initial.v;
  Vector gradient = Vector::Zero(q.size());
  double potential = 0.0;
  for (const auto& force : model.forces) {
    gradient += gradient_of(*force, q, v, model.mass);
    potential += energy_of(*force, q, v, model.mass);
  }
  const ForceSet forces(model);
  EXPECT_TRUE(compute_gradient(forces, q, v).isApprox(gradient, 1e-15));
  EXPECT_EQ(compute_force(forces, q, v), -compute_gradient(forces, q, v));
  EXPECT_NEAR(compute_potential_energy(forces, q, v), potential, 1e-14 * std::abs(potential));
  double kinetic = 0.0;
  for (int dof = 0; dof < model.num_dofs(); ++dof)
    kinetic += 0.5 * model.mass[dof] * v[dof] * v[dof];
  EXPECT_NEAR(compute_kinetic_energy(model, v), kinetic, 1e-15 * kinetic);
}

TYPED_TEST(ForceEvaluationTest, ZeroFixedZeroesTheFixedParticlesDofs) {
  constexpr int D = TypeParam::value;
  const TestScene scene = symmetric_scene<D>(87);  // particle 1 is fixed
  const auto& model = scene.model;
  Vector x = Vector::Ones(model.num_dofs());
  zero_fixed(model, x);
  Vector expected_x = Vector::Ones(model.num_dofs());
  expected_x.segment(D, D).setZero();
  EXPECT_EQ(x, expected_x);
}

}  // namespace
}  // namespace fosssim::testing
