// The run summary (outputs/run_summary.h, docs/command-line.md 'Run summaries'): energy drift of
// a hand-computed run, collisions and solver iterations counted as each step reported them,
// counts taken from the initial state on, and the same bytes outside "timings" run after run.

#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>

#include "core/step/simulation.h"
#include "io/scene_loader.h"
#include "outputs/run_summary.h"

namespace fosssim {
namespace {

using Json = nlohmann::ordered_json;  // keeps the file's key order

// One particle of mass 2 thrown at (3, 4) m/s under g = (0, -8), 8 steps of explicit Euler
// with h = 1/8 (exact in binary). Each step changes the kinetic energy by m v_y h g_y +
// m h² g² / 2 and the potential by -m g_y h v_y, so the total grows by m h² g² / 2 = 1 J a step:
// E_k = E_0 + k with E_0 = 1/2 · 2 · 25 + 2 · 8 · 1 = 41.
constexpr const char* kProjectile = R"(<scene>
  <duration time="1"/>
  <integrator type="explicit-euler" dt="0.125"/>
  <particle m="2" px="0" py="1" vx="3" vy="4" fixed="0"/>
  <simplegravity fx="0" fy="-8"/>
</scene>)";

// A ball dropped onto a half-plane with simple collision handling: it bounces on the floor.
constexpr const char* kBouncing = R"(<scene>
  <duration time="2"/>
  <integrator type="symplectic-euler" dt="0.01"/>
  <particle m="1" px="0" py="1" vx="0.5" vy="0" fixed="0" radius="0.1"/>
  <halfplane px="0" py="0" nx="0" ny="1"/>
  <simplegravity fx="0" fy="-9.81"/>
  <collision type="simple" COR="0.9"/>
</scene>)";

// Two particles on a stiff spring under implicit Euler: Newton iterates every step.
constexpr const char* kStiffSpring = R"(<scene>
  <duration time="0.5"/>
  <integrator type="implicit-euler" dt="0.05"/>
  <particle m="1" px="0" py="0" vx="0" vy="0" fixed="1"/>
  <particle m="1" px="1.5" py="0" vx="0" vy="2" fixed="0"/>
  <edge i="0" j="1"/>
  <springforce edge="0" k="1000" l0="1"/>
</scene>)";

struct Totals {
  std::int64_t collisions = 0, max_collisions = 0, colliding_steps = 0;
  std::int64_t iterations = 0;
  int max_iterations = 0;
};

/// Runs the scene to its end feeding a summary, and totals by hand what each step reported.
Json run(const Scene& scene, Totals* totals = nullptr) {
  RunSummary summary(scene);
  Simulation simulation(scene.model, scene.initial);
  summary.add(simulation.state(), nullptr, &simulation.integrator());
  while (!simulation.finished()) {
    simulation.step();
    summary.add(simulation.state(), &simulation.last_record(), &simulation.integrator());
    if (totals == nullptr) continue;
    const auto n = static_cast<std::int64_t>(simulation.last_record().collisions.size());
    totals->collisions += n;
    totals->max_collisions = std::max(totals->max_collisions, n);
    totals->colliding_steps += n > 0 ? 1 : 0;
    const int iterations = simulation.integrator().solver_report().last_step_iterations;
    totals->iterations += iterations;
    totals->max_iterations = std::max(totals->max_iterations, iterations);
  }
  EXPECT_EQ(summary.steps(), scene.model.num_steps());
  return Json::parse(summary.json());
}

TEST(RunSummary, EnergyDriftOfAHandComputedRun) {
  const Json s = run(load_scene_text(kProjectile, "projectile.xml"));
  EXPECT_EQ(s["schema"], "fosssim-run-stats");
  EXPECT_EQ(s["version"], RunSummary::kSchemaVersion);
  EXPECT_EQ(s["scene"], "projectile.xml");
  EXPECT_EQ(s["steps"], 8);
  EXPECT_EQ(s["time"]["end"].get<double>(), 1.0);
  const Json& e = s["energy"];
  EXPECT_EQ(e["initial"].get<double>(), 41.0);
  EXPECT_EQ(e["final"].get<double>(), 49.0);
  EXPECT_EQ(e["min"].get<double>(), 41.0);
  EXPECT_EQ(e["max"].get<double>(), 49.0);
  EXPECT_EQ(e["drift"].get<double>(), 8.0);
  EXPECT_EQ(e["max_drift"].get<double>(), 8.0);
  EXPECT_EQ(e["relative_drift"].get<double>(), 8.0 / 41.0);
  EXPECT_EQ(e["max_relative_drift"].get<double>(), 8.0 / 41.0);
  EXPECT_EQ(e["normalized_drift"].get<double>(), 8.0 / 41.0);
  EXPECT_EQ(e["max_normalized_drift"].get<double>(), 8.0 / 41.0);
  EXPECT_EQ(e["normalized_by"], "initial");
  EXPECT_TRUE(s["solver"]["iterations"].is_null()) << "explicit Euler does not iterate";
  EXPECT_TRUE(s["solver"]["linear_solves"].is_null());
  EXPECT_EQ(s["collisions"]["total"], 0);
}

TEST(RunSummary, DriftFromAZeroInitialEnergyIsAbsoluteAndSaysSo) {
  // The projectile's particle at rest at height 0: E_0 = 0, and explicit Euler adds
  // m h² g² / 2 = 1 J a step, so E_8 = 8 J.
  const Json s = run(load_scene_text(R"(<scene>
  <duration time="1"/>
  <integrator type="explicit-euler" dt="0.125"/>
  <particle m="2" px="0" py="0" vx="0" vy="0" fixed="0"/>
  <simplegravity fx="0" fy="-8"/>
</scene>)",
                                     "at_rest.xml"));
  const Json& e = s["energy"];
  EXPECT_EQ(e["initial"].get<double>(), 0.0);
  EXPECT_EQ(e["final"].get<double>(), 8.0);
  EXPECT_TRUE(e["relative_drift"].is_null());
  EXPECT_TRUE(e["max_relative_drift"].is_null());
  EXPECT_EQ(e["normalized_drift"].get<double>(), 8.0);
  EXPECT_EQ(e["max_normalized_drift"].get<double>(), 8.0);
  EXPECT_EQ(e["normalized_by"], "none");
}

TEST(RunSummary, CollisionsAreCountedAsTheStepsReportedThem) {
  Totals totals;
  const Json s = run(load_scene_text(kBouncing, "bouncing.xml"), &totals);
  ASSERT_GT(totals.collisions, 0) << "the ball must bounce for this test to mean anything";
  EXPECT_EQ(s["collisions"]["total"], totals.collisions);
  EXPECT_EQ(s["collisions"]["max_per_step"], totals.max_collisions);
  EXPECT_EQ(s["collisions"]["steps_with_collisions"], totals.colliding_steps);
  EXPECT_EQ(s["collisions"]["mean_per_step"].get<double>(),
            static_cast<double>(totals.collisions) / 200.0);
}

TEST(RunSummary, NewtonIterationsAreTheStepsOwn) {
  Totals totals;
  const Json s = run(load_scene_text(kStiffSpring, "spring.xml"), &totals);
  const Json& iterations = s["solver"]["iterations"];
  ASSERT_TRUE(iterations.is_object()) << s.dump(2);
  EXPECT_EQ(iterations["of"], "newton");
  EXPECT_GE(totals.iterations, 10) << "at least one iteration a step";
  EXPECT_EQ(iterations["total"], totals.iterations);
  EXPECT_EQ(iterations["max_per_step"], totals.max_iterations);
  EXPECT_EQ(s["solver"]["line_search_steps"], 0);
}

TEST(RunSummary, TheSameBytesOutsideTheTimingsRunAfterRun) {
  const Scene scene = load_scene_text(kBouncing, "bouncing.xml");
  Json a = run(scene), b = run(scene);
  ASSERT_TRUE(a.contains("timings"));
  EXPECT_EQ(a.back(), a["timings"]) << "timings come last";
  a.erase("timings");
  b.erase("timings");
  EXPECT_EQ(a.dump(), b.dump());
}

TEST(RunSummary, NotFiniteEnergiesAreNull) {
  // Every value the schema writes is JSON: an energy that overflowed is null, not "inf".
  Scene scene = load_scene_text(kProjectile, "projectile.xml");
  RunSummary summary(scene);
  State state = scene.initial;
  summary.add(state, nullptr, nullptr);
  state.v[1] = 1e300;  // kinetic energy 1e600: infinite
  state.step = 1;
  StepRecord record;
  summary.add(state, &record, nullptr);
  const Json s = Json::parse(summary.json());
  EXPECT_TRUE(s["energy"]["final"].is_null());
  EXPECT_TRUE(s["energy"]["max"].is_null());
  EXPECT_EQ(s["energy"]["initial"].get<double>(), 41.0);
}

}  // namespace
}  // namespace fosssim
