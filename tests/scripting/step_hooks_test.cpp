#include "scripting/step_hooks.h"

#include <gtest/gtest.h>

#include "core/step/simulation.h"
#include "grading/grader.h"
#include "io/scene_loader.h"
#include "io/trajectory_file.h"
#include "scripting/particle_fountain.h"
#include "support/scratch_folder.h"

namespace fosssim {
namespace {

// Two tagged particles thrown up and one untagged, under gravity; 3 s is long enough for the
// tagged ones to fall below -1.25 and come back several times.
constexpr const char* kFountain = R"(<scene>
  <duration time="3.0"/>
  <integrator type="symplectic-euler" dt="0.01"/>
  <scenetag tag="ParticleFountain"/>
  <particle m="1" px="0" py="0" vx="0.5" vy="3" fixed="0" tag="teleport"/>
  <particle m="1" px="0" py="0" vx="-0.5" vy="4" fixed="0" tag="teleport"/>
  <particle m="1" px="0" py="0" vx="0" vy="1" fixed="0"/>
  <simplegravity fx="0" fy="-9.81"/>
</scene>)";

Scene load(const std::string& text) { return load_scene_text(text, "fountain.xml"); }

TEST(MakeStepHook, ParticleFountainTagSelectsTheFountain) {
  const Scene scene = load(kFountain);
  const auto hook = make_step_hook(scene);
  ASSERT_NE(hook, nullptr);
  EXPECT_NE(dynamic_cast<const ParticleFountain*>(hook.get()), nullptr);
}

TEST(MakeStepHook, NoTagOrAnUnknownTagSelectsNothing) {
  Scene scene = load(kFountain);
  scene.tag = "";
  EXPECT_EQ(make_step_hook(scene), nullptr);
  scene.tag = "SomethingElse";
  EXPECT_EQ(make_step_hook(scene), nullptr);
  EXPECT_EQ(known_scene_tags(), std::vector<std::string>{"ParticleFountain"});
}

TEST(SimulationWithFountain, TaggedParticlesNeverEndAStepBelowTheFloor) {
  const Scene scene = load(kFountain);
  Simulation simulation(scene.model, scene.initial, scripted_additions(scene));
  int teleports = 0;
  double lowest_untagged = 0.0;
  while (!simulation.finished()) {
    const double before = simulation.state().q[1];
    simulation.step();
    const State& s = simulation.state();
    EXPECT_GE(s.q[1], ParticleFountain::kFloorHeight) << "step " << s.step;
    EXPECT_GE(s.q[3], ParticleFountain::kFloorHeight) << "step " << s.step;
    if (s.q[1] == 0.0 && s.q[0] == 0.0 && before < 0.0) ++teleports;
    lowest_untagged = std::min(lowest_untagged, s.q[5]);
  }
  EXPECT_GE(teleports, 2);
  EXPECT_LT(lowest_untagged, -10.0);  // the untagged particle just falls
}

TEST(SimulationWithFountain, TwoRunsAreBitIdentical) {
  const Scene scene = load(kFountain);
  Simulation a(scene.model, scene.initial, scripted_additions(scene));
  Simulation b(scene.model, scene.initial, scripted_additions(scene));
  while (!a.finished()) {
    a.step();
    b.step();
  }
  EXPECT_EQ(a.state().q, b.state().q);
  EXPECT_EQ(a.state().v, b.state().v);
}

/// Writes the whole run of `scene` (with or without its hook) as a trajectory file.
void write_run(const Scene& scene, bool with_hook, const std::string& path) {
  auto writer = TrajectoryWriter::open(path);
  Simulation simulation(scene.model, scene.initial,
                        with_hook ? scripted_additions(scene) : StepAdditions{});
  writer.write_frame(simulation.state());
  while (!simulation.finished()) {
    simulation.step();
    writer.write_frame(simulation.state());
  }
  writer.commit();
}

/// Grades a run of `scene` written with or without its hook.
GradeReport grade_run(const Scene& scene, bool with_hook) {
  const testing::ScratchFolder folder;
  write_run(scene, with_hook, folder / "run.bin");
  auto file = TrajectoryReader::open(folder / "run.bin", scene.model.num_dofs());
  return grade_trajectory(scene, file);
}

TEST(GradingWithFountain, ATrajectoryWithTheSameTeleportsPasses) {
  const Scene scene = load(kFountain);
  const auto report = grade_run(scene, true);
  EXPECT_TRUE(report.passed());
  EXPECT_EQ(report.max_position, 0.0);
}

TEST(GradingWithFountain, ATrajectoryWithoutTeleportsFailsAtTheFirstTeleport) {
  const Scene scene = load(kFountain);
  const auto report = grade_run(scene, false);
  EXPECT_FALSE(report.passed());
  ASSERT_TRUE(report.first_divergence.has_value());

  // The first teleport: the first step after which a tagged particle is below the floor.
  Simulation plain(scene.model, scene.initial);
  std::int64_t first = -1;
  while (first < 0 && !plain.finished()) {
    plain.step();
    const State& s = plain.state();
    if (s.q[1] < ParticleFountain::kFloorHeight || s.q[3] < ParticleFountain::kFloorHeight) {
      first = s.step;
    }
  }
  EXPECT_EQ(report.first_divergence->step, first);
}

}  // namespace
}  // namespace fosssim
