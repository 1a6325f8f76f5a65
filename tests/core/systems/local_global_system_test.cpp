// Tests of the local/global solver's constant pieces (core/systems/local_global_system.h) and
// the numbering of free unknowns (core/systems/free_dofs.h).
//
// Checked:
// - sort_mass_spring_forces: springs of SpringForce, SpringSetForce and ElasticBodySpringForce
//   (k = α / l0), in force order, with their damping; DragSpringForce as an anchor, asked for
//   where it pulls; forces declared explicit (gravity, elastic bending, CST) left to explicit
//   treatment; a force that declares nothing reported by check_local_global_roles, by name,
//   and never sorted among the explicit ones;
// - assemble_local_global_matrix equals M/h² + Σ_s (k_s + b_s/h)(e_i - e_j)(e_i - e_j)ᵀ
//   + Σ_a k_a e_a e_aᵀ built densely over every particle, then restricted to the free ones;
// - FreeDofs numbers the free particles and DOFs in order, restricts and expands vectors.

#include "core/systems/local_global_system.h"

#include <gtest/gtest.h>

#include "core/forces/drag_spring_force.h"
#include "core/forces/elastic_body_bending_force.h"
#include "core/forces/elastic_body_cst_force.h"
#include "core/forces/elastic_body_spring_force.h"
#include "core/forces/simple_gravity_force.h"
#include "core/forces/spring_set_force.h"
#include "core/integrators/integrator_registry.h"
#include "support/dense.h"
#include "support/scene_builder.h"
#include "support/thrown.h"

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

TEST(LocalGlobalSystem, AnAnchorIsAskedWhereItPullsNow) {
  TestScene scene(2, "local-global", 0.1);
  scene.add_particle(1.0, vec({0, 0}), vec({0, 0}));
  DragSpringForce drag(2);
  const MassSpringForces split = sort_mass_spring_forces(ForceSet(scene.model, {&drag}));
  ASSERT_EQ(split.anchors.size(), 1u);
  EXPECT_FALSE(split.anchors[0]->local_global_anchor().has_value());  // nothing grabbed
  drag.grab(0, Eigen::Vector3d(1.0, 2.0, 0.0), 50.0);
  const std::optional<AnchorTerm> anchor = split.anchors[0]->local_global_anchor();
  ASSERT_TRUE(anchor.has_value());
  EXPECT_EQ(anchor->i, 0);
  EXPECT_EQ(anchor->k, 50.0);
  EXPECT_EQ(anchor->target, Eigen::Vector3d(1.0, 2.0, 0.0));
}

TEST(LocalGlobalSystem, ElasticSpringsAreSpringsAndBendingAndTrianglesAreExplicit) {
  TestScene scene(2, "local-global", 0.01);
  scene.add_particle(1.0, vec({0, 0}), vec({0, 0}));
  scene.add_particle(1.0, vec({1, 0}), vec({0, 0}));
  scene.add_particle(1.0, vec({0, 1}), vec({0, 0}));
  scene.add_force(std::make_unique<ElasticBodyBendingForce>(0, 1, 2, 2.0, 0.3, 2.4));
  scene.add_force(std::make_unique<ElasticBodySpringForce<2>>(0, 1, 6.0, 1.5));
  scene.add_force(std::make_unique<ElasticBodyCstForce<2>>(
      std::array<int, 3>{0, 1, 2}, 10.0, 0.3,
      compute_cst_rest<2>(Vec<2>(0, 0), Vec<2>(1, 0), Vec<2>(0, 1))));
  scene.add_simple_gravity(vec({0, -9.8}));
  const MassSpringForces split = sort_mass_spring_forces(ForceSet(scene.model));
  ASSERT_EQ(split.springs.size(), 1u);
  EXPECT_EQ(split.springs[0].i, 0);
  EXPECT_EQ(split.springs[0].j, 1);
  EXPECT_EQ(split.springs[0].k, 4.0);  // α / l0
  EXPECT_EQ(split.springs[0].l0, 1.5);
  EXPECT_EQ(split.springs[0].b, 0.0);
  ASSERT_EQ(split.others.size(), 3u);  // bending, CST, gravity, in force order
  EXPECT_EQ(split.others[0], scene.model.forces[0].get());
  EXPECT_EQ(split.others[1], scene.model.forces[2].get());
  EXPECT_EQ(split.others[2], scene.model.forces[3].get());
  EXPECT_TRUE(split.undeclared.empty());
  EXPECT_EQ(split.contact, nullptr);
}

/// A force that says nothing about local/global: a constant push on particle 0.
class UndeclaredPush final : public Force {
 public:
  void add_energy(const ForceInput&, double&) const override {}
  void add_gradient(const ForceInput&, Vector& gradient) const override { gradient[0] -= 1.0; }
  void add_hessian_x(const ForceInput&, HessianBuilder&) const override {}
  void add_hessian_v(const ForceInput&, HessianBuilder&) const override {}
  bool is_conservative() const override { return false; }
  std::string label() const override { return "undeclaredpush"; }
};

TEST(LocalGlobalSystem, AForceThatDeclaresNothingIsReportedNotMadeExplicit) {
  TestScene scene(2, "local-global", 0.01);
  scene.add_particle(1.0, vec({0, 0}), vec({0, 0}));
  scene.add_particle(1.0, vec({1, 0}), vec({0, 0}));
  scene.add_spring(0, 1, 10.0, 1.0);
  scene.add_force(std::make_unique<UndeclaredPush>());
  scene.add_force(std::make_unique<UndeclaredPush>());
  const MassSpringForces split = sort_mass_spring_forces(ForceSet(scene.model));
  EXPECT_EQ(split.springs.size(), 1u);
  EXPECT_TRUE(split.others.empty());
  ASSERT_EQ(split.undeclared.size(), 2u);
  EXPECT_EQ(split.undeclared[0], scene.model.forces[1].get());
  const Error error = thrown_by([&] { check_local_global_roles(split, "local-global"); });
  EXPECT_EQ(error.kind(), ErrorKind::kBadInput);
  const std::string message = error.what();
  EXPECT_NE(message.find("local-global: the force undeclaredpush does not say"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("nor 1 other force"), std::string::npos) << message;
  // The integrators that take the sorting as it is refuse the scene when bound to it.
  for (std::string_view method : {"local-global", "accelerated-local-global"}) {
    scene.model.integrator.use(integrator_method(method));
    const Error bound = thrown_by([&] { (void)make_integrator(scene.model); });
    EXPECT_EQ(bound.kind(), ErrorKind::kBadInput) << method;
    EXPECT_NE(std::string(bound.what()).find("undeclaredpush"), std::string::npos) << method;
  }
  // Quasi-Newton uses the springs only for its preconditioner and the force in its residual.
  scene.model.integrator.use(integrator_method("quasi-newton"));
  EXPECT_NO_THROW((void)make_integrator(scene.model));
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
