// Tests of the rigid-body contact responses (core/rigid/contact_lcp.h, rigid_contact_response.h):
// the handout's LCP example, Dantzig against the exact QP on random problems, the LCP and
// velocity projection giving the same velocities on random contact, elastic generalized
// reflections conserving kinetic energy and momentum, and the degenerate cases (redundant
// contacts, bodies exactly touching, a fixed body with a velocity under gr-lcp).

#include "core/rigid/rigid_contact_response.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <string>

#include "core/error.h"
#include "core/rigid/rigid_contact_test_models.h"
#include "support/random.h"
#include "support/thrown.h"

namespace fosssim::testing {
namespace {

TEST(ContactLcp, HandoutExampleOfABlockOverATableEdge) {
  // A = [[13/20, 9/20], [9/20, 7/20]], b = (−2, −2): λ = (0, 40/7).
  ContactProblem problem;
  problem.A.resize(2, 2);
  problem.A << 13.0 / 20, 9.0 / 20, 9.0 / 20, 7.0 / 20;
  problem.b = Vector::Constant(2, -2.0);
  problem.J = problem.A.llt().matrixU();  // JᵀJ = A
  EXPECT_FALSE(is_degenerate(problem.A));
  const ContactSolveResult dantzig = solve_contact_lcp_dantzig(problem);
  ASSERT_TRUE(dantzig.valid) << dantzig.problem;
  EXPECT_NEAR(dantzig.lambda[0], 0.0, 1e-15);
  EXPECT_NEAR(dantzig.lambda[1], 5.714285714285714, 1e-14);
  const Vector qp = solve_contact_qp(problem, contact_qp_iteration_limit(2));
  EXPECT_NEAR(qp[0], 0.0, 1e-15);
  EXPECT_NEAR(qp[1], 5.714285714285714, 1e-14);
}

/// A = NᵀM⁻¹N for a random N of `contacts` columns over `dofs` coordinates, with random
/// diagonal masses; b = Nᵀq̇ for a random q̇ (the velocity projection's b: always solvable).
ContactProblem random_problem(Random& random, int dofs, int contacts) {
  Eigen::MatrixXd N(dofs, contacts);
  for (int i = 0; i < dofs; ++i) {
    for (int j = 0; j < contacts; ++j) N(i, j) = random.uniform(-1, 1);
  }
  const Vector inverse_mass = random.uniform_vector(dofs, 0.2, 3.0);
  ContactProblem problem;
  problem.J = inverse_mass.cwiseSqrt().asDiagonal() * N;
  problem.A = N.transpose() * inverse_mass.asDiagonal() * N;
  problem.b = N.transpose() * random.uniform_vector(dofs, -2, 1);
  return problem;
}

TEST(ContactLcp, DantzigAndTheQpAgreeOnRandomNonDegenerateProblems) {
  Random random(5);
  for (int trial = 0; trial < 200; ++trial) {
    const int contacts = 1 + random.index(8);
    const int dofs = contacts + random.index(6);  // N has full column rank: A is definite
    const ContactProblem problem = random_problem(random, dofs, contacts);
    ASSERT_FALSE(is_degenerate(problem.A));
    const ContactSolveResult dantzig = solve_contact_lcp_dantzig(problem);
    ASSERT_TRUE(dantzig.valid) << dantzig.problem;
    const Vector qp = solve_contact_qp(problem, contact_qp_iteration_limit(contacts));
    std::string why;
    EXPECT_TRUE(check_contact_solution(problem, qp, &why)) << why;
    // A definite: the solution is unique.
    EXPECT_LT((qp - dantzig.lambda).cwiseAbs().maxCoeff(),
              1e-9 * std::max(1.0, qp.cwiseAbs().maxCoeff()))
        << "trial " << trial;
  }
}

TEST(ContactLcp, TheQpSolvesDegenerateProblems) {
  // More contacts than coordinates: A is singular; the QP still gives a valid solution.
  Random random(8);
  for (int trial = 0; trial < 100; ++trial) {
    const int dofs = 1 + random.index(4);
    const int contacts = dofs + 1 + random.index(6);
    const ContactProblem problem = random_problem(random, dofs, contacts);
    EXPECT_TRUE(is_degenerate(problem.A));
    const Vector qp = solve_contact_qp(problem, contact_qp_iteration_limit(contacts));
    std::string why;
    EXPECT_TRUE(check_contact_solution(problem, qp, &why)) << "trial " << trial << ": " << why;
  }
}

TEST(ContactLcp, TheQpFailsClearlyWithinItsIterationLimit) {
  // A zero column with b < 0: no impulse can make that contact separate.
  ContactProblem problem;
  problem.A = Eigen::MatrixXd::Zero(1, 1);
  problem.J = Eigen::MatrixXd::Zero(3, 1);
  problem.b = Vector::Constant(1, -1.0);
  const Error error = thrown_by([&] { solve_contact_qp(problem, 100); });
  EXPECT_NE(std::string(error.what()).find("impossible to satisfy"), std::string::npos);
}

double kinetic_energy(const SceneModel& model, const Vector& v) {
  return 0.5 * v.dot(model.mass.cwiseProduct(v));
}

/// Random piles whose bodies move at random velocities, with no fixed body declaring a velocity.
std::pair<SceneModel, State> moving_pile(unsigned seed, bool with_fixed, double spread) {
  auto [model, state] = random_pile(seed, 12, spread, 0.7);
  Random random(seed + 1000);
  auto bodies = std::make_shared<RigidBodies>(*model.rigid_bodies);
  for (int b = 0; b < bodies->size(); ++b) {
    if (!with_fixed) {
      bodies->bodies[b].fixed = false;
      model.fixed[b] = false;
    }
    if (!bodies->bodies[b].fixed) {
      state.v.segment<3>(3 * b) << random.uniform(-2, 2), random.uniform(-2, 2),
          random.uniform(-3, 3);
    }
  }
  model.rigid_bodies = bodies;
  return {std::move(model), std::move(state)};
}

/// A grid of unit squares (1 to 3 rows, 2 to 4 columns) 0.15 apart with radii 0.1, slightly
/// tilted, of random vertex masses, at random velocities: every neighbour touches, none is
/// wedged into another (elastic answers exist). Piles of overlapping bodies can have none:
/// generalized reflections then cycle for ever (their limit ends them).
std::pair<SceneModel, State> moving_grid(unsigned seed) {
  Random random(seed);
  const int rows = 1 + random.index(3), columns = 2 + random.index(3);
  std::vector<BodySpec> specs;
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < columns; ++j) {
      BodySpec spec = body(box(1.15 * j, 1.15 * i, 1.15 * j + 1, 1.15 * i + 1));
      for (double& m : spec.masses) m = random.uniform(0.5, 2.0);
      spec.velocity = Vec2(random.uniform(-2, 2), random.uniform(-2, 2));
      spec.omega = random.uniform(-1, 1);
      specs.push_back(spec);
    }
  }
  auto [model, state] = make_rigid_model(specs);
  for (int b = 0; b < static_cast<int>(specs.size()); ++b)
    state.q[3 * b + 2] = random.uniform(-0.02, 0.02);
  return {std::move(model), std::move(state)};
}

TEST(RigidContactResponse, LcpAndVelocityProjectionGiveTheSameVelocities) {
  int compared = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    const auto [model, state] = moving_pile(seed, true, 6.0);
    const RigidBodies& bodies = *model.rigid_bodies;
    const auto contacts = detect_rigid_contacts(bodies, state.q);
    Vector lcp = state.v, vp = state.v;
    ContactReport lcp_report, vp_report;
    apply_inelastic_response(ContactSolver::kLcp, bodies, state.q, contacts, lcp, lcp_report);
    apply_inelastic_response(ContactSolver::kVelocityProjection, bodies, state.q, contacts, vp,
                             vp_report);
    EXPECT_LT((lcp - vp).cwiseAbs().maxCoeff(), 1e-9) << "seed " << seed;
    // No contact approaches afterwards.
    const ContactProblem after = assemble_contact_problem(ContactSolver::kVelocityProjection,
                                                          bodies, state.q, lcp, contacts);
    if (after.b.size() > 0) {
      EXPECT_GT(after.b.minCoeff(), -1e-9) << "seed " << seed;
    }
    compared += lcp_report.groups - lcp_report.fallbacks;
  }
  EXPECT_GT(compared, 20);  // enough groups where Dantzig's answer itself was compared
}

TEST(RigidContactResponse, InelasticResponseChangesOnlyFreeBodiesAndConservesMomentumBetweenThem) {
  const auto [model, state] = moving_pile(3, false, 4.0);
  const RigidBodies& bodies = *model.rigid_bodies;
  const auto contacts = detect_rigid_contacts(bodies, state.q);
  ASSERT_FALSE(contacts.empty());
  Vector v = state.v;
  ContactReport report;
  apply_inelastic_response(ContactSolver::kLcp, bodies, state.q, contacts, v, report);
  Vec2 before = Vec2::Zero(), after = Vec2::Zero();
  for (int b = 0; b < bodies.size(); ++b) {
    before += bodies.bodies[b].mass * state.v.segment<2>(3 * b);
    after += bodies.bodies[b].mass * v.segment<2>(3 * b);
  }
  EXPECT_LT((after - before).norm(), 1e-12 * std::max(1.0, before.norm()));
  EXPECT_LE(kinetic_energy(model, v), kinetic_energy(model, state.v) * (1 + 1e-12));
}

TEST(RigidContactResponse, ElasticReflectionsConserveKineticEnergyAndMomentum) {
  for (const ContactSolver solver : {ContactSolver::kLcp, ContactSolver::kVelocityProjection}) {
    int reflected = 0;
    for (unsigned seed = 1; seed <= 30; ++seed) {
      const auto [model, state] = moving_grid(seed);
      const RigidBodies& bodies = *model.rigid_bodies;
      const auto contacts = detect_rigid_contacts(bodies, state.q);
      Vector v = state.v;
      ContactReport report;
      apply_generalized_reflections(solver, bodies, state.q, contacts, 10000, v, report);
      const double before = kinetic_energy(model, state.v), after = kinetic_energy(model, v);
      EXPECT_NEAR(after, before, 1e-10 * before) << "seed " << seed;
      Vec2 p0 = Vec2::Zero(), p1 = Vec2::Zero();
      for (int b = 0; b < bodies.size(); ++b) {
        p0 += bodies.bodies[b].mass * state.v.segment<2>(3 * b);
        p1 += bodies.bodies[b].mass * v.segment<2>(3 * b);
      }
      EXPECT_LT((p1 - p0).norm(), 1e-10 * std::max(1.0, p0.norm())) << "seed " << seed;
      const ContactProblem end = assemble_contact_problem(ContactSolver::kVelocityProjection,
                                                          bodies, state.q, v, contacts);
      if (end.b.size() > 0) {
        EXPECT_GE(end.b.minCoeff(), kReflectionThreshold);
      }
      reflected += report.reflections > 1;
    }
    EXPECT_GT(reflected, 0);  // some scene needed more than one reflection
  }
}

TEST(RigidContactResponse, FixedBodyVelocityEntersTheLcpButNotTheProjection) {
  // A box resting on a fixed floor that declares vy = −0.5: the LCP's b counts the floor's
  // velocity (measured in the course's program), velocity projection does not.
  BodySpec floor = body(box(-5, -1, 5, 0), 0.1, true);
  floor.velocity = Vec2(0, -0.5);
  const auto [model, state] = make_rigid_model({floor, body(box(-1, 0.15, 1, 1.15))});
  const RigidBodies& bodies = *model.rigid_bodies;
  const auto contacts = detect_rigid_contacts(bodies, state.q);
  ASSERT_EQ(contacts.size(), 2u);
  const ContactProblem lcp =
      assemble_contact_problem(ContactSolver::kLcp, bodies, state.q, state.v, contacts);
  const ContactProblem vp = assemble_contact_problem(ContactSolver::kVelocityProjection, bodies,
                                                     state.q, state.v, contacts);
  // n̂ points from the floor (0) to the box (1): ġ = n̂·(v_box − v_floor) = 0.5.
  EXPECT_NEAR(lcp.b[0], 0.5, 1e-15);
  EXPECT_NEAR(vp.b[0], 0.0, 1e-15);
  // gr-lcp never ends there: the active set (free velocities) sees the box falling onto the
  // floor (at 0.1, slower than the floor's declared 0.5), the LCP sees it separating and gives
  // λ = 0, so each reflection leaves the velocity as it was. FOSSSim stops at the limit.
  Vector v = state.v;
  v[4] = -0.1;
  ContactReport report, vp_report;
  const Error error = thrown_by([&, &state = state] {
    apply_generalized_reflections(ContactSolver::kLcp, bodies, state.q, contacts, 50, v, report);
  });
  EXPECT_NE(std::string(error.what()).find("did not end after 50 reflections"), std::string::npos)
      << error.what();
  EXPECT_NE(std::string(error.what()).find("maxreflections"), std::string::npos);
  // gr-velocity-projection ignores the floor's velocity and stops the box.
  v = state.v;
  v[4] = -0.1;
  apply_generalized_reflections(ContactSolver::kVelocityProjection, bodies, state.q, contacts, 50,
                                v, vp_report);
  EXPECT_NEAR(v[4], 0.1, 1e-12);
}

TEST(RigidContactResponse, TwoFixedBodiesExactlyTouchingChangeNothing) {
  // A fixed square's corner lies exactly on a fixed floor's edge (d = 0, a NaN normal): the
  // course's lcp turns every velocity into NaN; FOSSSim leaves contacts between fixed bodies out.
  const auto [model, state] = make_rigid_model({body(box(-5, -1, 5, 0), 0.1, true),
                                                body({{0, 1}, {1, 0}, {0, -1}, {-1, 0}}, 0.1, true),
                                                body(box(3, 0.15, 4, 1.15))});
  const RigidBodies& bodies = *model.rigid_bodies;
  const auto contacts = detect_rigid_contacts(bodies, state.q);
  bool exact = false;
  for (const RigidContact& c : contacts) exact |= !has_finite_normal(c);
  EXPECT_TRUE(exact);
  for (const ContactSolver solver : {ContactSolver::kLcp, ContactSolver::kVelocityProjection}) {
    Vector v = state.v;
    v[7] = -1.0;  // the free box falls onto the floor
    ContactReport report;
    apply_inelastic_response(solver, bodies, state.q, contacts, v, report);
    EXPECT_TRUE(v.allFinite());
    EXPECT_NEAR(v[7], 0.0, 1e-12);
    EXPECT_EQ(v.head<6>(), Vector::Zero(6));
  }
}

TEST(RigidContactResponse, AFreeBodyExactlyTouchingFailsClearly) {
  const auto [model, state] = make_rigid_model(
      {body(box(-5, -1, 5, 0), 0.1, true), body({{0, 2}, {1, 1}, {0, 0}, {-1, 1}})});
  const auto contacts = detect_rigid_contacts(*model.rigid_bodies, state.q);
  Vector v = state.v;
  ContactReport report;
  const Error error = thrown_by([&, &model = model, &state = state] {
    apply_inelastic_response(ContactSolver::kVelocityProjection, *model.rigid_bodies, state.q,
                             contacts, v, report);
  });
  EXPECT_NE(std::string(error.what()).find("rigid bodies 0 and 1 touch exactly"), std::string::npos)
      << error.what();
}

}  // namespace
}  // namespace fosssim::testing

namespace fosssim::testing {
namespace {

TEST(ContactLcp, NearlyRedundantProblemsAreSolvedOrCaught) {
  // Columns that almost repeat others (by 1e-3 to 1e-6): A is definite but ill-conditioned.
  // Dantzig's method gets them (is_degenerate says no) and must end; its answer is either valid
  // or caught by the check, and the response's answer (Dantzig's or the QP's) is always valid.
  Random random(21);
  int dantzig_valid = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int dofs = 3 + random.index(6);
    const int base = 1 + random.index(dofs - 1);
    Eigen::MatrixXd N(dofs, base + random.index(dofs - base + 1));
    for (int j = 0; j < N.cols(); ++j) {
      if (j < base) {
        for (int i = 0; i < dofs; ++i) N(i, j) = random.uniform(-1, 1);
      } else {
        const double eps = std::pow(10.0, -3 - random.index(4));
        N.col(j) = N.col(random.index(base)) + eps * random.uniform_vector(dofs, -1, 1);
      }
    }
    const Vector inverse_mass = random.uniform_vector(dofs, 0.2, 3.0);
    ContactProblem problem;
    problem.J = inverse_mass.cwiseSqrt().asDiagonal() * N;
    problem.A = N.transpose() * inverse_mass.asDiagonal() * N;
    problem.b = N.transpose() * random.uniform_vector(dofs, -2, 1);
    if (is_degenerate(problem.A)) continue;
    const ContactSolveResult dantzig = solve_contact_lcp_dantzig(problem);
    dantzig_valid += dantzig.valid;
    const Vector qp = solve_contact_qp(problem, contact_qp_iteration_limit(N.cols()));
    std::string why;
    EXPECT_TRUE(check_contact_solution(problem, qp, &why)) << "trial " << trial << ": " << why;
  }
  EXPECT_GT(dantzig_valid, 100);
}

}  // namespace
}  // namespace fosssim::testing
