// The implicit integrators' course-exact path (docs/solvers.md, 'The course-exact dense path'):
// small 2D systems assembled densely (StepMatrix::assemble_course) and solved by CourseLu.
//
// Math checked, on a 2D scene of 6 particles (12 unknowns: more than one panel of 8, so the
// substitutions' blocking is used) with a fixed particle, damped springs, Newtonian gravity,
// drag and gravity:
// - linearized implicit Euler: the velocity change is exactly CourseLu's solution of
//   A δ = h F(q + h v, v) (fixed DOFs zeroed) with A = assemble_course(q + h v, v), which solves
//   that system to round-off (‖A δ - b‖ ≤ 1e-13 (‖A‖ ‖δ‖ + ‖b‖)) and agrees with the sparse
//   assembly and solver to 1e-12; then q = q + h vⁿ⁺¹ exactly; the fixed particle keeps its
//   velocity;
// - assemble_course: every entry is h (h ΣhessX + ΣhessV) + m, which differs from the sparse
//   h² hessX + h hessV + M by round-off only; fixed rows and columns are 0 with a unit diagonal;
// - implicit Euler: the step solves backward Euler's equations (residual below 1e-8 relative)
//   and both integrators give the same bytes when run twice.

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "core/force_evaluation.h"
#include "core/forces/spring_force.h"
#include "core/solvers/course_lu.h"
#include "core/solvers/step_solver.h"
#include "core/systems/backward_euler.h"
#include "core/systems/step_matrix.h"
#include "support/scene_builder.h"

namespace fosssim::testing {
namespace {

TestScene six_particles(std::string_view integrator) {
  TestScene scene(2, integrator, 0.01);
  const double xs[6][4] = {{0.0, 0.0, 0.0, 0.0},  {0.9, 0.1, 0.3, -0.2}, {1.7, -0.3, 0.0, 0.5},
                           {2.8, 0.2, -0.4, 0.1}, {3.5, 1.1, 0.2, 0.2},  {4.6, 0.4, 0.0, -0.7}};
  for (int p = 0; p < 6; ++p) {
    scene.add_particle(1.0 + 0.25 * p, vec({xs[p][0], xs[p][1]}), vec({xs[p][2], xs[p][3]}),
                       p == 0);
  }
  for (int p = 0; p + 1 < 6; ++p) scene.add_spring(p, p + 1, 40.0 + 7.0 * p, 0.8, 0.3 * p);
  scene.add_spring(1, 4, 12.0, 2.0, 0.0);
  scene.add_simple_gravity(vec({0.0, -9.81}));
  scene.add_gravitation(2, 5, 3.0);
  scene.add_drag(0.05);
  return scene;
}

TEST(CourseExactSteps, AssembleCourseIsTheStepMatrixSummedTheCoursesWay) {
  const TestScene scene = six_particles("linearized-implicit-euler");
  const ForceSet forces(scene.model);
  StepMatrix matrix(forces, FixedParticleRule::kIdentityRows);
  const double h = 0.01;
  const Vector& q = scene.initial.q;
  const Vector& v = scene.initial.v;
  const Eigen::MatrixXd course = matrix.assemble_course(q, v, h);
  const Eigen::MatrixXd sparse(matrix.assemble(q, v, h));
  EXPECT_LE((course - sparse).lpNorm<Eigen::Infinity>(), 1e-13 * sparse.lpNorm<Eigen::Infinity>());
  for (int k = 0; k < 12; ++k) {
    for (int dof : {0, 1}) {
      EXPECT_EQ(course(dof, k), dof == k ? 1.0 : 0.0);
      EXPECT_EQ(course(k, dof), dof == k ? 1.0 : 0.0);
    }
  }
  // One entry written out: particle 5's x row, touched by spring (4, 5) and the gravitation
  // (2, 5), and its mass and drag.
  ForceInput in{q, v, forces.model().mass};
  HessianBuilder hx, hv;
  for (const Force* force : forces) {
    if (const auto* spring = dynamic_cast<const SpringForce<2>*>(force)) {
      spring->add_course_hessian_x(in, hx);
      spring->add_course_hessian_v(in, hv);
    } else {
      force->add_hessian_x(in, hx);
      force->add_hessian_v(in, hv);
    }
  }
  double sum_x = 0.0, sum_v = 0.0;
  for (const Triplet& t : hx.triplets()) {
    if (t.row() == 10 && t.col() == 10) sum_x = sum_x + t.value();
  }
  for (const Triplet& t : hv.triplets()) {
    if (t.row() == 10 && t.col() == 10) sum_v = sum_v + t.value();
  }
  EXPECT_EQ(course(10, 10), h * (h * sum_x + sum_v) + forces.model().mass[10]);
}

TEST(CourseExactSteps, LinearizedImplicitStepIsTheCourseLuSolution) {
  const TestScene scene = six_particles("linearized-implicit-euler");
  const ForceSet forces(scene.model);
  const double h = 0.01;
  const State& start = scene.initial;
  const State next = run_steps(scene.model, start, 1);
  EXPECT_EQ(run_steps(scene.model, start, 1).q, next.q) << "deterministic";

  const Vector predicted = start.q + h * start.v;
  StepMatrix matrix(forces, FixedParticleRule::kIdentityRows);
  const Vector b = matrix.restrict(h * compute_force(forces, predicted, start.v));
  const Eigen::MatrixXd A = matrix.assemble_course(predicted, start.v, h);
  CourseLu lu;
  ASSERT_TRUE(lu.factor(A));
  const Vector delta = lu.solve(b);
  EXPECT_EQ(next.v, start.v + delta);
  EXPECT_EQ(next.q, start.q + h * next.v);
  EXPECT_EQ(next.v.head(2), start.v.head(2)) << "the fixed particle keeps its velocity";
  EXPECT_LE((A * delta - b).norm(), 1e-13 * (A.norm() * delta.norm() + b.norm()));

  StepSolver sparse(false, SolverChoice::kEigen);
  const auto sparse_delta = sparse.solve(matrix.assemble(predicted, start.v, h), b);
  ASSERT_TRUE(sparse_delta);
  EXPECT_LE((*sparse_delta - delta).norm(), 1e-12 * delta.norm());
}

TEST(CourseExactSteps, ImplicitStepSolvesBackwardEulerAndIsDeterministic) {
  const TestScene scene = six_particles("implicit-euler");
  const ForceSet forces(scene.model);
  const double h = 0.01;
  const State& start = scene.initial;
  const State next = run_steps(scene.model, start, 3);
  const State again = run_steps(scene.model, start, 3);
  EXPECT_EQ(next.q, again.q);
  EXPECT_EQ(next.v, again.v);
  const State one = run_steps(scene.model, start, 1);
  const BackwardEulerStep problem{forces, start, h};
  const Vector residual = problem.residual(one.v - start.v);
  EXPECT_LE(residual.norm(), 1e-8 * (h * compute_force(forces, one.q, one.v)).norm());
  EXPECT_EQ(one.v.head(2), start.v.head(2));
}

}  // namespace
}  // namespace fosssim::testing
