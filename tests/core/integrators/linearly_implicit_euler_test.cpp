// Linearly implicit Euler with fixed particles projected out (CSC417 a2).

#include "core/integrators/linearly_implicit_euler.h"

#include <gtest/gtest.h>

#include "core/force_evaluation.h"
#include "core/integrators/implicit_euler.h"
#include "core/integrators/linearized_implicit_euler.h"
#include "support/scene_builder.h"

namespace fosssim {
namespace {

TEST(LinearlyImplicitEuler, OneStepOfASpringMatchesTheHandComputedSolution) {
  // Along the spring: (m + h²k) v⁺ = m v - h k (x - l0), x⁺ = x + h v⁺.
  const double m = 2.0, k = 50.0, l0 = 1.0, h = 0.1, x = 1.3, v = 0.4;
  const Eigen::Vector3d n = Eigen::Vector3d(2.0, 3.0, 6.0) / 7.0;
  testing::TestScene scene =
      testing::particles(3, {0, 0, 0, x * n.x(), x * n.y(), x * n.z()}, m, {true, false});
  scene.initial.v.segment<3>(3) = v * n;
  scene.add_spring(0, 1, k, l0);
  scene.model.integrator.use(integrator_method("linearly-implicit-euler"));
  scene.model.integrator.dt = h;
  State state = scene.initial;
  make_integrator(scene.model)->step(state);
  const double v_next = (m * v - h * k * (x - l0)) / (m + h * h * k);
  EXPECT_LT((state.v.segment<3>(3) - v_next * n).norm(), 1e-14);
  EXPECT_LT((state.q.segment<3>(3) - (x + h * v_next) * n).norm(), 1e-14);
  EXPECT_EQ(state.q.segment<3>(0), Eigen::Vector3d::Zero());
}

TEST(LinearlyImplicitEuler, TransverseMotionUsesTheFullSpringHessian) {
  // Moving across a stretched spring: (m I + h² H) δv = h F - h² H v, H = k[P + (1 - l0/l)(I - P)].
  const double m = 1.0, k = 10.0, l0 = 0.5, h = 0.05;
  testing::TestScene scene = testing::particles(3, {0, 0, 0, 1, 0, 0}, m, {true, false});
  scene.initial.v.segment<3>(3) << 0.0, 2.0, -1.0;
  scene.add_spring(0, 1, k, l0);
  scene.model.integrator.use(integrator_method("linearly-implicit-euler"));
  scene.model.integrator.dt = h;
  State state = scene.initial;
  make_integrator(scene.model)->step(state);
  const Eigen::Matrix3d H = k * Eigen::Vector3d(1.0, 1.0 - l0, 1.0 - l0).asDiagonal();
  const Eigen::Vector3d v0(0.0, 2.0, -1.0), F(-k * (1.0 - l0), 0.0, 0.0);
  const Eigen::Vector3d dv =
      (m * Eigen::Matrix3d::Identity() + h * h * H).lu().solve(h * F - h * h * H * v0);
  EXPECT_LT((state.v.segment<3>(3) - (v0 + dv)).norm(), 1e-14);
}

TEST(LinearlyImplicitEuler, FixedParticlesStayExactlyInPlace) {
  Scene scene = testing::cloth(6, 80.0, "linearly-implicit-euler", 0.01, true, "top-row");
  State state = scene.initial;
  const auto integrator = make_integrator(scene.model);
  for (int step = 0; step < 50; ++step) integrator->step(state);
  EXPECT_EQ(state.q.head(18), scene.initial.q.head(18));
  EXPECT_EQ(state.v.head(18), Vector::Zero(18));
  EXPECT_LT(state.q[3 * 35 + 1], -0.05);
}

/// max |v_a - v_b| after one step of two integrators from the same moving cloth state.
double one_step_difference(std::string_view a, std::string_view b, double h) {
  Scene scene = testing::cloth(5, 1.0, "implicit-euler", h);
  State start = scene.initial;
  start.v = Vector::NullaryExpr(
      start.v.size(), [](Eigen::Index k) { return 0.1 * std::sin(0.7 * static_cast<double>(k)); });
  zero_fixed(scene.model, start.v);
  State sa = start, sb = start;
  for (auto [method, state] : {std::pair{a, &sa}, std::pair{b, &sb}}) {
    scene.model.integrator.use(integrator_method(method));
    if (scene.model.integrator.options.has("newton-tolerance")) {
      scene.model.integrator.options.set("newton-tolerance", 1e-14);
    }
    make_integrator(scene.model)->step(*state);
  }
  return (sa.v - sb.v).lpNorm<Eigen::Infinity>();
}

TEST(LinearlyImplicitEuler, DiffersFromTheCompatLinearizationAndFromNewtonByOhCubedPerStep) {
  for (std::string_view other : {"linearized-implicit-euler", "implicit-euler"}) {
    // Both linearizations agree with the exact step up to O(h²) in the force, so velocities
    // differ by O(h³): halving h divides the difference by about 8.
    const double coarse = one_step_difference("linearly-implicit-euler", other, 0.0025);
    const double fine = one_step_difference("linearly-implicit-euler", other, 0.00125);
    EXPECT_GT(fine, 1e-9) << std::string(other) << ": a different method";
    EXPECT_GT(coarse / fine, 7.0) << std::string(other);
    EXPECT_LT(coarse / fine, 9.0) << std::string(other);
  }
}

TEST(LinearlyImplicitEuler, ProjectedHessianChangesOnlyCompressedSprings) {
  // Two particles 0.5 apart on a spring of rest length 1 (compressed), moving sideways.
  auto step = [](bool project, double l0) {
    testing::TestScene scene = testing::particles(3, {0, 0, 0, 0.5, 0, 0}, 1.0, {true, false});
    scene.initial.v.segment<3>(3) << 0.0, 1.0, 0.0;
    scene.add_spring(0, 1, 100.0, l0);
    scene.model.integrator.use(integrator_method("linearly-implicit-euler"));
    scene.model.integrator.dt = 0.1;
    scene.model.integrator.options.set("hessian", project ? "projected" : "exact");
    State state = scene.initial;
    make_integrator(scene.model)->step(state);
    return state.v;
  };
  EXPECT_GT((step(true, 1.0) - step(false, 1.0)).norm(), 0.1);
  EXPECT_EQ(step(true, 0.25), step(false, 0.25));
  // Projected: the transverse block is m + h²·0 = 1, so the sideways speed is kept.
  EXPECT_DOUBLE_EQ(step(true, 1.0)[4], 1.0);
}

TEST(LinearlyImplicitEuler, SolvesIndefiniteSystemsCorrectly) {
  // Strongly compressed stiff springs make M + h² hessX indefinite; the answer must still
  // satisfy the linear system (the LDLᵀ residual check falls back to LU when needed).
  testing::TestScene scene =
      testing::particles(3, {0, 0, 0, 0.1, 0, 0, 0.1, 0.1, 0}, 1e-3, {true, false, false});
  scene.initial.v.setConstant(0.3);
  scene.initial.v.head(3).setZero();
  scene.add_spring(0, 1, 1e4, 1.0);
  scene.add_spring(1, 2, 1e4, 1.0);
  scene.model.integrator.use(integrator_method("linearly-implicit-euler"));
  scene.model.integrator.dt = 0.01;
  State state = scene.initial;
  make_integrator(scene.model)->step(state);
  // Check (M + h² hessX) δv = h F - h² hessX v on the free DOFs directly.
  const double h = 0.01;
  const Vector& q = scene.initial.q;
  const Vector& v = scene.initial.v;
  const ForceSet forces(scene.model);
  const SparseMatrix Hx = compute_hessian_x(forces, q, v);
  const Vector dv = state.v - v;
  Vector residual = scene.model.mass.cwiseProduct(dv) + h * h * (Hx * dv) -
                    (h * compute_force(forces, q, v) - h * h * (Hx * v));
  zero_fixed(scene.model, residual);
  EXPECT_LT(residual.norm(), 1e-9 * (h * compute_force(forces, q, v)).norm());
}

}  // namespace
}  // namespace fosssim
