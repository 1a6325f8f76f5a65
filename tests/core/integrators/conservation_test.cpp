// Energy and momentum behaviour of every integrator of the registry, in 2D and 3D, as its
// properties declare (IntegratorProperties::energy).
//
// Math checked:
// - Kepler orbit (eccentricity 0.5, around a fixed sun, 100 periods, h = P/2000). Symplectic
//   Euler (kick with F(qⁿ), then drift with vⁿ⁺¹) is the flow of the splitting e^{hT} e^{hU},
//   which exactly conserves a modified energy H̃ = H - (h/2) v·F + O(h²). With the start at
//   perihelion, where v·F = 0, |H(t) - H(0)| ≤ (h/2) max|v·F| + O(h²), and on the orbit
//   |v·F| = G M m |ṙ|/r² with r = p/(1 + e cos θ), ṙ = √(GM/p) e sin θ, whose maximum is taken
//   over θ below. The relative oscillation stays under that bound (+10% for the O(h²) part),
//   equally in the first and the last period: every method declared kBounded is held to it.
//   Explicit Euler's energy (every kGrows method's), sampled each time the planet crosses the
//   perihelion direction, rises at every crossing; for a first-order method, far beyond the
//   bound.
// - Every kDecays method dissipates on undamped springs: for a quadratic potential ½ qᵀK q
//   (zero-rest-length springs, a fixed anchor) backward Euler gives
//   E' - E = -½ ΔvᵀMΔv - ½ ΔqᵀKΔq < 0 at every step, and implicit, linearized implicit and
//   linearly implicit Euler are backward Euler on linear systems, as is local/global (its local
//   step is exact for zero rest length); implicit Euler also on a nonlinear spring moving
//   radially (U convex in l).
// - Momentum: with pair forces only (springs with and without damping, Newtonian gravity,
//   vortices) and no fixed particle, Σ F = 0 and the pair pattern makes every column of hessX
//   and hessV sum to zero per coordinate, so 1ᵀA δv = 1ᵀM δv = 1ᵀ rhs = 0; local/global's
//   matrix M/h² + AᵀKA has the same column sums, so Σ m p = Σ m y: every method keeps Σ m v
//   constant to round-off (1e-13 of max m|v|; for local/global, whose velocities are position
//   differences, plus ε Σ m|q|/h per step).
// - The same for a free elastic body of Theme 4's forces (elastic springs, constant strain
//   triangles, and in 2D a bending hinge), every one invariant under translations and rotations:
//   each force's gradient sums to zero over its particles and its hessX's columns sum to zero
//   per coordinate, so every method keeps Σ m v (while the forces change the velocities by more
//   than 0.05, so they are not ignored); and symplectic Euler, whose kick uses F(qⁿ) and
//   whose drift is along vⁿ⁺¹, keeps the angular momentum Σ m x × v exactly, since a rotation-
//   invariant energy exerts no torque: Lⁿ⁺¹ - Lⁿ = h Σ xⁿ × F(xⁿ) = 0.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "core/analysis/energy.h"
#include "core/forces/elastic_body_bending_force.h"
#include "core/forces/elastic_body_cst_force.h"
#include "core/forces/elastic_body_spring_force.h"
#include "core/forces/vortex_force.h"
#include "support/closed_forms.h"
#include "support/random.h"
#include "support/scene_builder.h"
#include "support/typed_tests.h"

namespace fosssim::testing {
namespace {

FOSSSIM_TEST_SUITE_IN_2D_AND_3D(ConservationTest);

double total_energy(const TestScene& scene) {
  return compute_energies(scene.model, scene.initial).total();
}

/// A planet of mass m = 1 at perihelion r_p = a(1 - e) of an orbit with a = 1, e = 0.5 around a
/// fixed sun M = 1, G = 1: v_p = √(GM(1 + e)/(a(1 - e))) = √3, E = -GMm/(2a) = -0.5, P = 2π.
template <int D>
TestScene kepler(std::string_view kind, double h) {
  const auto [e1, e2] = plane_axes<D>();
  TestScene scene(D, kind, h);
  scene.add_particle(1.0, Vector::Zero(D), Vector::Zero(D), /*fixed=*/true);
  scene.add_particle(1.0, 0.5 * e1, std::sqrt(3.0) * e2);
  scene.add_gravitation(0, 1, 1.0);
  return scene;
}

constexpr int kPerPeriod = 2000, kPeriods = 100;

/// The bound on the relative energy oscillation of a first-order symplectic splitting on the
/// Kepler orbit (see the top of this file), with 10% for the O(h²) part.
double kepler_energy_bound(double h) {
  // max |v·F| = GMm √(GM/p) e max_θ |sin θ| (1 + e cos θ)² / p², p = a(1 - e²) = 0.75.
  const double p = 0.75, e = 0.5;
  double shape = 0.0;
  for (int i = 0; i < 100000; ++i) {
    const double theta = 2.0 * std::numbers::pi * i / 100000;
    shape = std::max(shape, std::abs(std::sin(theta)) * std::pow(1.0 + e * std::cos(theta), 2));
  }
  return 1.1 * 0.5 * h * std::sqrt(1.0 / p) * e * shape / (p * p) / 0.5;
}

/// A method whose energy is bounded: the oscillation stays under the bound and does not grow.
template <int D>
void expect_bounded_kepler_energy(std::string_view method, double h) {
  const double bound = kepler_energy_bound(h);
  TestScene scene = kepler<D>(method, h);
  const double e0 = total_energy(scene);
  ASSERT_NEAR(e0, -0.5, 1e-15);
  auto integrator = make_integrator(scene.model);
  double first = 0.0, last = 0.0, worst = 0.0;
  for (int k = 0; k < kPeriods; ++k) {
    double in_period = 0.0;
    for (int i = 0; i < kPerPeriod; ++i) {
      integrator->step(scene.initial);
      in_period = std::max(in_period, std::abs(total_energy(scene) - e0) / 0.5);
    }
    if (k == 0) first = in_period;
    last = in_period;
    worst = std::max(worst, in_period);
  }
  std::printf(
      "%dD Kepler, 100 periods, %s: relative energy oscillation %.4e (bound %.4e), first "
      "period %.4e, last %.4e\n",
      D, std::string(method).c_str(), worst, bound, first, last);
  EXPECT_LE(worst, bound) << method;
  EXPECT_NEAR(last, first, 0.01 * first) << method << ": the oscillation does not grow";
}

/// A method whose energy grows: sampled each time the planet crosses the perihelion
/// direction, it rises at every crossing (for a first-order method, far beyond the symplectic
/// bound).
template <int D>
void expect_growing_kepler_energy(std::string_view method, double h) {
  TestScene scene = kepler<D>(method, h);
  const double e0 = total_energy(scene);
  auto integrator = make_integrator(scene.model);
  std::vector<double> at_perihelion_direction;
  const Vector e1 = plane_axes<D>().first, e2 = plane_axes<D>().second;
  double previous_y = 0.0;
  for (int i = 0; i < kPeriods * kPerPeriod; ++i) {
    integrator->step(scene.initial);
    const Vector x = scene.initial.q.tail(D);
    const double y = x.dot(e2);
    if (previous_y < 0.0 && y >= 0.0 && x.dot(e1) > 0.0) {
      at_perihelion_direction.push_back(total_energy(scene));
    }
    previous_y = y;
  }
  ASSERT_GE(at_perihelion_direction.size(), 10u) << method;
  for (size_t k = 1; k < at_perihelion_direction.size(); ++k) {
    EXPECT_GT(at_perihelion_direction[k], at_perihelion_direction[k - 1])
        << method << ", revolution " << k;
  }
  const double drift = (at_perihelion_direction.back() - e0) / 0.5;
  std::printf("%dD Kepler, %s: energy up by %.3e of |E| over %zu revolutions\n", D,
              std::string(method).c_str(), drift, at_perihelion_direction.size());
  EXPECT_GT(drift, 0.0) << method;
  // A first-order method gains O(h) per revolution, so after 100 it is far beyond the
  // symplectic method's O(h) oscillation; higher orders gain less and are only held to rising.
  if (integrator_method(method).properties.order == 1) {
    EXPECT_GT(drift, 100.0 * kepler_energy_bound(h)) << method;
  }
}

TYPED_TEST(ConservationTest, KeplerEnergyIsBoundedOrGrowsAsEachMethodDeclares) {
  constexpr int D = TypeParam::value;
  const double h = 2.0 * std::numbers::pi / kPerPeriod;
  int checked = 0;
  for (const IntegratorMethod* method : all_integrators()) {
    if (method->properties.energy == EnergyTrend::kBounded) {
      expect_bounded_kepler_energy<D>(method->name, h);
    } else if (method->properties.energy == EnergyTrend::kGrows) {
      expect_growing_kepler_energy<D>(method->name, h);
    } else {
      continue;  // decaying methods: DecayingMethodsDissipateEnergyOnUndampedSprings
    }
    ++checked;
  }
  EXPECT_GE(checked, 2) << "explicit and symplectic Euler";
}

/// A chain: fixed anchor 0 at the origin, free particles 1 and 2, zero-rest-length springs.
template <int D>
TestScene quadratic_chain(std::string_view kind) {
  Random random(141);
  TestScene scene(D, kind, 0.05);
  scene.add_particle(1.0, Vector::Zero(D), Vector::Zero(D), /*fixed=*/true);
  scene.add_particle(0.7, random.uniform_vector(D, -1.0, 1.0), random.uniform_vector(D, -1.0, 1.0));
  scene.add_particle(1.3, random.uniform_vector(D, -1.0, 1.0), random.uniform_vector(D, -1.0, 1.0));
  scene.add_spring(0, 1, 30.0, 0.0);
  scene.add_spring(1, 2, 50.0, 0.0);
  return scene;
}

/// Runs `steps` steps and expects the total energy to fall at every one, and by 10% overall.
void expect_monotone_dissipation(TestScene scene, int steps, const char* what) {
  auto integrator = make_integrator(scene.model);
  const double start = total_energy(scene);
  double previous = start;
  for (int s = 0; s < steps; ++s) {
    integrator->step(scene.initial);
    const double energy = total_energy(scene);
    EXPECT_LT(energy, previous) << what << ", step " << s + 1;
    previous = energy;
  }
  EXPECT_LT(previous, 0.9 * start) << what;
}

TYPED_TEST(ConservationTest, DecayingMethodsDissipateEnergyOnUndampedSprings) {
  constexpr int D = TypeParam::value;
  int checked = 0;
  for (const IntegratorMethod* method : all_integrators()) {
    if (method->properties.energy != EnergyTrend::kDecays) continue;
    expect_monotone_dissipation(quadratic_chain<D>(method->name), 200,
                                (std::string(method->name) + ", zero-rest-length chain").c_str());
    ++checked;
  }
  EXPECT_GE(checked, 4) << "implicit, linearized implicit, local/global, linearly implicit";
  // A nonlinear spring (l0 = 1) oscillating along its own line between l = 0.6 and 1.4.
  const Vector axis = plane_axes<D>().first;
  TestScene radial(D, "implicit-euler", 0.05);
  radial.add_particle(1.0, Vector::Zero(D), Vector::Zero(D), /*fixed=*/true);
  radial.add_particle(1.0, 1.4 * axis, Vector::Zero(D));
  radial.add_spring(0, 1, 40.0, 1.0);
  expect_monotone_dissipation(std::move(radial), 200, "implicit Euler, radial spring");
}

/// Five free particles joined by pair forces only: springs (one damped), Newtonian gravity and a
/// vortex, with unequal masses, spread on a circle with random velocities. (Particles that
/// collide under Newtonian gravity or a vortex meet a singularity, where Newton's method rightly
/// fails; the test checks that those pairs stay 0.1 apart.)
template <int D>
TestScene pair_forces_only(std::string_view kind) {
  Random random(142);
  const auto [e1, e2] = plane_axes<D>();
  TestScene scene(D, kind, 0.01);
  for (int p = 0; p < 5; ++p) {
    const double angle = 2.0 * std::numbers::pi * p / 5.0;
    Vector x = std::cos(angle) * e1 + std::sin(angle) * e2;
    if constexpr (D == 3) x += random.uniform(-0.3, 0.3) * Vector::Ones(3);
    scene.add_particle(random.uniform(0.5, 2.0), x, random.uniform_vector(D, -0.5, 0.5));
  }
  scene.add_spring(0, 1, 20.0, 1.0);
  scene.add_spring(1, 2, 10.0, 1.2, 0.5);
  scene.add_spring(2, 3, 15.0, 1.1);
  scene.add_spring(3, 4, 25.0, 1.2);
  scene.add_gravitation(0, 1, 0.5);  // on springs, which keep the pairs apart
  scene.add_gravitation(3, 4, 0.5);
  scene.add_force(
      std::make_unique<VortexForce<D>>(4, 0, 0.8, 0.3, vortex_rotation<D>(Vec<3>(0.0, 0.6, 0.8))));
  return scene;
}

/// The momentum drift allowed after `steps` steps of `method` on `scene` (its final state):
/// round-off of 1e-13 of the largest momentum `scale` (max m|v|), and, where velocities are
/// position differences, ε Σ m|q| / h more per step.
template <int D>
double momentum_drift_bound(const TestScene& scene, const IntegratorMethod& method, double scale,
                            int steps) {
  double bound = 1e-13 * scale;
  if (method.properties.velocity_from_positions) {
    double mq = 0.0;
    for (int p = 0; p < scene.model.num_particles(); ++p) {
      mq += scene.model.mass[D * p] * scene.initial.q.segment(D * p, D).norm();
    }
    bound += steps * std::numeric_limits<double>::epsilon() * mq / scene.model.integrator.dt;
  }
  return bound;
}

TYPED_TEST(ConservationTest, PairForcesConserveMomentumWithEveryMethod) {
  constexpr int D = TypeParam::value;
  for (const IntegratorMethod* method : all_integrators()) {
    const std::string_view kind = method->name;
    TestScene scene = pair_forces_only<D>(kind);
    const Vector start = linear_momentum(scene.model, scene.initial.v);
    double scale = 0.0;  // max m|v|: the size of the terms that cancel
    auto integrator = make_integrator(scene.model);
    for (int s = 0; s < 300; ++s) {
      integrator->step(scene.initial);
      for (const auto& [i, j] : {std::pair{0, 1}, std::pair{3, 4}, std::pair{4, 0}}) {
        const Vector d = scene.initial.q.segment(D * j, D) - scene.initial.q.segment(D * i, D);
        ASSERT_GT(d.norm(), 0.1) << std::string(kind) << ", step " << s;
      }
      for (int p = 0; p < 5; ++p) {
        scale = std::max(scale, scene.model.mass[D * p] * scene.initial.v.segment(D * p, D).norm());
      }
    }
    const double drift = (linear_momentum(scene.model, scene.initial.v) - start).norm();
    const double bound = momentum_drift_bound<D>(scene, *method, scale, 300);
    EXPECT_LE(drift, bound) << std::string(kind) << ": momentum drift " << drift;
    std::printf("%dD %-26s momentum drift after 300 steps %.2e (max m|v| %.2f)\n", D,
                std::string(kind).c_str(), drift, scale);
  }
}

/// A free elastic body: four particles of unequal masses on a square (tilted out of every
/// coordinate plane in 3D, and bent out of it a little), two constant strain triangles whose rest
/// shapes are other than the start, four elastic springs with other rest lengths and, in 2D, a
/// bending hinge; random velocities (off the plane in 3D).
template <int D>
TestScene free_elastic_body(std::string_view kind) {
  Random random(143);
  // Named copies, not a structured binding: lambdas capture them (clang 14 cannot capture
  // structured bindings).
  const auto axes = plane_axes<D>();
  const Vector e1 = axes.first, e2 = axes.second;
  TestScene scene(D, kind, 0.002);
  const double corners[4][2] = {{0, 0}, {1, 0}, {1.1, 0.9}, {-0.1, 1}};
  for (int p = 0; p < 4; ++p) {
    Vector x = corners[p][0] * e1 + corners[p][1] * e2;
    if constexpr (D == 3) x += random.uniform(-0.1, 0.1) * Vector::Ones(3);
    scene.add_particle(random.uniform(0.5, 2.0), x, random.uniform_vector(D, -0.5, 0.5));
  }
  const auto rest = [&](double ax, double ay, double bx, double by, double cx, double cy) {
    return compute_cst_rest<D>(Vec<D>(ax * e1 + ay * e2), Vec<D>(bx * e1 + by * e2),
                               Vec<D>(cx * e1 + cy * e2));
  };
  scene.add_force(std::make_unique<ElasticBodyCstForce<D>>(std::array<int, 3>{0, 1, 2}, 30.0, 0.3,
                                                           rest(0, 0, 0.9, 0, 1, 1)));
  scene.add_force(std::make_unique<ElasticBodyCstForce<D>>(std::array<int, 3>{0, 2, 3}, 20.0, 0.45,
                                                           rest(0, 0, 1, 1.1, 0, 1)));
  for (int p = 0; p < 4; ++p) {
    scene.add_force(std::make_unique<ElasticBodySpringForce<D>>(p, (p + 1) % 4, 8.0, 0.9));
  }
  if constexpr (D == 2) {
    scene.add_force(std::make_unique<ElasticBodyBendingForce>(0, 1, 2, 0.5, 1.2, 2.0));
  }
  return scene;
}

/// Σ m x × v: one number in 2D, a vector in 3D.
template <int D>
Vector angular_momentum(const TestScene& scene) {
  Vector L = Vector::Zero(D == 2 ? 1 : 3);
  for (int p = 0; p < scene.model.num_particles(); ++p) {
    const Vector x = scene.initial.q.segment(D * p, D);
    const Vector mv = scene.model.mass[D * p] * scene.initial.v.segment(D * p, D);
    if constexpr (D == 2) {
      L[0] += x[0] * mv[1] - x[1] * mv[0];
    } else {
      L += Vec<3>(x).cross(Vec<3>(mv));
    }
  }
  return L;
}

TYPED_TEST(ConservationTest, ElasticBodyForcesConserveMomentumWithEveryMethod) {
  constexpr int D = TypeParam::value;
  for (const IntegratorMethod* method : all_integrators()) {
    const std::string_view kind = method->name;
    TestScene scene = free_elastic_body<D>(kind);
    const Vector start = linear_momentum(scene.model, scene.initial.v);
    const Vector start_angular = angular_momentum<D>(scene);
    const double start_potential = compute_energies(scene.model, scene.initial).potential;
    double scale = 0.0;          // max m|v|: the size of the terms that cancel
    double angular_scale = 0.0;  // max Σ m|x||v|
    double potential_change = 0.0;  // the body does deform: its elastic energy moves
    double velocity_change = 0.0;   // and the forces act: velocities change
    const Vector start_velocity = scene.initial.v;
    auto integrator = make_integrator(scene.model);
    for (int s = 0; s < 300; ++s) {
      integrator->step(scene.initial);
      ASSERT_TRUE(scene.initial.q.allFinite() && scene.initial.v.allFinite())
          << std::string(kind) << ", step " << s;
      double moment = 0.0;
      for (int p = 0; p < 4; ++p) {
        const double mv = scene.model.mass[D * p] * scene.initial.v.segment(D * p, D).norm();
        scale = std::max(scale, mv);
        moment += mv * scene.initial.q.segment(D * p, D).norm();
      }
      angular_scale = std::max(angular_scale, moment);
      potential_change = std::max(
          potential_change,
          std::abs(compute_energies(scene.model, scene.initial).potential - start_potential));
      velocity_change =
          std::max(velocity_change, (scene.initial.v - start_velocity).lpNorm<Eigen::Infinity>());
    }
    EXPECT_GT(potential_change, 1e-3) << std::string(kind);
    EXPECT_GT(velocity_change, 0.05) << std::string(kind);
    const double drift = (linear_momentum(scene.model, scene.initial.v) - start).norm();
    const double bound = momentum_drift_bound<D>(scene, *method, scale, 300);
    EXPECT_LE(drift, bound) << std::string(kind) << ": momentum drift " << drift;
    if (kind == "symplectic-euler") {
      const double turn = (angular_momentum<D>(scene) - start_angular).norm();
      EXPECT_LE(turn, 300 * 1e-15 * angular_scale) << "angular momentum drift " << turn;
    }
    std::printf(
        "%dD %-26s elastic body: momentum drift after 300 steps %.2e (max m|v| %.2f, max |Δv| "
        "%.2f)\n",
        D, std::string(kind).c_str(), drift, scale, velocity_change);
  }
}

}  // namespace
}  // namespace fosssim::testing
