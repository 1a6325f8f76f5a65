// Tests of the limits on what a run may ask for (core/limits.h) and of step counts that do not
// fit an integer (SceneModel::num_steps saturates instead of overflowing).
//
// Checked: check_step_count accepts a count at the limit and refuses one above it, naming the
// count, the limit and --max-steps; a duration/dt that overflows a double (1e300 / 1e-300,
// a subnormal dt) is refused with its own message instead of becoming "0 steps";
// saturating_product saturates instead of overflowing.

#include "core/limits.h"

#include <gtest/gtest.h>

#include <limits>

#include "core/scene_model.h"
#include "support/thrown.h"

namespace fosssim {
namespace {

SceneModel model_of(double duration, double dt) {
  SceneModel model;
  model.duration = duration;
  model.integrator.dt = dt;
  return model;
}

TEST(StepCount, AtTheLimitIsAcceptedAndAboveItRefusedNamingTheOption) {
  Limits limits;
  limits.max_steps = 100;
  check_step_count(model_of(1.0, 0.01), limits);  // exactly 100 steps
  const Error error = thrown_by([&] { check_step_count(model_of(1.01, 0.01), limits); });
  EXPECT_EQ(error.kind(), ErrorKind::kBadInput);
  EXPECT_STREQ(error.what(),
               "duration 1.01 s at dt 0.01 s takes 101 steps, more than the limit of 100 steps "
               "(raise it with --max-steps N)");
}

TEST(StepCount, ARatioBeyondEveryIntegerIsRefusedNotTurnedIntoZeroSteps) {
  for (const auto& [duration, dt] :
       {std::pair{1e300, 1e-300}, std::pair{5.0, 1e-320}, std::pair{1e300, 1e-5}}) {
    const SceneModel model = model_of(duration, dt);
    EXPECT_EQ(model.num_steps(), SceneModel::kMaxStepCount) << duration << " / " << dt;
    const Error error = thrown_by([&] { check_step_count(model, Limits{}); });
    EXPECT_EQ(error.kind(), ErrorKind::kBadInput);
    EXPECT_NE(std::string(error.what()).find("duration"), std::string::npos) << error.what();
  }
  const Error overflow = thrown_by([] { check_step_count(model_of(5.0, 1e-320), Limits{}); });
  EXPECT_STREQ(overflow.what(),
               "duration 5 s at dt 1e-320 s: duration / dt overflows, more steps than a double "
               "can count; use a larger dt or a shorter duration");
}

TEST(StepCount, LargeButCountableRatiosAreCountedExactly) {
  const SceneModel model = model_of(4e9, 1.0);
  EXPECT_EQ(model.num_steps(), 4'000'000'000);  // beyond int, within int64
  const Error error = thrown_by([&] { check_step_count(model, Limits{}); });
  EXPECT_NE(std::string(error.what()).find("takes 4000000000 steps"), std::string::npos)
      << error.what();
}

TEST(SaturatingProduct, SaturatesInsteadOfOverflowing) {
  constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
  EXPECT_EQ(saturating_product({2001, 2001, 2001}), 8'012'006'001);
  EXPECT_EQ(saturating_product({100000, 100000, 100000, 100000}), kMax);
  EXPECT_EQ(saturating_product({kMax, 2}), kMax);
  EXPECT_EQ(saturating_product({kMax, 2, 0}), 0);
  EXPECT_EQ(saturating_product({}), 1);
}

}  // namespace
}  // namespace fosssim
