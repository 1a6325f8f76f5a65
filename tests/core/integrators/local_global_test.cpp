// The local/global solver (Liu et al. 2013) on systems with known answers.

#include "core/integrators/local_global.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/forces/drag_spring_force.h"
#include "core/forces/elastic_body_bending_force.h"
#include "core/forces/elastic_body_cst_force.h"
#include "core/forces/elastic_body_spring_force.h"
#include "core/integrators/implicit_euler.h"
#include "core/integrators/linearly_implicit_euler.h"
#include "core/step/simulation.h"
#include "support/scene_builder.h"

namespace fosssim {
namespace {

/// A unit mass on a spring (k = 4π², so ω = 2π; rest length 1) to a fixed particle at the
/// origin, released 0.1 m stretched along the unit direction `axis` (in dim dimensions).
constexpr double kPi = std::numbers::pi;

testing::TestScene oscillator_scene(int dim, std::string_view kind, double dt,
                                    const Eigen::Vector3d& axis) {
  std::vector<double> positions(2 * dim, 0.0);
  for (int c = 0; c < dim; ++c) positions[dim + c] = 1.1 * axis[c];
  testing::TestScene scene = testing::particles(dim, positions, 1.0, {true, false});
  scene.add_spring(0, 1, 4.0 * kPi * kPi, 1.0);
  scene.model.integrator.use(integrator_method(kind));
  scene.model.integrator.dt = dt;
  scene.model.duration = 1.0;
  return scene;
}

/// |x(1) - x_exact(1)| of the oscillator, x_exact(t) = (1 + 0.1 cos ωt) axis, after N steps.
double oscillator_error(int dim, std::string_view kind, int steps) {
  const Eigen::Vector3d axis =
      dim == 3 ? Eigen::Vector3d(1.0, 2.0, 2.0) / 3.0 : Eigen::Vector3d(0.6, 0.8, 0.0);
  Scene scene = oscillator_scene(dim, kind, 1.0 / steps, axis);
  Simulation simulation(scene.model, scene.initial);
  while (!simulation.finished()) simulation.step();
  const double amplitude = 1.0 + 0.1 * std::cos(2.0 * kPi * 1.0);
  double squared = 0.0;
  for (int c = 0; c < dim; ++c) {
    const double difference = simulation.state().q[dim + c] - amplitude * axis[c];
    squared += difference * difference;
  }
  return std::sqrt(squared);
}

TEST(LocalGlobal, SingleSpringFollowsCosOmegaTWithFirstOrderError) {
  for (int dim : {2, 3}) {
    for (std::string_view kind : {"local-global", "linearly-implicit-euler"}) {
      double previous = oscillator_error(dim, kind, 200);
      for (int steps : {400, 800, 1600}) {
        const double error = oscillator_error(dim, kind, steps);
        const double ratio = previous / error;
        EXPECT_GT(ratio, 1.8) << std::string(kind) << " " << dim << "D, " << steps << " steps";
        EXPECT_LT(ratio, 2.2) << std::string(kind) << " " << dim << "D, " << steps << " steps";
        previous = error;
      }
      EXPECT_LT(previous, 2e-3) << std::string(kind) << " " << dim << "D";
    }
  }
}

TEST(LocalGlobal, SingleSpringMatchesNewtonsImplicitEulerStepByStep) {
  // Along the spring the system is linear, so one local/global iteration is exact.
  const Eigen::Vector3d axis = Eigen::Vector3d(2.0, -1.0, 2.0) / 3.0;
  Scene lg = oscillator_scene(3, "local-global", 0.01, axis);
  lg.model.integrator.options.set("iterations", 1);
  Scene newton = oscillator_scene(3, "implicit-euler", 0.01, axis);
  Simulation a(lg.model, lg.initial), b(newton.model, newton.initial);
  for (int step = 0; step < 100; ++step) {
    a.step();
    b.step();
    ASSERT_LT((a.state().q - b.state().q).norm(), 1e-12) << "step " << step;
    ASSERT_LT((a.state().v - b.state().v).norm(), 1e-10) << "step " << step;
  }
}

TEST(LocalGlobal, SpringDampingAlongTheSpringEqualsAxialDamping) {
  // Laplacian damping -b(v_i - v_j) equals SpringForce's b (n·dv) n when dv is along n.
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, 2.0, 2.0) / 3.0;
  testing::TestScene lg = oscillator_scene(3, "local-global", 0.01, axis);
  testing::TestScene newton = oscillator_scene(3, "implicit-euler", 0.01, axis);
  for (testing::TestScene* scene : {&lg, &newton}) {
    scene->model.forces.clear();
    scene->add_spring(0, 1, 4.0 * kPi * kPi, 1.0, 1.5);
  }
  Simulation a(lg.model, lg.initial), b(newton.model, newton.initial);
  for (int step = 0; step < 100; ++step) {
    a.step();
    b.step();
  }
  EXPECT_LT((a.state().q - b.state().q).norm(), 1e-10);
  EXPECT_LT(a.state().q.segment<3>(3).norm() - 1.0, 0.1 * 0.5) << "the damping took energy out";
}

/// Three particles, one of them fixed, at rest apart from particle 2's push, under gravity.
testing::TestScene elastic_triangle(std::string_view kind, double dt) {
  testing::TestScene scene =
      testing::particles(2, {0.0, 0.0, 1.1, 0.1, 0.2, 0.9}, 1.0, {true, false, false});
  scene.initial.v << 0.0, 0.0, 0.0, 0.0, 0.5, -0.25;
  scene.model.integrator.use(integrator_method(kind));
  scene.model.integrator.dt = dt;
  scene.add_simple_gravity(testing::vec({0.0, -9.81}));
  return scene;
}

TEST(LocalGlobal, ElasticSpringsAreImplicitLikeNewtonsImplicitEuler) {
  // Two elastic springs (k = α / l0 = 50 and 40) enter the constant matrix: with iterations to
  // convergence, local/global's steps are implicit Euler's, which Newton solves exactly.
  testing::TestScene lg = elastic_triangle("local-global", 0.01);
  lg.model.integrator.options.set("iterations", 5000);
  lg.model.integrator.options.set("tolerance", 1e-15);
  testing::TestScene newton = elastic_triangle("implicit-euler", 0.01);
  for (testing::TestScene* scene : {&lg, &newton}) {
    scene->add_force(std::make_unique<ElasticBodySpringForce<2>>(0, 1, 50.0, 1.0));
    scene->add_force(std::make_unique<ElasticBodySpringForce<2>>(1, 2, 48.0, 1.2));
  }
  Simulation a(lg.model, lg.initial), b(newton.model, newton.initial);
  for (int step = 0; step < 50; ++step) {
    a.step();
    b.step();
    ASSERT_LT((a.state().q - b.state().q).lpNorm<Eigen::Infinity>(), 1e-11) << "step " << step;
    ASSERT_LT((a.state().v - b.state().v).lpNorm<Eigen::Infinity>(), 1e-9) << "step " << step;
  }
  // And the springs did work: the particles moved away from free fall.
  EXPECT_GT(std::abs(a.state().q[3] - (0.1 - 0.5 * 9.81 * 0.25)), 1e-3);
}

TEST(LocalGlobal, ElasticBendingAndTrianglesAreExplicitTerms) {
  // Declared explicit, bending and the CST enter as f(qⁿ) held through the step:
  // pⁿ⁺¹ = y + h² M⁻¹ f(qⁿ), i.e. vⁿ⁺¹ = vⁿ + h M⁻¹ f(qⁿ), qⁿ⁺¹ = qⁿ + h vⁿ⁺¹: symplectic
  // Euler's step, up to the rounding of the global solve.
  testing::TestScene lg = elastic_triangle("local-global", 0.01);
  testing::TestScene symplectic = elastic_triangle("symplectic-euler", 0.01);
  for (testing::TestScene* scene : {&lg, &symplectic}) {
    scene->add_force(std::make_unique<ElasticBodyBendingForce>(0, 1, 2, 3.0, 0.5, 2.3));
    scene->add_force(std::make_unique<ElasticBodyCstForce<2>>(
        std::array<int, 3>{0, 1, 2}, 20.0, 0.3,
        compute_cst_rest<2>(Vec<2>(0, 0), Vec<2>(1, 0), Vec<2>(0, 1))));
  }
  Simulation a(lg.model, lg.initial), b(symplectic.model, symplectic.initial);
  for (int step = 0; step < 50; ++step) {
    a.step();
    b.step();
    ASSERT_LT((a.state().q - b.state().q).lpNorm<Eigen::Infinity>(), 1e-13) << "step " << step;
    ASSERT_LT((a.state().v - b.state().v).lpNorm<Eigen::Infinity>(), 1e-11) << "step " << step;
  }
  EXPECT_GT((a.state().v - lg.initial.v).norm(), 0.1);
}

TEST(LocalGlobal, GravityAloneIsExact) {
  testing::TestScene scene = testing::particles(2, {0.0, 0.0, 1.0, 0.0}, 2.0, {false, false});
  scene.initial.v << 1.0, 3.0, -1.0, 0.0;
  scene.add_simple_gravity(testing::vec({0.0, -9.8}));
  scene.model.integrator.use(integrator_method("local-global"));
  scene.model.integrator.dt = 0.05;
  Simulation simulation(scene.model, scene.initial);
  Vector q = scene.initial.q, v = scene.initial.v;
  for (int step = 0; step < 20; ++step) {
    simulation.step();
    v[1] -= 0.05 * 9.8;
    v[3] -= 0.05 * 9.8;
    q += 0.05 * v;
  }
  EXPECT_LT((simulation.state().q - q).norm(), 1e-12);
  EXPECT_LT((simulation.state().v - v).norm(), 1e-12);
}

TEST(LocalGlobal, EliminatedPinsStayExactlyAtRestAndMovingOnesMoveExactly) {
  Scene scene = testing::cloth(6, 50.0, "local-global", 1.0 / 30.0);
  scene.initial.v.segment<3>(0) << 0.25, 0.0, -0.125;  // pinned corner 0 moves on its own
  Simulation simulation(scene.model, scene.initial);
  for (int step = 0; step < 60; ++step) simulation.step();
  const State& state = simulation.state();
  EXPECT_EQ(state.q.segment<3>(15), scene.initial.q.segment<3>(15));  // corner 5, at rest
  EXPECT_EQ(state.v.segment<3>(0), scene.initial.v.segment<3>(0));
  Eigen::Vector3d expected = scene.initial.q.segment<3>(0);
  for (int step = 0; step < 60; ++step) expected += (1.0 / 30.0) * scene.initial.v.segment<3>(0);
  EXPECT_EQ(state.q.segment<3>(0), expected);
  double lowest = 0.0;
  for (int p = 0; p < 36; ++p) lowest = std::min(lowest, state.q[3 * p + 1]);
  EXPECT_LT(lowest, -0.3) << "the free cloth fell";
}

TEST(LocalGlobal, PenaltyPinsStayWithin1e8OfRest) {
  Scene scene = testing::cloth(8, 50.0, "local-global", 1.0 / 30.0);
  scene.model.integrator.options.set("pins", "penalty");
  Simulation simulation(scene.model, scene.initial);
  double worst = 0.0;
  for (int step = 0; step < 100; ++step) {
    simulation.step();
    for (int p : {0, 7}) {
      worst = std::max(
          worst,
          (simulation.state().q.segment<3>(3 * p) - scene.initial.q.segment<3>(3 * p)).norm());
    }
  }
  EXPECT_LT(worst, 1e-8);
  EXPECT_GT(worst, 0.0) << "a penalty holds only approximately";
}

TEST(LocalGlobal, PenaltyPinnedParticlesReceiveTheirForces) {
  // One particle pinned by a soft penalty w, under gravity: Q = m/h² + w, and one step from
  // rest at the anchor a gives p = a + m g/(m/h² + w); eliminated, it does not move.
  const double m = 2.0, h = 0.1, w = 50.0, g = 9.8;
  for (const char* pins : {"penalty", "elimination"}) {
    testing::TestScene scene = testing::particles(3, {0.5, 1.0, -0.5}, m, {true});
    scene.add_simple_gravity(testing::vec({0.0, -g, 0.0}));
    scene.model.integrator.use(integrator_method("local-global"));
    scene.model.integrator.dt = h;
    scene.model.integrator.options.set("pins", pins);
    scene.model.integrator.options.set("penalty", w);
    Simulation simulation(scene.model, scene.initial);
    simulation.step();
    const double sag = std::string_view(pins) == "penalty" ? m * g / (m / (h * h) + w) : 0.0;
    EXPECT_NEAR(simulation.state().q[1], 1.0 - sag, 1e-15) << pins;
    EXPECT_NEAR(simulation.state().q[0], 0.5, 1e-15) << pins;
  }
}

/// Two unit masses joined by a spring at rest along x (k, length 1), moving apart along y
/// with speed u each, integrated by local/global with one iteration from `start`.
Scene parting_pair(const char* start, double k, double u, double h) {
  testing::TestScene scene =
      testing::particles(3, {0.0, 0.0, 0.0, 1.0, 0.0, 0.0}, 1.0, {false, false});
  scene.initial.v << 0.0, u, 0.0, 0.0, -u, 0.0;
  scene.add_spring(0, 1, k, 1.0);
  scene.model.integrator.use(integrator_method("local-global"));
  scene.model.integrator.dt = h;
  scene.model.integrator.options.set("iterations", 1);
  scene.model.integrator.options.set("start", start);
  return scene;
}

TEST(LocalGlobal, OneIterationFromTheCurrentPositionsIsTheHandComputedSolve) {
  // From pⁿ the local step finds the springs at rest, d = pⁿ_0 - pⁿ_1, so the global step
  // solves (M/h² + k AᵀA)(p - pⁿ) = M vⁿ/h: each particle moves by u h/(1 + 2 k h²) along y.
  const double k = 30.0, u = 0.7, h = 0.05;
  Scene scene = parting_pair("current", k, u, h);
  Simulation current(scene.model, scene.initial);
  current.step();
  const double shift = u * h / (1.0 + 2.0 * k * h * h);
  const Vector expected = (Vector(6) << 0.0, shift, 0.0, 1.0, -shift, 0.0).finished();
  EXPECT_LT((current.state().q - expected).lpNorm<Eigen::Infinity>(), 1e-15);
  // From y = pⁿ + h vⁿ the spring is found stretched and rotated: a different answer.
  Scene other = parting_pair("inertial", k, u, h);
  Simulation inertial(other.model, other.initial);
  inertial.step();
  EXPECT_GT((inertial.state().q - expected).lpNorm<Eigen::Infinity>(), 1e-4);
}

TEST(LocalGlobal, BothStartsAgreeAtRestAndOnceConverged) {
  std::vector<Vector> at_rest, converged;
  for (const char* start : {"inertial", "current"}) {
    Scene scene = testing::cloth(5, 40.0, "local-global", 1.0 / 30.0);
    scene.model.integrator.options.set("start", start);
    Simulation simulation(scene.model, scene.initial);
    simulation.step();  // vⁿ = 0: y = pⁿ, the same start
    at_rest.push_back(simulation.state().q);
    scene.model.integrator.options.set("iterations", 100000);
    scene.model.integrator.options.set("tolerance", 1e-14);
    Simulation exact(scene.model, simulation.state());
    for (int step = 0; step < 10; ++step) exact.step();
    converged.push_back(exact.state().q);
  }
  EXPECT_EQ(at_rest[0], at_rest[1]);
  EXPECT_LT((converged[0] - converged[1]).lpNorm<Eigen::Infinity>(), 1e-11);
  Scene few = testing::cloth(5, 40.0, "local-global", 1.0 / 30.0);
  few.model.integrator.options.set("iterations", 3);
  State moving = few.initial;
  moving.v.setConstant(0.5);
  std::vector<Vector> starts;
  for (const char* start : {"inertial", "current"}) {
    few.model.integrator.options.set("start", start);
    Simulation simulation(few.model, moving);
    simulation.step();
    starts.push_back(simulation.state().q);
  }
  EXPECT_GT((starts[0] - starts[1]).lpNorm<Eigen::Infinity>(), 1e-6) << "3 iterations differ";
}

TEST(LocalGlobal, DenseAndSparseFactorizationsAgree) {
  std::vector<Vector> finals;
  for (const char* solver : {"dense", "sparse", "auto"}) {
    Scene scene = testing::cloth(5, 30.0, "local-global", 1.0 / 30.0);
    scene.model.integrator.options.set("solver", solver);
    const auto integrator = testing::bound_integrator<LocalGlobal<3>>(scene.model);
    State state = scene.initial;
    for (int step = 0; step < 30; ++step) integrator->step(state);
    EXPECT_EQ(integrator->solver_method(), std::string_view(solver) == "sparse"
                                               ? SpdSolver::Method::kSparse
                                               : SpdSolver::Method::kDense);
    finals.push_back(state.q);
  }
  EXPECT_LT((finals[0] - finals[1]).norm(), 1e-12);
  EXPECT_EQ(finals[0], finals[2]) << "23 free particles are solved densely under auto";
}

TEST(LocalGlobal, ToleranceEndsTheIterationsEarly) {
  Scene scene = testing::cloth(6, 30.0, "local-global", 1.0 / 30.0);
  scene.model.integrator.options.set("iterations", 10000);
  scene.model.integrator.options.set("tolerance", 1e-10);
  const auto integrator = testing::bound_integrator<LocalGlobal<3>>(scene.model);
  State state = scene.initial;
  for (int step = 0; step < 5; ++step) {
    integrator->step(state);
    EXPECT_LE(integrator->last_change(), 1e-10);
    EXPECT_LT(integrator->last_iterations(), 10000);
    EXPECT_GT(integrator->last_iterations(), 1);
  }
}

TEST(LocalGlobal, FactorsInPrecomputeAndAgainOnlyWhenAnchorsChange) {
  Scene scene = testing::cloth(6, 30.0, "local-global", 1.0 / 30.0);
  DragSpringForce drag(3);
  const auto integrator = testing::bound_integrator<LocalGlobal<3>>(scene.model, {&drag});
  EXPECT_EQ(integrator->factorizations(), 1) << "precompute factors Q";
  State state = scene.initial;
  for (int step = 0; step < 10; ++step) integrator->step(state);
  EXPECT_EQ(integrator->factorizations(), 1);
  drag.grab(20, Eigen::Vector3d(0.0, 0.5, 0.5), 40.0);
  integrator->step(state);
  EXPECT_EQ(integrator->factorizations(), 2);
  drag.move_target(Eigen::Vector3d(0.1, 0.5, 0.5));  // only the right-hand side changes
  integrator->step(state);
  EXPECT_EQ(integrator->factorizations(), 2);
  drag.release();
  integrator->step(state);
  EXPECT_EQ(integrator->factorizations(), 3);
  scene.model.integrator.dt = 0.01;  // a bound model must not change
  EXPECT_THROW(integrator->step(state), std::logic_error);
}

TEST(LocalGlobal, DraggingConvergesToNewtonWithTheSameDragSpring) {
  std::vector<Vector> finals;
  for (std::string_view kind : {"local-global", "implicit-euler"}) {
    Scene scene = testing::cloth(4, 10.0, kind, 1.0 / 30.0);
    if (scene.model.integrator.options.has("iterations")) {
      scene.model.integrator.options.set("iterations", 20000);
      scene.model.integrator.options.set("tolerance", 1e-13);
    }
    DragSpringForce drag(3);
    drag.grab(14, Eigen::Vector3d(0.2, 0.4, 0.6), 5.0);
    StepAdditions additions;
    additions.interaction_forces = {&drag};
    Simulation simulation(scene.model, scene.initial, std::move(additions));
    for (int step = 0; step < 15; ++step) simulation.step();
    finals.push_back(simulation.state().q);
  }
  EXPECT_LT((finals[0] - finals[1]).lpNorm<Eigen::Infinity>(), 1e-9);
}

}  // namespace
}  // namespace fosssim
