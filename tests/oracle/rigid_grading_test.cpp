// fosssim-oracle on Theme 3 (rigid-body) scenes: run the candidate, grade its file with the
// rigid-body grader of FOSSSim -i, and report it like any other scene (docs/grading.md). A
// correct candidate passes with zero residuals; a perturbed state, a NaN, a short file and a
// hanging candidate get their verdicts with reasons; the command writes JUnit for the suite.

#include <gtest/gtest.h>

#include <cstring>
#include <limits>

#include "batch.h"
#include "diagnosis.h"
#include "grading/rigid_grader.h"
#include "io/scene_loader.h"
#include "scene_grading.h"
#include "test_support.h"

namespace fosssim {
namespace {

using testing::TemporaryFolder;

const std::string kRigidScene = testing::kData + "/rigid/square_triangle_springs.xml";
constexpr int kBodies = 2;
constexpr int kSteps = 40;

SceneEntry rigid_scene() { return {"rigid/square_triangle_springs.xml", kRigidScene, false}; }

GradingOptions rigid_options_for(const std::string& candidate, const TemporaryFolder& work) {
  GradingOptions options;
  options.run.candidate = candidate;
  options.run.timeout_seconds = 30.0;
  options.run.readable = testing::sandbox_readable();
  options.run.readable.push_back(work.path());  // the prepared files of file_copying_candidate
  options.work_dir = work.path();
  return options;
}

bool rigid_text_contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// The byte offset of body b's state component c (X_x X_y θ V_x V_y ω) in frame k of a Theme 3
/// file (io/rigid_trajectory.h): frame 0 is 6B + 4B + 6B + 1 doubles, later frames 6B + 6B + 1.
std::size_t state_offset(int k, int b, int c) {
  const int frame0 = 16 * kBodies + 1, frame = 12 * kBodies + 1;
  const int doubles = k == 0 ? 0 : frame0 + frame * (k - 1);
  return 8 * static_cast<std::size_t>(doubles + 6 * b + c);
}

/// Grades the rigid scene with file_copying_candidate.sh writing `bytes`.
SceneResult grade_copied_rigid(const std::string& bytes, const TemporaryFolder& work) {
  const std::string file = work / "prepared.bin";
  testing::write_bytes(file, bytes);
  testing::set_env("ORACLE_TEST_TRAJECTORY", file);
  testing::set_env("ORACLE_TEST_EXIT", "0");
  testing::set_env("ORACLE_TEST_STDERR", "");
  return grade_scene(rigid_scene(),
                     rigid_options_for(testing::candidate("file_copying_candidate.sh"), work));
}

void add_to_double(std::string& bytes, std::size_t offset, double delta) {
  double value = 0.0;
  std::memcpy(&value, bytes.data() + offset, sizeof value);
  value += delta;
  std::memcpy(bytes.data() + offset, &value, sizeof value);
}

TEST(RigidGrading, FossSimPassesWithZeroResiduals) {
  TemporaryFolder work;
  const SceneResult r = grade_scene(rigid_scene(), rigid_options_for(testing::kFossSim, work));
  EXPECT_EQ(r.verdict, Verdict::kPassed) << r.reason << "\n" << r.details;
  ASSERT_TRUE(r.residuals);
  EXPECT_EQ(r.residuals->accumulated_position, 0.0);  // same code, same bits
  EXPECT_EQ(r.residuals->accumulated_velocity, 0.0);
  EXPECT_EQ(r.residuals->max_position, 0.0);
  EXPECT_EQ(r.residuals->max_velocity, 0.0);
  EXPECT_EQ(r.integrator, "symplectic-euler");
  EXPECT_EQ(r.steps, kSteps);
  EXPECT_EQ(r.particles, kBodies);
}

// The oracle's verdict and residuals are those of FOSSSim -i's rigid grader on the same file.
TEST(RigidGrading, APerturbedAngleFailsAtThatStepAsFossSimGradesIt) {
  TemporaryFolder work;
  std::string bytes = testing::fosssim_trajectory(kRigidScene, work);
  ASSERT_EQ(bytes.size(), 8u * (4 * kBodies + (kSteps + 1) * (12 * kBodies + 1)));
  add_to_double(bytes, state_offset(17, 1, 2), 1e-7);  // frame 17, body 1, θ
  const SceneResult r = grade_copied_rigid(bytes, work);
  EXPECT_EQ(r.verdict, Verdict::kFailed);
  EXPECT_TRUE(rigid_text_contains(r.reason, "Maximum Theta Residual")) << r.reason;
  EXPECT_TRUE(rigid_text_contains(r.reason, "(limit 1e-08)")) << r.reason;
  EXPECT_TRUE(rigid_text_contains(r.reason, "first step over the limits 17")) << r.reason;
  EXPECT_TRUE(rigid_text_contains(r.details, "Overall success: Failed.")) << r.details;
  ASSERT_TRUE(r.residuals);
  // What FOSSSim -i reports for the same file: the course's residual-file sums.
  testing::write_bytes(work / "perturbed.bin", bytes);
  const RigidGradeReport direct =
      grade_rigid_trajectory(load_scene_file(kRigidScene), work / "perturbed.bin");
  EXPECT_FALSE(direct.passed());
  EXPECT_EQ(r.residuals->max_position,
            direct.maximum[kResidualX] + direct.maximum[kResidualTheta]);
  EXPECT_EQ(r.residuals->accumulated_velocity,
            direct.accumulated[kResidualV] + direct.accumulated[kResidualOmega]);
  EXPECT_GE(r.residuals->max_position, 1e-7 * (1 - 1e-6));
}

TEST(RigidGrading, APerturbationBelowTheLimitPasses) {
  TemporaryFolder work;
  std::string bytes = testing::fosssim_trajectory(kRigidScene, work);
  add_to_double(bytes, state_offset(17, 0, 0), 1e-12);  // frame 17, body 0, X_x
  const SceneResult r = grade_copied_rigid(bytes, work);
  EXPECT_EQ(r.verdict, Verdict::kPassed) << r.reason;
  ASSERT_TRUE(r.residuals);
  EXPECT_GT(r.residuals->max_position, 0.0);
  EXPECT_LT(r.residuals->max_position, 1e-8);
}

TEST(RigidGrading, NanIsGarbageNamingFrameAndBody) {
  TemporaryFolder work;
  std::string bytes = testing::fosssim_trajectory(kRigidScene, work);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::memcpy(bytes.data() + state_offset(9, 1, 5), &nan, sizeof nan);  // frame 9, body 1, ω
  const SceneResult r = grade_copied_rigid(bytes, work);
  EXPECT_EQ(r.verdict, Verdict::kGarbage);
  EXPECT_TRUE(rigid_text_contains(r.reason, "frame 9, body 1: state")) << r.reason;
  EXPECT_TRUE(rigid_text_contains(r.reason, "nan")) << r.reason;
}

TEST(RigidGrading, ShortAndOversizedFilesAreRefusedBeforeGrading) {
  TemporaryFolder work;
  const std::string good = testing::fosssim_trajectory(kRigidScene, work);
  EXPECT_EQ(grade_copied_rigid(good.substr(0, good.size() - 8), work).verdict, Verdict::kShort);
  EXPECT_EQ(grade_copied_rigid(good + good.substr(0, 8), work).verdict, Verdict::kOversized);
}

TEST(RigidGrading, AHangingCandidateTimesOut) {
  TemporaryFolder work;
  GradingOptions options = rigid_options_for(testing::candidate("hanging_candidate.sh"), work);
  options.run.timeout_seconds = 0.5;
  const SceneResult r = grade_scene(rigid_scene(), options);
  EXPECT_EQ(r.verdict, Verdict::kTimedOut);
  EXPECT_LT(r.run_seconds, 5.0);
}

TEST(RigidGrading, TheCommandGradesATheme3SuiteIntoJUnit) {
  TemporaryFolder work;
  const std::string junit = work / "junit.xml";
  std::vector<std::string> argv = {testing::kOracle, "grade", "--candidate", testing::kFossSim,
                                   "-q", "--junit", junit, "--work-dir", work.path(),
                                   testing::kData + "/rigid"};
  for (const std::string& argument : testing::allow_read_arguments()) argv.push_back(argument);
  const ChildOutcome outcome = testing::run_program(argv);
  EXPECT_EQ(outcome.exit_status, 0) << outcome.stderr_tail;
  const std::string xml = testing::read_bytes(junit);
  EXPECT_TRUE(rigid_text_contains(xml, "name=\"square_triangle_springs.xml\"")) << xml;
  EXPECT_TRUE(rigid_text_contains(xml, "failures=\"0\"")) << xml;
  EXPECT_FALSE(rigid_text_contains(xml, "<failure")) << xml;
  EXPECT_FALSE(rigid_text_contains(xml, "<error")) << xml;
}


// The diagnosis of a failing Theme 3 scene (fosssim-oracle --diagnose): the perturbing candidate
// (FOSSSim, then one double of its file changed) turns body 1's ω at frame 23 by 1e-6; the
// oracle names step 23, body 1, Omega, shows the residuals of the steps up to it, and writes the
// per-step table (zero residuals before step 23, the change at 23) and the plot.
TEST(RigidGrading, TheDiagnosisNamesTheFirstFailingStepBodyAndQuantity) {
  TemporaryFolder work, diagnosis;
  testing::use_perturbing_candidate(23, 1, 5, "1e-6");
  GradingOptions options = rigid_options_for(testing::candidate("perturbing_candidate.sh"), work);
  options.diagnose_dir = diagnosis.path();
  const SceneResult r = grade_scene(rigid_scene(), options);
  EXPECT_EQ(r.verdict, Verdict::kFailed);
  ASSERT_TRUE(r.first_divergence);
  EXPECT_EQ(r.first_divergence->step, 23);
  EXPECT_EQ(r.first_divergence->particle, 1);
  EXPECT_NEAR(r.first_divergence->velocity_residual, 1e-6, 1e-12);
  EXPECT_EQ(r.first_divergence->position_residual, 0.0);  // the frame's positions are right
  EXPECT_TRUE(rigid_text_contains(
      r.details, "First divergence: step 23, body 1, Omega (residual 1.00000000002"))
      << r.details;
  EXPECT_TRUE(rigid_text_contains(r.details, "Residuals per step")) << r.details;
  EXPECT_TRUE(rigid_text_contains(r.details, "\n  22  0 (0)"))
      << r.details;  // the step before: exact
  // The table: a header and one row per step, zero before step 23.
  const std::string stem = diagnosis_stem(diagnosis.path(), rigid_scene().name);
  const std::string table = testing::read_bytes(stem + ".residuals.tsv");
  std::vector<std::string> rows;
  std::size_t at = 0;
  while (at < table.size()) {
    const std::size_t end = table.find('\n', at);
    rows.push_back(table.substr(at, end - at));
    at = end == std::string::npos ? table.size() : end + 1;
  }
  ASSERT_EQ(rows.size(), 1u + kSteps) << table;
  EXPECT_EQ(rows[22].substr(0, 3), "22\t");
  EXPECT_TRUE(rigid_text_contains(rows[22], "\t0\t")) << rows[22];
  EXPECT_EQ(rows[23].substr(0, 3), "23\t");
  EXPECT_TRUE(rigid_text_contains(rows[23], "\t1.00000000002")) << rows[23];
  EXPECT_TRUE(rigid_text_contains(testing::read_bytes(stem + ".residuals.svg"), "<svg"));
  EXPECT_TRUE(
      rigid_text_contains(testing::read_bytes(stem + ".diagnosis.txt"), "First divergence"));
  // The grader's own report agrees: FOSSSim -i's first divergence on the same kind of file.
  std::string bytes = testing::fosssim_trajectory(kRigidScene, work);
  add_to_double(bytes, state_offset(23, 1, 5), 1e-6);
  testing::write_bytes(work / "perturbed.bin", bytes);
  std::vector<RigidStepResiduals> steps;
  const RigidGradeReport direct = grade_rigid_trajectory(
      load_scene_file(kRigidScene), work / "perturbed.bin", {},
      [&steps](const RigidStepResiduals& s) { steps.push_back(s); });
  ASSERT_TRUE(direct.first_divergence);
  EXPECT_EQ(direct.first_divergence->step, 23);
  EXPECT_EQ(direct.first_divergence->body, 1);
  EXPECT_EQ(direct.first_divergence->quantity, "Omega");
  ASSERT_EQ(steps.size(), static_cast<std::size_t>(kSteps));
  EXPECT_EQ(steps[22].step, 23);
  EXPECT_EQ(steps[22].body[kResidualOmega], 1);
  EXPECT_EQ(steps[21].maximum[kResidualOmega], 0.0);
  // Step 24 restarts from the perturbed frame: its residuals show the change carried on.
  EXPECT_GT(steps[23].maximum[kResidualTheta] + steps[23].maximum[kResidualOmega], 0.0);
}

// A wrong derived quantity alone (the state right) is a divergence too: its frame and body.
TEST(RigidGrading, AWrongDerivedQuantityIsTheFirstDivergence) {
  TemporaryFolder work;
  std::string bytes = testing::fosssim_trajectory(kRigidScene, work);
  // Frame 9's quantities block follows its state: P (2B), L_cm (B), L_spin (B), T_cm (B), ...
  const std::size_t quantities = state_offset(9, 0, 0) + 8 * 6 * kBodies;
  add_to_double(bytes, quantities + 8 * (2 * kBodies + kBodies + 1), 1e-5);  // L_spin, body 1
  testing::write_bytes(work / "wrong_l.bin", bytes);
  const RigidGradeReport report =
      grade_rigid_trajectory(load_scene_file(kRigidScene), work / "wrong_l.bin");
  ASSERT_TRUE(report.first_divergence);
  EXPECT_EQ(report.first_divergence->step, 9);
  EXPECT_EQ(report.first_divergence->body, 1);
  EXPECT_EQ(report.first_divergence->quantity, "Lspin");
  EXPECT_NEAR(report.first_divergence->residual, 1e-5, 1e-12);
}

}  // namespace
}  // namespace fosssim
