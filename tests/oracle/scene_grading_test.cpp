// The oracle on real candidates: FOSSSim itself, a deliberately wrong one, and every way a
// candidate can misbehave. Each must give its verdict with a clear reason, never stop the run.

#include "scene_grading.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>

#include "batch.h"
#include "test_support.h"

namespace fosssim {
namespace {

using testing::TemporaryFolder;
using testing::tsv_row;

SceneEntry chain_scene() {
  return {"assets/basics/spring_chain_explicit.xml", testing::kChainScene, false};
}

GradingOptions options_for(const std::string& candidate, const TemporaryFolder& work) {
  GradingOptions options;
  options.run.candidate = candidate;
  options.run.timeout_seconds = 30.0;
  options.run.readable = testing::sandbox_readable();
  options.run.readable.push_back(work.path());  // the prepared files of file_copying_candidate
  options.work_dir = work.path();
  return options;
}

/// Grades the explicit chain scene with one of the scripts in candidates/.
SceneResult grade_chain_with(const std::string& script, const TemporaryFolder& work) {
  return grade_scene(chain_scene(), options_for(testing::candidate(script), work));
}

bool text_contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(GradeScene, FossSimPassesEveryTestSceneWithZeroResiduals) {
  TemporaryFolder work;
  auto scenes = discover_scenes({testing::kAssets}, {testing::kExtraCredit});
  const auto results = grade_scenes(scenes, options_for(testing::kFossSim, work), 2);
  ASSERT_EQ(results.size(), 5u);
  for (const SceneResult& r : results) {
    EXPECT_EQ(r.verdict, Verdict::kPassed) << r.name << ": " << r.reason;
    ASSERT_TRUE(r.residuals);
    EXPECT_EQ(r.residuals->max_position, 0.0);  // same code, same bits
    EXPECT_EQ(r.residuals->max_velocity, 0.0);
  }
  EXPECT_EQ(results[3].integrator, "implicit-euler");
  EXPECT_EQ(results[3].dim, 3);
  EXPECT_EQ(results[0].steps, 50);
  // The work folders are gone.
  EXPECT_TRUE(std::filesystem::is_empty(work.path()));
}

TEST(GradeScene, CollisionScenesAreGradedOnTheirCollisionRecordsToo) {
  TemporaryFolder work;
  const SceneEntry scene{"collisions/ball_pair_simple.xml",
                         testing::kData + "/collisions/ball_pair_simple.xml", false};
  const SceneResult own = grade_scene(scene, options_for(testing::kFossSim, work));
  EXPECT_EQ(own.verdict, Verdict::kPassed) << own.reason;
  // A candidate that misses the collision: its file has the right layout but no records.
  testing::set_env("FOSSSIM", testing::kFossSim);
  const SceneResult thin =
      grade_scene(scene, options_for(testing::candidate("thin_balls_candidate.sh"), work));
  EXPECT_EQ(thin.verdict, Verdict::kFailed);
  EXPECT_TRUE(text_contains(thin.reason, "Collisions from step 1 (1 missed")) << thin.reason;
  EXPECT_TRUE(
      text_contains(thin.details, "  Missed collision: Particle 0 - Particle 1 with normal"))
      << thin.details;
}

TEST(GradeScene, PerturbedCandidateFailsAtExactlyThePerturbedStepAndParticle) {
  TemporaryFolder work, diagnosis;
  testing::use_perturbing_candidate(17, 2, 1, "1e-9");  // frame 17, particle 2, position y
  GradingOptions options = options_for(testing::candidate("perturbing_candidate.sh"), work);
  options.diagnose_dir = diagnosis.path();
  const SceneResult r = grade_scene(chain_scene(), options);
  EXPECT_EQ(r.verdict, Verdict::kFailed);
  ASSERT_TRUE(r.first_divergence);
  EXPECT_EQ(r.first_divergence->step, 17);
  EXPECT_EQ(r.first_divergence->particle, 2);
  EXPECT_NEAR(r.first_divergence->position_residual, 1e-9, 1e-15);
  EXPECT_EQ(r.first_divergence->velocity_residual, 0.0);  // frame 16 is intact, so is v at 17
  EXPECT_TRUE(text_contains(r.reason, "first divergence at step 17, particle 2")) << r.reason;
  EXPECT_TRUE(text_contains(r.details, "First divergence at step 17, particle 2")) << r.details;
  EXPECT_TRUE(text_contains(r.details, "reference step")) << r.details;
  // Diagnosis files: text, per-step table and plot.
  const std::string stem = diagnosis / "assets/basics/spring_chain_explicit";
  const std::string text = testing::read_bytes(stem + ".diagnosis.txt");
  EXPECT_TRUE(text_contains(text, "First divergence at step 17, particle 2")) << text;
  const auto row = tsv_row(testing::read_bytes(stem + ".residuals.tsv"), "16");
  ASSERT_EQ(row.size(), 8u);
  EXPECT_EQ(row[2], "0");  // step 16 is still exact
  const auto failing = tsv_row(testing::read_bytes(stem + ".residuals.tsv"), "17");
  ASSERT_EQ(failing.size(), 8u);
  EXPECT_NEAR(std::stod(failing[2]), 1e-9, 1e-15);
  EXPECT_EQ(failing[3], "2");
  testing::expect_residual_plot(stem + ".residuals.svg");  // marked at step 17
}

TEST(GradeScene, PerturbationBelowTheLimitPasses) {
  TemporaryFolder work;
  testing::use_perturbing_candidate(17, 2, 0, "1e-12");
  const SceneResult r = grade_chain_with("perturbing_candidate.sh", work);
  EXPECT_EQ(r.verdict, Verdict::kPassed) << r.reason;
  ASSERT_TRUE(r.residuals);
  EXPECT_GT(r.residuals->max_position, 0.0);
  EXPECT_LT(r.residuals->max_position, 1e-10);
}

// A scene with Theme 4 forces is graded with the Theme 4 program's velocity limit, 1e-9
// (SPEC-elastica section 5), and a Theme 1 scene with Theme 1's, 1e-10: the same velocity
// change of 5e-10 passes the one and fails the other; 2e-9 fails both, where it was made.
TEST(GradeScene, ElasticScenesAreGradedWithTheTheme4VelocityLimit) {
  TemporaryFolder work;
  const SceneEntry elastic{"elastic/hinge_and_triangle.xml",
                           testing::kData + "/elastic/hinge_and_triangle.xml", false};
  const std::string candidate = testing::candidate("perturbing_candidate.sh");
  testing::use_perturbing_candidate(17, 2, 2, "5e-10");  // frame 17, particle 2, velocity x
  const SceneResult within = grade_scene(elastic, options_for(candidate, work));
  EXPECT_EQ(within.verdict, Verdict::kPassed) << within.reason;
  ASSERT_TRUE(within.residuals);
  EXPECT_NEAR(within.residuals->max_velocity, 5e-10, 1e-15);
  const SceneResult theme1 = grade_scene(chain_scene(), options_for(candidate, work));
  EXPECT_EQ(theme1.verdict, Verdict::kFailed);
  testing::use_perturbing_candidate(17, 2, 2, "2e-9");
  const SceneResult over = grade_scene(elastic, options_for(candidate, work));
  EXPECT_EQ(over.verdict, Verdict::kFailed);
  ASSERT_TRUE(over.first_divergence);
  EXPECT_EQ(over.first_divergence->step, 17);
  EXPECT_EQ(over.first_divergence->particle, 2);
}

/// Grades the chain scene with file_copying_candidate.sh writing `bytes`.
SceneResult grade_copied(const std::string& bytes, const TemporaryFolder& work, int exit_status = 0,
                         const std::string& stderr_text = "") {
  const std::string file = work / "prepared.bin";
  testing::write_bytes(file, bytes);
  testing::set_env("ORACLE_TEST_TRAJECTORY", file);
  testing::set_env("ORACLE_TEST_EXIT", std::to_string(exit_status));
  testing::set_env("ORACLE_TEST_STDERR", stderr_text);
  return grade_chain_with("file_copying_candidate.sh", work);
}

TEST(GradeScene, CopiedCorrectTrajectoryPasses) {
  TemporaryFolder work;
  EXPECT_EQ(grade_copied(testing::fosssim_trajectory(testing::kChainScene, work), work).verdict,
            Verdict::kPassed);
}

TEST(GradeScene, ShortFileFails) {
  TemporaryFolder work;
  const std::string good = testing::fosssim_trajectory(testing::kChainScene, work);
  const SceneResult whole_frames = grade_copied(good.substr(0, good.size() / 2), work);
  EXPECT_EQ(whole_frames.verdict, Verdict::kShort);
  EXPECT_TRUE(text_contains(whole_frames.reason, "3264 bytes, but the scene needs 6528"))
      << whole_frames.reason;
  const SceneResult cut_frame = grade_copied(good.substr(0, good.size() - 5), work);
  EXPECT_EQ(cut_frame.verdict, Verdict::kShort);
}

TEST(GradeScene, OversizedFileFailsWithoutBeingRead) {
  TemporaryFolder work;
  const std::string good = testing::fosssim_trajectory(testing::kChainScene, work);
  const SceneResult r = grade_copied(good + good.substr(0, 128), work);
  EXPECT_EQ(r.verdict, Verdict::kOversized);
  EXPECT_TRUE(text_contains(r.reason, "6656 bytes")) << r.reason;
}

// The Theme 4 program grades a file with frames after the last step, ignoring them
// (SPEC-elastica section 5): FOSSSim's trajectory of a Theme 4 scene with two more frames passes
// and says so in its details; the same for the Theme 1 chain scene is OVERSIZED (above).
TEST(GradeScene, ElasticScenesPassWithFramesAfterTheLastStep) {
  TemporaryFolder work;
  const std::string scene = testing::kData + "/elastic/hinge_and_triangle.xml";
  const SceneEntry elastic{"elastic/hinge_and_triangle.xml", scene, false};
  const std::string good = testing::fosssim_trajectory(scene, work);
  constexpr std::size_t kFrameBytes = 2 * 6 * 8;  // 3 particles in 2D: 6 positions, 6 velocities
  ASSERT_EQ(good.size(), 31 * kFrameBytes);        // 30 steps
  const std::string file = work / "prepared.bin";
  testing::write_bytes(file, good + good.substr(good.size() - 2 * kFrameBytes));
  testing::set_env("ORACLE_TEST_TRAJECTORY", file);
  testing::set_env("ORACLE_TEST_EXIT", "0");
  testing::set_env("ORACLE_TEST_STDERR", "");
  const SceneResult r =
      grade_scene(elastic, options_for(testing::candidate("file_copying_candidate.sh"), work));
  EXPECT_EQ(r.verdict, Verdict::kPassed) << r.reason;
  EXPECT_TRUE(text_contains(r.details, "holds 2 frames after the scene's last step")) << r.details;
}

TEST(GradeScene, RunawayWriterIsStoppedAndFailsAsOversized) {
  TemporaryFolder work;
  const SceneResult r = grade_chain_with("runaway_candidate.sh", work);
  EXPECT_EQ(r.verdict, Verdict::kOversized) << r.reason;
  EXPECT_LT(r.run_seconds, 20.0);
}

TEST(GradeScene, NanFileIsGarbage) {
  TemporaryFolder work;
  std::string bytes = testing::fosssim_trajectory(testing::kChainScene, work);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Frame 9, particle 1, velocity y: frame = 16 doubles, velocities start at double 8.
  std::memcpy(bytes.data() + 8 * (16 * 9 + 8 + 2 * 1 + 1), &nan, sizeof(nan));
  const SceneResult r = grade_copied(bytes, work);
  EXPECT_EQ(r.verdict, Verdict::kGarbage);
  EXPECT_TRUE(text_contains(r.reason, "frame 9, particle 1: velocity (")) << r.reason;
  EXPECT_TRUE(text_contains(r.reason, "nan")) << r.reason;
}

TEST(GradeScene, RandomBytesFailAtTheFirstStep) {
  TemporaryFolder work;
  std::mt19937_64 random(12345);
  std::uniform_real_distribution<double> value(-10.0, 10.0);
  std::string bytes(6528, '\0');
  for (std::size_t k = 0; k < bytes.size() / 8; ++k) {
    const double x = value(random);
    std::memcpy(bytes.data() + 8 * k, &x, sizeof(x));
  }
  const SceneResult r = grade_copied(bytes, work);
  EXPECT_EQ(r.verdict, Verdict::kFailed);
  ASSERT_TRUE(r.first_divergence);
  EXPECT_EQ(r.first_divergence->step, 1);
  const SceneResult odd = grade_copied(bytes.substr(0, 1001), work);
  EXPECT_EQ(odd.verdict, Verdict::kShort);
}

TEST(GradeScene, NonZeroExitFailsEvenWithAGoodFileAndKeepsStandardError) {
  TemporaryFolder work;
  const SceneResult r = grade_copied(testing::fosssim_trajectory(testing::kChainScene, work), work,
                                     3, "solver <exploded> & \"died\"");
  EXPECT_EQ(r.verdict, Verdict::kExitStatus);
  EXPECT_TRUE(text_contains(r.reason, "exited with status 3"));
  EXPECT_EQ(r.stderr_tail, "solver <exploded> & \"died\"");
}

TEST(GradeScene, NoFileFails) {
  TemporaryFolder work;
  testing::set_env("ORACLE_TEST_TRAJECTORY", "");
  testing::set_env("ORACLE_TEST_EXIT", "0");
  const SceneResult r = grade_chain_with("file_copying_candidate.sh", work);
  EXPECT_EQ(r.verdict, Verdict::kNoOutput);
  EXPECT_TRUE(text_contains(r.reason, "wrote no trajectory")) << r.reason;
}

TEST(GradeScene, CrashFailsWithTheSignal) {
  TemporaryFolder work;
  const SceneResult r = grade_chain_with("crashing_candidate.sh", work);
  EXPECT_EQ(r.verdict, Verdict::kCrashed);
  EXPECT_TRUE(text_contains(r.reason, "SIGSEGV")) << r.reason;
  EXPECT_EQ(r.stderr_tail, "about to crash");
}

TEST(GradeScene, HangIsKilledAtTheTimeout) {
  TemporaryFolder work;
  GradingOptions options = options_for(testing::candidate("hanging_candidate.sh"), work);
  options.run.timeout_seconds = 0.5;
  const SceneResult r = grade_scene(chain_scene(), options);
  EXPECT_EQ(r.verdict, Verdict::kTimedOut);
  EXPECT_TRUE(text_contains(r.reason, "timeout of 0.5 s")) << r.reason;
  EXPECT_LT(r.run_seconds, 5.0);
}

TEST(GradeScene, MissingAndNonExecutableCandidatesFailEveryScene) {
  TemporaryFolder work;
  const SceneResult missing =
      grade_scene(chain_scene(), options_for(work / "no-such-simulator", work));
  EXPECT_EQ(missing.verdict, Verdict::kCannotRun);
  EXPECT_TRUE(text_contains(missing.reason, "does not exist")) << missing.reason;
  testing::write_bytes(work / "not-executable.sh", "#!/bin/sh\nexit 0\n");
  const SceneResult denied =
      grade_scene(chain_scene(), options_for(work / "not-executable.sh", work));
  EXPECT_EQ(denied.verdict, Verdict::kCannotRun);
  EXPECT_TRUE(text_contains(denied.reason, "not executable")) << denied.reason;
}

TEST(GradeScene, BrokenSceneIsASceneError) {
  TemporaryFolder work;
  testing::write_bytes(work / "broken.xml", "<scene><particle m=\"1\"/></scene>");
  const SceneResult r = grade_scene({"x/broken.xml", work / "broken.xml", false},
                                    options_for(testing::kFossSim, work));
  EXPECT_EQ(r.verdict, Verdict::kSceneError);
  EXPECT_TRUE(text_contains(r.reason, "broken.xml")) << r.reason;
}

TEST(GradeScenes, OneBadCandidateRunDoesNotStopTheBatch) {
  // The crashing candidate fails every scene, each with its reason, and all are reported.
  TemporaryFolder work;
  auto scenes = discover_scenes({testing::kAssets}, {testing::kExtraCredit});
  std::size_t finished = 0;
  const auto results =
      grade_scenes(scenes, options_for(testing::candidate("crashing_candidate.sh"), work), 2,
                   [&finished](const SceneResult&, std::size_t done, std::size_t total) {
                     EXPECT_EQ(done, ++finished);
                     EXPECT_EQ(total, 5u);
                   });
  ASSERT_EQ(results.size(), 5u);
  for (std::size_t k = 0; k < results.size(); ++k) {
    EXPECT_EQ(results[k].name, (scenes)[k].name);  // in scene order, whatever finished first
    EXPECT_EQ(results[k].verdict, Verdict::kCrashed);
  }
}

}  // namespace
}  // namespace fosssim
