// Grading by output comparison (docs/command-line.md, 'Grading'): a run passes its own grading,
// a perturbation of one double at one step fails at exactly that step and particle, and the
// report's lines and residual file match the course's format.

#include "grading/grader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/step/simulation.h"
#include "grading/step_grader.h"
#include "io/scene_loader.h"
#include "support/scratch_folder.h"
#include "support/thrown.h"
#include "support/trajectories.h"

namespace fosssim {
namespace {

namespace fs = std::filesystem;

// Three particles, one fixed, damped springs, gravity and drag, stepped by implicit Euler: every
// kind of term the reference integrator has to reproduce.
constexpr const char* kParticleScene = R"(<scene>
  <duration time="0.5"/>
  <integrator type="implicit-euler" dt="0.01"/>
  <particle m="1" px="0" py="0" vx="0" vy="0" fixed="1"/>
  <particle m="2" px="1" py="0.2" vx="0" vy="1" fixed="0"/>
  <particle m="0.5" px="1.5" py="-0.5" vx="-1" vy="0" fixed="0"/>
  <edge i="0" j="1"/>
  <edge i="1" j="2"/>
  <springforce edge="0" k="50" l0="0.9" b="0.5"/>
  <springforce edge="1" k="20" l0="0.7"/>
  <simplegravity fx="0" fy="-9.81"/>
  <dragdamping b="0.05"/>
</scene>)";

class Grader : public ::testing::Test {
 protected:
  void SetUp() override {
    scene_ = std::make_unique<Scene>(load_scene_text(kParticleScene, "grader.xml"));
    file_ = folder_ / "run.bin";
    testing::write_simulated_trajectory(*scene_, file_);
  }

  /// Adds delta to one double of the file: frame k, particle p, coordinate c, of q or v.
  void perturb(std::int64_t frame, int particle, int coordinate, bool velocity, double delta) {
    const int dofs = scene_->model.num_dofs();
    const std::int64_t index = frame * 2 * dofs + (velocity ? dofs : 0) + 2 * particle + coordinate;
    std::fstream io(file_, std::ios::in | std::ios::out | std::ios::binary);
    double value = 0.0;
    io.seekg(index * 8);
    io.read(reinterpret_cast<char*>(&value), 8);
    value += delta;
    io.seekp(index * 8);
    io.write(reinterpret_cast<const char*>(&value), 8);
  }

  GradeReport grade() {
    auto reader = TrajectoryReader::open(file_, scene_->model.num_dofs());
    return grade_trajectory(*scene_, reader);
  }

  std::unique_ptr<Scene> scene_;
  testing::ScratchFolder folder_;
  std::string file_;
};

TEST_F(Grader, PassesItsOwnTrajectoryWithZeroResidual) {
  auto report = grade();
  EXPECT_TRUE(report.passed());
  EXPECT_EQ(report.steps, 50);
  EXPECT_EQ(report.steps_graded, 50);
  ASSERT_TRUE(report.last_step.has_value());
  EXPECT_EQ(report.last_step->step, 50);
  EXPECT_EQ(report.accumulated_position, 0.0);
  EXPECT_EQ(report.accumulated_velocity, 0.0);
  EXPECT_EQ(report.max_position, 0.0);
  EXPECT_EQ(report.max_velocity, 0.0);
  EXPECT_FALSE(report.first_divergence.has_value());
}

TEST_F(Grader, FailsAPositionPerturbedBy1e9AtExactlyThatStepAndParticle) {
  perturb(/*frame=*/17, /*particle=*/2, /*coordinate=*/1, /*velocity=*/false, 1e-9);
  auto report = grade();
  EXPECT_FALSE(report.passed());
  EXPECT_FALSE(report.max_position_passed());
  ASSERT_TRUE(report.first_divergence.has_value());
  EXPECT_EQ(report.first_divergence->step, 17);
  EXPECT_EQ(report.first_divergence->particle, 2);
  EXPECT_NEAR(report.first_divergence->position_residual, 1e-9, 1e-15);
  // Step by step, each step's residuals are the report's last_step.
  auto reader = TrajectoryReader::open(file_, scene_->model.num_dofs());
  StepGrader grader = StepGrader::open(*scene_, reader);
  for (std::int64_t k = 1; k <= 17; ++k) {
    ASSERT_TRUE(grader.grade_next_step());
    ASSERT_EQ(grader.report().last_step->step, k);
    if (k < 17) {
      EXPECT_EQ(grader.report().last_step->max_position, 0.0) << k;
    }
  }
  EXPECT_EQ(grader.report().last_step->max_position_particle, 2);
}

TEST_F(Grader, FailsAVelocityPerturbationOnTheVelocityCriterion) {
  perturb(/*frame=*/3, /*particle=*/1, /*coordinate=*/0, /*velocity=*/true, -1e-9);
  auto report = grade();
  EXPECT_FALSE(report.passed());
  EXPECT_FALSE(report.max_velocity_passed());
  ASSERT_TRUE(report.first_divergence.has_value());
  EXPECT_EQ(report.first_divergence->step, 3);
  EXPECT_EQ(report.first_divergence->particle, 1);
  EXPECT_NEAR(report.first_divergence->velocity_residual, 1e-9, 1e-15);
}

TEST_F(Grader, PerturbingTheFixedParticleIsCaughtToo) {
  perturb(/*frame=*/40, /*particle=*/0, /*coordinate=*/0, /*velocity=*/false, 1e-9);
  auto report = grade();
  EXPECT_FALSE(report.passed());
  EXPECT_EQ(report.first_divergence->step, 40);
  EXPECT_EQ(report.first_divergence->particle, 0);
}

// Grading measures each step's local error: a perturbation below the maximum limit passes.
TEST_F(Grader, ToleratesAPerturbationBelowTheLimit) {
  perturb(/*frame=*/10, /*particle=*/1, /*coordinate=*/0, /*velocity=*/false, 3e-11);
  auto report = grade();
  EXPECT_TRUE(report.passed());
  EXPECT_GT(report.max_position, 1e-11);
  EXPECT_LT(report.max_position, 1e-10);
}

TEST_F(Grader, NotANumberInTheFileFails) {
  perturb(/*frame=*/5, /*particle=*/1, /*coordinate=*/0, /*velocity=*/false,
          std::numeric_limits<double>::quiet_NaN());
  auto report = grade();
  EXPECT_FALSE(report.passed());
  EXPECT_TRUE(std::isnan(report.max_position));
  EXPECT_EQ(report.first_divergence->step, 5);
}

TEST_F(Grader, RejectsAFileWithTooFewFrames) {
  fs::resize_file(file_, 50 * 2 * 6 * 8);  // 50 frames instead of 51
  const Error report_error = thrown_by<Error>([&] { grade(); });
  EXPECT_EQ(report_error.kind(), ErrorKind::kBadInput);
  EXPECT_STREQ(report_error.what(),
               "the trajectory has 50 frames, but the scene takes 50 steps and so needs 51 (the "
               "initial state and one frame per step); the file was cut short, or made with "
               "another duration");
}

TEST_F(Grader, RejectsAFileWithTooManyFrames) {
  fs::resize_file(file_, 52 * 2 * 6 * 8);
  const Error report_error = thrown_by<Error>([&] { grade(); });
  EXPECT_EQ(report_error.kind(), ErrorKind::kBadInput);
  EXPECT_STREQ(report_error.what(),
               "the trajectory has 52 frames, but the scene takes 50 steps and so needs 51 (the "
               "initial state and one frame per step); the file was made with another duration");
}

TEST_F(Grader, ReportsAReferenceStepThatCannotBeTaken) {
  scene_->model.integrator.options.set("newton-max-iterations", 1);
  scene_->model.integrator.options.set("newton-tolerance", 1e-300);
  auto report = grade();
  EXPECT_FALSE(report.passed());
  ASSERT_TRUE(report.reference_failure.has_value());
  EXPECT_NE(
      report.reference_failure->find("step 1: implicit Euler: Newton's method did not converge"),
      std::string::npos)
      << *report.reference_failure;
}

// A trajectory of zeros makes the springs' lengths zero: the reference step cannot be taken.
// Its residuals are undefined, so every criterion fails, in the printed report and in the
// residual file alike (they once said "Passed" four times over an overall failure).
TEST_F(Grader, AStepTheReferenceCannotTakeFailsEveryCriterionInTheReportAndTheResidualFile) {
  fs::resize_file(file_, 0);
  fs::resize_file(file_, 51 * 2 * 6 * 8);  // 51 frames of zeros
  const GradeReport report = grade();
  ASSERT_TRUE(report.reference_failure.has_value()) << "the zeros were graded";
  EXPECT_FALSE(report.passed());
  for (const Criterion& c : criteria_of(report)) {
    EXPECT_FALSE(c.passed) << c.name;
    EXPECT_TRUE(std::isnan(c.value)) << c.name;
  }
  std::ostringstream printed;
  print_grade_report(printed, report);
  EXPECT_EQ(printed.str(),
            "Accumulated Position Residual: nan   Failed.\n"
            "Accumulated Velocity Residual: nan   Failed.\n"
            "Maximum Position Residual: nan   Failed.\n"
            "Maximum Velocity Residual: nan   Failed.\n"
            "Overall success: Failed.\n");
  const std::string residuals = folder_ / "residual.txt";
  write_residual_file(residuals, report);
  std::ifstream in(residuals);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}),
            "0   nan\n0   nan\n0   nan\n0   nan\n");
}

TEST(GradeReport, CriteriaAreStrict) {
  GradeReport report;
  EXPECT_TRUE(report.passed());
  report.accumulated_position = 1e-6;
  EXPECT_FALSE(report.accumulated_position_passed());
  report.accumulated_position = std::nextafter(1e-6, 0.0);
  EXPECT_TRUE(report.accumulated_position_passed());
  report.max_velocity = 1e-10;
  EXPECT_FALSE(report.max_velocity_passed());
  EXPECT_FALSE(report.passed());
  report.max_velocity = std::nextafter(1e-10, 0.0);
  EXPECT_TRUE(report.passed());
}

TEST(GradeReport, PrintsTheCourseLines) {
  GradeReport report;
  report.accumulated_position = 2.5e-7;
  report.accumulated_velocity = 3e-6;
  report.max_position = 1e-11;
  report.max_velocity = 0.0;
  std::ostringstream out;
  print_grade_report(out, report);
  EXPECT_EQ(out.str(),
            "Accumulated Position Residual: 2.5e-07   Passed.\n"
            "Accumulated Velocity Residual: 3e-06   Failed.\n"
            "Maximum Position Residual: 1e-11   Passed.\n"
            "Maximum Velocity Residual: 0   Passed.\n"
            "Overall success: Failed.\n");
}

TEST(GradeReport, WritesTheResidualFile) {
  GradeReport report;
  report.accumulated_position = 2.5e-7;
  report.max_position = 0.5;
  const testing::ScratchFolder folder;
  const std::string path = folder / "residual.txt";
  write_residual_file(path, report);
  EXPECT_EQ(testing::read_file(path), "1   2.5e-07\n1   0\n0   0.5\n1   0\n");
  EXPECT_FALSE(fs::exists(path + ".partial"));
}

}  // namespace
}  // namespace fosssim
