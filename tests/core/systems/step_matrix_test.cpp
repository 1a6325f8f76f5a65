// Tests of the step matrix (core/systems/step_matrix.h) in 2D and 3D.
//
// Math checked, against matrices built densely by hand from compute_hessian_x/_v:
// - kIdentityRows: A = diag(m) + h² hessX + h hessV with the rows and columns of fixed particles
//   zeroed and 1 on their diagonal (docs/integrators.md, 'Fixed particles'); restrict zeroes
//   the fixed DOFs of a right-hand side and add_solution adds the whole vector;
// - kElimination: A = P (diag(m) + h² hessX + h hessV) Pᵀ with P the selection of the free
//   DOFs; restrict = P b, add_solution adds Pᵀ x;
// - both: the same system solved either way gives the same velocity change on the free DOFs
//   and none on the fixed ones; reassembling gives the same matrix; given a vector u, the
//   right-hand side loses h² hessX u over every DOF (before the fixed-particle rule);
// - writes: when every spring is damped, the hessV pass writes the blocks of the hessX pass and
//   the recorded list is kept once (as long as an undamped chain's), walked twice with the
//   same bits as triplets; when the passes stop matching, they are recorded anew;
// - definite_hessian: a compressed spring's block loses its negative transverse stiffness, so
//   the matrix differs from the exact one exactly where that spring's blocks are.

#include "core/systems/step_matrix.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "core/force_evaluation.h"
#include "support/dense.h"
#include "support/random.h"
#include "support/scene_builder.h"
#include "support/typed_tests.h"

namespace fosssim::testing {
namespace {

FOSSSIM_TEST_SUITE_IN_2D_AND_3D(StepMatrixTest);

/// Four particles, the second fixed, with springs (one damped) and drag.
template <int D>
TestScene fixed_scene(unsigned seed) {
  Random random(seed);
  TestScene scene = random_spring_chain(D, random);
  scene.add_spring(0, 2, 3.0, 0.5, 2.0);  // damped: hessV and a non-symmetric hessX
  scene.add_drag(0.4);
  return scene;
}

/// diag(m) + h² hessX + h hessV, densely.
Eigen::MatrixXd full_matrix(const ForceSet& forces, const Vector& q, const Vector& v, double h) {
  Eigen::MatrixXd A =
      h * h * dense(compute_hessian_x(forces, q, v)) + h * dense(compute_hessian_v(forces, q, v));
  A.diagonal() += forces.mass();
  return A;
}

TYPED_TEST(StepMatrixTest, IdentityRowsForFixedParticles) {
  constexpr int D = TypeParam::value;
  const TestScene scene = fixed_scene<D>(87);
  const ForceSet forces(scene.model);
  const Vector& q = scene.initial.q;
  const Vector& v = scene.initial.v;
  const double h = 0.05;
  Eigen::MatrixXd expected = full_matrix(forces, q, v, h);
  expected.middleRows(D, D).setZero();  // particle 1 is fixed
  expected.middleCols(D, D).setZero();
  expected.block(D, D, D, D).setIdentity();
  StepMatrix matrix(forces, FixedParticleRule::kIdentityRows);
  EXPECT_EQ(matrix.size(), 4 * D);
  const Eigen::MatrixXd A = dense(matrix.assemble(q, v, h));
  EXPECT_TRUE(A.isApprox(expected, 1e-15));
  EXPECT_EQ(dense(matrix.assemble(q, v, h)), A) << "reassembling gives the same bits";

  const Vector b = Vector::LinSpaced(4 * D, 1.0, 2.0);
  Vector restricted_expected = b;
  restricted_expected.segment(D, D).setZero();
  EXPECT_EQ(matrix.restrict(b), restricted_expected);
  Vector full = Vector::Ones(4 * D);
  matrix.add_solution(b, full);
  EXPECT_EQ(full, Vector(Vector::Ones(4 * D) + b));
}

TYPED_TEST(StepMatrixTest, EliminationKeepsOnlyTheFreeDofs) {
  constexpr int D = TypeParam::value;
  const TestScene scene = fixed_scene<D>(88);
  const ForceSet forces(scene.model);
  const Vector& q = scene.initial.q;
  const Vector& v = scene.initial.v;
  const double h = 0.05;
  // P selects particles 0, 2, 3.
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(3 * D, 4 * D);
  P.block(0, 0, D, D).setIdentity();
  P.block(D, 2 * D, D, D).setIdentity();
  P.block(2 * D, 3 * D, D, D).setIdentity();
  const Eigen::MatrixXd expected = P * full_matrix(forces, q, v, h) * P.transpose();
  StepMatrix matrix(forces, FixedParticleRule::kElimination);
  EXPECT_EQ(matrix.size(), 3 * D);
  EXPECT_TRUE(dense(matrix.assemble(q, v, h)).isApprox(expected, 1e-15));
  const Vector b = Vector::LinSpaced(4 * D, 1.0, 2.0);
  EXPECT_EQ(matrix.restrict(b), Vector(P * b));
  const Vector x = Vector::LinSpaced(3 * D, -1.0, 1.0);
  Vector full = Vector::Zero(4 * D);
  matrix.add_solution(x, full);
  EXPECT_EQ(full, Vector(P.transpose() * x));
}

/// Four particles, the second fixed, in a chain of springs with damping `b` (the last one of
/// rest length 0).
TestScene damped_chain(int dim, double b) {
  Random random(31);
  TestScene scene(dim, "implicit-euler", 0.05);
  for (int p = 0; p < 4; ++p) {
    const Vector x = random.uniform_vector(dim, -1.0, 1.0);
    const Vector v = random.uniform_vector(dim, -1.0, 1.0);
    scene.add_particle(random.uniform(0.5, 2.0), x, v, p == 1);
  }
  scene.add_spring(0, 1, 5.0, 0.3, b);
  scene.add_spring(1, 2, 2.0, 1.5, 2.0 * b);
  scene.add_spring(2, 3, 7.0, 0.0, 3.0 * b);
  return scene;
}

TYPED_TEST(StepMatrixTest, AHessVPassThatRepeatsTheHessXPassIsKeptOnce) {
  constexpr int D = TypeParam::value;
  const TestScene damped = damped_chain(D, 0.5);
  const TestScene undamped = damped_chain(D, 0.0);  // hessV has no entries
  const ForceSet damped_forces(damped.model), undamped_forces(undamped.model);
  StepMatrix matrix(damped_forces, FixedParticleRule::kIdentityRows);
  StepMatrix reference(damped_forces, FixedParticleRule::kIdentityRows);
  StepMatrix undamped_matrix(undamped_forces, FixedParticleRule::kIdentityRows);
  const double h = 0.05;
  Vector q = damped.initial.q;
  const Vector& v = damped.initial.v;
  undamped_matrix.assemble(q, v, h);
  EXPECT_EQ(dense(matrix.assemble(q, v, h)), dense(reference.assemble_from_triplets(q, v, h)));
  EXPECT_EQ(matrix.pattern_bytes(), undamped_matrix.pattern_bytes())
      << "the damped springs' hessV blocks are the hessX blocks: one list of writes";

  q += 0.1 * v;  // the recorded writes, walked twice, at another state
  EXPECT_EQ(dense(matrix.assemble(q, v, h)), dense(reference.assemble_from_triplets(q, v, h)));
  // Particle 3 on particle 2: the zero-length spring's hessV has no entries, so the passes
  // differ and the writes are recorded anew.
  q.segment(3 * D, D) = q.segment(2 * D, D);
  EXPECT_EQ(dense(matrix.assemble(q, v, h)), dense(reference.assemble_from_triplets(q, v, h)));
  EXPECT_GT(matrix.pattern_bytes(), undamped_matrix.pattern_bytes());
}

TYPED_TEST(StepMatrixTest, BothRulesGiveTheSameStep) {
  constexpr int D = TypeParam::value;
  const TestScene scene = fixed_scene<D>(89);
  const ForceSet forces(scene.model);
  const Vector& q = scene.initial.q;
  const Vector& v = scene.initial.v;
  const double h = 0.05;
  const Vector rhs = h * compute_force(forces, q, v);
  Vector dv[2];
  int k = 0;
  for (FixedParticleRule rule :
       {FixedParticleRule::kIdentityRows, FixedParticleRule::kElimination}) {
    StepMatrix matrix(forces, rule);
    const Eigen::MatrixXd A = dense(matrix.assemble(q, v, h));
    dv[k] = Vector::Zero(4 * D);
    matrix.add_solution(A.partialPivLu().solve(matrix.restrict(rhs)), dv[k]);
    ++k;
  }
  EXPECT_TRUE(dv[0].isApprox(dv[1], 1e-13));
  EXPECT_EQ(Vector(dv[0].segment(D, D)), Vector::Zero(D)) << "the fixed particle keeps its v";
  EXPECT_EQ(Vector(dv[1].segment(D, D)), Vector::Zero(D));
  EXPECT_GT(dv[0].norm(), 0.0);
}

TYPED_TEST(StepMatrixTest, SubtractsHSquaredHessXTimesAVectorFromTheRightSide) {
  constexpr int D = TypeParam::value;
  const TestScene scene = fixed_scene<D>(90);
  const ForceSet forces(scene.model);
  const Vector& q = scene.initial.q;
  const Vector& v = scene.initial.v;
  const double h = 0.05;
  const Vector u = Vector::LinSpaced(4 * D, -2.0, 3.0);
  const Vector start = Vector::LinSpaced(4 * D, 1.0, 5.0);
  for (FixedParticleRule rule :
       {FixedParticleRule::kIdentityRows, FixedParticleRule::kElimination}) {
    StepMatrix matrix(forces, rule);
    Vector rhs = start;
    const Eigen::MatrixXd with = dense(matrix.assemble(q, v, h, &u, &rhs));
    const Vector expected = start - h * h * (dense(compute_hessian_x(forces, q, v)) * u);
    EXPECT_TRUE(rhs.isApprox(expected, 1e-14));
    EXPECT_NE(Vector(rhs.segment(D, D)), Vector(start.segment(D, D))) << "the fixed DOFs too";
    EXPECT_EQ(with, dense(matrix.assemble(q, v, h))) << "the matrix is the same";
  }
}

TYPED_TEST(StepMatrixTest, DefiniteHessianDropsACompressedSpringsTransverseStiffness) {
  constexpr int D = TypeParam::value;
  TestScene scene(D, "linearly-implicit-euler", 0.1);
  Vector x1 = Vector::Zero(D);
  x1[0] = 0.5;  // rest length 1: compressed to half
  scene.add_particle(1.0, Vector::Zero(D), Vector::Zero(D));
  scene.add_particle(1.0, x1, Vector::Zero(D));
  scene.add_spring(0, 1, 10.0, 1.0);
  const ForceSet forces(scene.model);
  StepMatrix exact(forces, FixedParticleRule::kElimination);
  StepMatrix definite(forces, FixedParticleRule::kElimination, /*definite_hessian=*/true);
  const double h = 0.1;
  const Eigen::MatrixXd a = dense(exact.assemble(scene.initial.q, scene.initial.v, h));
  const Eigen::MatrixXd b = dense(definite.assemble(scene.initial.q, scene.initial.v, h));
  // Transverse stiffness k (l - l0)/l = -10 in the exact block, 0 in the definite one.
  EXPECT_DOUBLE_EQ(a(1, 1), 1.0 + h * h * -10.0);
  EXPECT_DOUBLE_EQ(b(1, 1), 1.0);
  EXPECT_DOUBLE_EQ(a(0, 0), b(0, 0)) << "the axial stiffness is unchanged";
  EXPECT_GT(b.selfadjointView<Eigen::Lower>().eigenvalues().minCoeff(), 0.0);
  EXPECT_LT(a.selfadjointView<Eigen::Lower>().eigenvalues().minCoeff(), 1.0);
}

}  // namespace
}  // namespace fosssim::testing
