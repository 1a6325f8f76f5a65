// Tests of grading/rigid_grader (docs/rigid-bodies.md, 'Grading'): FOSSSim's own Theme 3
// trajectory passes; single doubles perturbed across the course's limits fail the right check;
// a file of the wrong length is refused (the course's grader would pass one a few bytes short).

#include "grading/rigid_grader.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/step/simulation.h"
#include "io/scene_loader.h"
#include "support/scratch_folder.h"
#include "support/thrown.h"

namespace fosssim::testing {
namespace {

const std::string kRigidScene =
    std::string(FOSSSIM_SOURCE_DIR) + "/assets/t3m1/mixed_explicit_all_forces.xml";

/// Writes the scene's own trajectory to `path`.
void write_run(const Scene& scene, const std::string& path) {
  RigidTrajectoryWriter writer(TrajectoryWriter::open(path), scene.model);
  Simulation simulation(scene.model, scene.initial);
  writer.write(simulation.state());
  while (!simulation.finished()) {
    simulation.step();
    writer.write(simulation.state());
  }
  writer.commit();
}

/// Adds `delta` to the double at index `index` of the file.
void perturb(const std::string& path, std::int64_t index, double delta) {
  std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
  double value = 0.0;
  file.seekg(8 * index);
  file.read(reinterpret_cast<char*>(&value), 8);
  value += delta;
  file.seekp(8 * index);
  file.write(reinterpret_cast<const char*>(&value), 8);
}

class RigidGraderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    scene_ = load_scene_file(kRigidScene);
    path_ = folder_ / "run.bin";
    write_run(scene_, path_);
  }
  // B = 3 bodies: frame 0 has 16B + 1 = 49 doubles, later frames 12B + 1 = 37.
  static constexpr int kB = 3;
  static std::int64_t frame_start(std::int64_t k) {
    return k == 0 ? 0 : (16 * kB + 1) + (k - 1) * (12 * kB + 1);
  }
  Scene scene_;
  ScratchFolder folder_;
  std::string path_;
};

TEST_F(RigidGraderTest, OwnTrajectoryPassesWithZeroResiduals) {
  const RigidGradeReport report = grade_rigid_trajectory(scene_, path_);
  EXPECT_TRUE(report.passed());
  for (int r = 0; r < 4; ++r) {
    EXPECT_EQ(report.accumulated[r], 0.0);
    EXPECT_EQ(report.maximum[r], 0.0);
  }
  std::ostringstream out;
  print_rigid_grade_report(out, report);
  EXPECT_NE(out.str().find("M     Computation(s): correct"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("U     Computation: correct"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("Overall success: Passed."), std::string::npos) << out.str();
}

TEST_F(RigidGraderTest, AngleOffByMoreThanTheLimitFails) {
  // θ of body 1 in frame 7 (index 6·1 + 2 of the state block) off by 1.01e-8.
  perturb(path_, frame_start(7) + 8, 1.01e-8);
  const RigidGradeReport report = grade_rigid_trajectory(scene_, path_);
  EXPECT_FALSE(report.passed());
  EXPECT_FALSE(report.maximum_passed(kResidualTheta));
  EXPECT_NEAR(report.maximum[kResidualTheta], 1.01e-8, 1e-15);
  EXPECT_EQ(report.first_failing_step, 7);
}

TEST_F(RigidGraderTest, AngleOffByLessThanTheLimitPassesTheResidualCheck) {
  perturb(path_, frame_start(7) + 8, 0.99e-8);
  const RigidGradeReport report = grade_rigid_trajectory(scene_, path_);
  EXPECT_TRUE(report.maximum_passed(kResidualTheta));
  EXPECT_NEAR(report.maximum[kResidualTheta], 0.99e-8, 1e-15);
}

TEST_F(RigidGraderTest, WrongMassInTheStartBlockFailsTheMassCheck) {
  perturb(path_, 6 * kB + 1, 2e-8);  // M of body 1
  const RigidGradeReport report = grade_rigid_trajectory(scene_, path_);
  EXPECT_FALSE(report.passed());
  EXPECT_FALSE(report.quantity_correct[kQuantityM]);
  EXPECT_TRUE(report.quantity_correct[kQuantityI]);
  ASSERT_FALSE(report.mismatches.empty());
  EXPECT_EQ(report.mismatches[0].body, 1);
}

TEST_F(RigidGraderTest, WrongEnergyFailsTheEnergyCheck) {
  perturb(path_, frame_start(3) + 12 * kB, 1e-7);  // U of frame 3
  const RigidGradeReport report = grade_rigid_trajectory(scene_, path_);
  EXPECT_FALSE(report.passed());
  EXPECT_FALSE(report.quantity_correct[kQuantityU]);
  EXPECT_TRUE(report.quantity_correct[kQuantityP]);
}

TEST_F(RigidGraderTest, FileEightBytesShortIsRefused) {
  std::filesystem::resize_file(path_, std::filesystem::file_size(path_) - 8);
  const Error error = thrown_by<Error>([&] { grade_rigid_trajectory(scene_, path_); });
  EXPECT_EQ(error.kind(), ErrorKind::kBadInput);
  EXPECT_NE(std::string(error.what()).find("cut short"), std::string::npos) << error.what();
}

}  // namespace
}  // namespace fosssim::testing
