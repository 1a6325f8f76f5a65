// Tests of the local/global solver's constant pieces (core/systems/local_global_system.h) and
// the numbering of free unknowns (core/systems/free_dofs.h).
//
// Checked:
// - sort_mass_spring_forces: springs of SpringForce and SpringSetForce, in force order, with
//   their damping; DragSpringForce as an anchor; every other force left to explicit treatment;
// - assemble_local_global_matrix equals M/h² + Σ_s (k_s + b_s/h)(e_i - e_j)(e_i - e_j)ᵀ
//   + Σ_a k_a e_a e_aᵀ built densely over every particle, then restricted to the free ones;
// - FreeDofs numbers the free particles and DOFs in order, restricts and expands vectors.

#include "core/systems/local_global_system.h"

#include <gtest/gtest.h>

#include "core/forces/simple_gravity_force.h"
#include "core/forces/spring_set_force.h"
#include "support/dense.h"
#include "support/scene_builder.h"

namespace fosssim::testing {
namespace {

TEST(FreeDofs, NumbersTheFreeParticlesInOrder) {
  const FreeDofs free({false, true, false, false}, 3);
  EXPECT_EQ(free.num_particles(), 3);
  EXPECT_EQ(free.num_dofs(), 9);
  EXPECT_EQ(free.of_particle(0), 0);
  EXPECT_EQ(free.of_particle(1), -1);
  EXPECT_EQ(free.of_particle(3), 2);
  EXPECT_EQ(free.of_dof(4), -1);
  EXPECT_EQ(free.of_dof(7), 4);  // particle 2, z -> free particle 1, z
  EXPECT_EQ(free.particles(), (std::vector<int>{0, 2, 3}));
  const Vector full = Vector::LinSpaced(12, 0.0, 11.0);
  const Vector reduced = free.restrict(full);
  EXPECT_EQ(reduced, vec({0, 1, 2, 6, 7, 8, 9, 10, 11}));
  Vector back = Vector::Zero(12);
  free.add_expanded(reduced, back);
  EXPECT_EQ(back, vec({0, 1, 2, 0, 0, 0, 6, 7, 8, 9, 10, 11}));
}

TEST(LocalGlobalSystem, SortsSpringsAnchorsAndTheRest) {
  TestScene scene(3, "local-global", 0.1);
  for (int p = 0; p < 4; ++p) scene.add_particle(1.0, vec({1.0 * p, 0, 0}), vec({0, 0, 0}));
  scene.add_spring(0, 1, 10.0, 1.0, 0.5);
  scene.add_simple_gravity(vec({0, -9.8, 0}));
  scene.add_force(std::make_unique<SpringSetForce<3>>(
      std::vector<SpringTerm>{{1, 2, 20.0, 1.0, 0.0}, {2, 3, 30.0, 1.0, 0.0}}, "set"));
  DragSpringForce drag(3);
  const MassSpringForces split = sort_mass_spring_forces(ForceSet(scene.model, {&drag}));
  ASSERT_EQ(split.springs.size(), 3u);
  EXPECT_EQ(split.springs[0].k, 10.0);
  EXPECT_EQ(split.springs[0].b, 0.5);
  EXPECT_EQ(split.springs[2].j, 3);
  ASSERT_EQ(split.anchors.size(), 1u);
  EXPECT_EQ(split.anchors[0], &drag);
  ASSERT_EQ(split.others.size(), 1u);
  EXPECT_EQ(split.others[0], scene.model.forces[1].get());
}

TEST(LocalGlobalSystem, TheMatrixIsMassOverHSquaredPlusTheSpringLaplacianPlusAnchors) {
  const int n = 4;
  const double h = 0.1;
  Vector mass(2 * n);
  mass << 1, 1, 2, 2, 3, 3, 4, 4;
  const std::vector<SpringTerm> springs = {{0, 1, 10.0, 1.0, 0.5},
                                           {1, 2, 20.0, 1.0, 0.0},
                                           {2, 3, 30.0, 1.0, 1.0},
                                           {0, 3, 5.0, 2.0, 0.0}};
  const std::vector<AnchorTerm> anchors = {{2, 7.0, Eigen::Vector3d::Zero()}};
  Eigen::MatrixXd full = Eigen::MatrixXd::Zero(n, n);
  for (int p = 0; p < n; ++p) full(p, p) = mass[2 * p] / (h * h);
  for (const SpringTerm& s : springs) {
    Eigen::VectorXd a = Eigen::VectorXd::Zero(n);
    a[s.i] = 1.0;
    a[s.j] = -1.0;
    full += (s.k + s.b / h) * a * a.transpose();
  }
  full(2, 2) += 7.0;
  const FreeDofs free({false, true, false, false}, 2);  // particle 1 eliminated
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(3, n);
  P(0, 0) = P(1, 2) = P(2, 3) = 1.0;
  const Eigen::MatrixXd Q = dense(assemble_local_global_matrix(mass, free, springs, anchors, h));
  EXPECT_TRUE(Q.isApprox(P * full * P.transpose(), 1e-15));
}

}  // namespace
}  // namespace fosssim::testing
