#include "viewer/stepper.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/step_error.h"
#include "io/scene_loader.h"
#include "io/trajectory_file.h"
#include "support/scratch_folder.h"

namespace fosssim {
namespace {

constexpr const char* kTwoSprings = R"(<scene>
  <duration time="0.5"/><integrator type="symplectic-euler" dt="0.01"/>
  <particle m="1" px="0" py="0" vx="0" vy="0" fixed="1"/>
  <particle m="1" px="1" py="0" vx="0" vy="0" fixed="0"/>
  <particle m="1" px="2" py="0" vx="0" vy="0" fixed="0"/>
  <edge i="0" j="1"/><edge i="1" j="2"/>
  <springforce edge="0" k="50" l0="1"/><springforce edge="1" k="50" l0="1"/>
  <simplegravity fx="0" fy="-9.81"/>
</scene>)";

Scene load() { return load_scene_text(kTwoSprings, "springs.xml"); }

TEST(GradingMarks, RingsByHowFarTheFileIsFromTheReference) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto marks =
      grading_marks({0.0, 5e-10, 2e-9, 0.0, 1e-10, nan}, {0.0, 0.0, 0.0, 3e-6, 0.0, 0.0}, {});
  ASSERT_EQ(marks.size(), 5u);
  EXPECT_EQ(marks[0].particle, 1);
  EXPECT_EQ(marks[0].color, kFailColor);  // above 1e-10, below 1e-9
  EXPECT_EQ(marks[1].particle, 2);
  EXPECT_EQ(marks[1].color, kDisagreeColor);
  EXPECT_EQ(marks[2].particle, 3);
  EXPECT_EQ(marks[2].color, kDisagreeColor);  // the velocity counts too
  EXPECT_EQ(marks[3].particle, 4);
  EXPECT_EQ(marks[3].color, kFailColor);  // exactly 1e-10 fails the strict criterion
  EXPECT_EQ(marks[4].particle, 5);
  EXPECT_EQ(marks[4].color, kDisagreeColor);  // NaN
}

TEST(GradingMarks, VelocitiesAreRingedByTheVelocityLimitOfTheScenesTheme) {
  // Theme 4's single velocity residual may reach 1e-9 (its position limit stays 1e-10).
  const std::vector<double> positions = {0.0, 0.0, 0.0, 0.0, 5e-10, 2e-9};
  const std::vector<double> velocities = {5e-10, 1e-9, 2e-9, 2e-8, 0.0, 0.0};
  const auto theme1 = grading_marks(positions, velocities, GradingCriteria{});
  ASSERT_EQ(theme1.size(), 6u);
  EXPECT_EQ(theme1[0].color, kFailColor);       // 5e-10 ≥ 1e-10
  EXPECT_EQ(theme1[1].color, kFailColor);       // 1e-9: not beyond ten times 1e-10
  EXPECT_EQ(theme1[2].color, kDisagreeColor);   // 2e-9 > 1e-9
  const auto theme4 = grading_marks(positions, velocities, kTheme4Criteria);
  ASSERT_EQ(theme4.size(), 5u);
  EXPECT_EQ(theme4[0].particle, 1);  // 5e-10 passes 1e-9: no ring
  EXPECT_EQ(theme4[0].color, kFailColor);  // exactly 1e-9 fails the strict criterion
  EXPECT_EQ(theme4[1].particle, 2);
  EXPECT_EQ(theme4[1].color, kFailColor);  // 2e-9: fails, within ten times the limit
  EXPECT_EQ(theme4[2].particle, 3);
  EXPECT_EQ(theme4[2].color, kDisagreeColor);  // 2e-8 > 1e-8
  EXPECT_EQ(theme4[3].particle, 4);
  EXPECT_EQ(theme4[3].color, kFailColor);  // positions keep 1e-10
  EXPECT_EQ(theme4[4].particle, 5);
  EXPECT_EQ(theme4[4].color, kDisagreeColor);
}

TEST(SimulationStepper, RunsTheSceneToItsEnd) {
  const Scene scene = load();
  SimulationStepper stepper(scene);
  int steps = 0;
  while (!stepper.finished()) {
    stepper.step();
    ++steps;
  }
  EXPECT_EQ(steps, 50);
  EXPECT_DOUBLE_EQ(stepper.state().time, 0.5);
  EXPECT_TRUE(stepper.overlay().marks.empty());
}

TEST(GradingStepper, ShowsTheFilesFramesAndRingsTheParticlesItGotWrong) {
  const testing::ScratchFolder folder;
  const Scene scene = load();
  {  // A run of the scene with particle 2's position off by 1e-6 at step 20.
    auto writer = TrajectoryWriter::open(folder / "run.bin");
    Simulation simulation(scene.model, scene.initial);
    writer.write_frame(simulation.state());
    while (!simulation.finished()) {
      simulation.step();
      State frame = simulation.state();
      if (frame.step == 20) frame.q[4] += 1e-6;
      writer.write_frame(frame);
    }
    writer.commit();
  }
  auto file = TrajectoryReader::open(folder / "run.bin", scene.model.num_dofs());
  GradingStepper stepper(StepGrader::open(scene, file));
  EXPECT_EQ(stepper.state().step, 0);
  for (int k = 1; k < 20; ++k) {
    stepper.step();
    EXPECT_TRUE(stepper.overlay().marks.empty()) << "step " << k;
  }
  stepper.step();
  EXPECT_EQ(stepper.state().step, 20);
  Vector q(6), v(6);
  file.read_frame(20, q, v);
  EXPECT_EQ(stepper.state().q, q);  // the file's frame is what is shown
  const Overlay overlay = stepper.overlay();
  ASSERT_EQ(overlay.marks.size(), 1u);
  EXPECT_EQ(overlay.marks[0].particle, 2);
  EXPECT_EQ(overlay.marks[0].color, kDisagreeColor);
  ASSERT_FALSE(overlay.status.empty());
  EXPECT_EQ(overlay.status[0], "grading step 20/50: 1 particle(s) disagree");
  while (!stepper.finished()) stepper.step();
  EXPECT_EQ(stepper.overlay().status.back(), "Overall: Failed");
  EXPECT_FALSE(stepper.grader().report().passed());
}

}  // namespace
}  // namespace fosssim
