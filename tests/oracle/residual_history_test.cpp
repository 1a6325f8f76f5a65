// The oracle's per-step residual history (oracle/src/residual_history.h): which steps it counts
// as failing a maximum limit, under the scene's criteria.
//
// Checked: positions are held to criteria.maximum_limit and velocities to
// criteria.maximum_velocity_limit (Theme 4: 1e-9), strictly, NaN failing; the largest single
// residual and its step.

#include "residual_history.h"

#include <gtest/gtest.h>

#include <limits>

namespace fosssim {
namespace {

StepResidual residual(std::int64_t step, double position, double velocity) {
  StepResidual r;
  r.step = step;
  r.max_position = position;
  r.max_velocity = velocity;
  return r;
}

/// Steps 1..5: velocities 5e-10 (passes Theme 4 only), 1e-9 (fails both: the criterion is
/// strict), 2e-12, then a position of 1e-10 (fails both), then all small.
ResidualHistory history_of(const GradingCriteria& criteria) {
  ResidualHistory history(5, 0.01, criteria, /*keep_table=*/false);
  history.add(residual(1, 0.0, 5e-10));
  history.add(residual(2, 1e-12, 1e-9));
  history.add(residual(3, 0.0, 2e-12));
  history.add(residual(4, 1e-10, 0.0));
  history.add(residual(5, 3e-11, 3e-11));
  return history;
}

TEST(ResidualHistory, HoldsVelocitiesToTheThemeFourVelocityLimit) {
  const ResidualHistory theme4 = history_of(kTheme4Criteria);
  EXPECT_EQ(theme4.steps_over_limit(), 2);
  EXPECT_EQ(theme4.first_step_over_limit(), 2);
  EXPECT_EQ(theme4.last_step_over_limit(), 4);
  EXPECT_EQ(theme4.worst_residual(), 1e-9);
  EXPECT_EQ(theme4.worst_step(), 2);
}

TEST(ResidualHistory, HoldsVelocitiesToTheThemeOneLimitForThemeOneScenes) {
  const ResidualHistory theme1 = history_of(GradingCriteria{});
  EXPECT_EQ(theme1.steps_over_limit(), 3);
  EXPECT_EQ(theme1.first_step_over_limit(), 1);
  EXPECT_EQ(theme1.last_step_over_limit(), 4);
}

TEST(ResidualHistory, ANanVelocityFailsEveryLimit) {
  ResidualHistory history(2, 0.01, kTheme4Criteria, /*keep_table=*/false);
  history.add(residual(1, 0.0, std::numeric_limits<double>::quiet_NaN()));
  history.add(residual(2, 0.0, 0.0));
  EXPECT_EQ(history.steps_over_limit(), 1);
  EXPECT_EQ(history.first_step_over_limit(), 1);
}

}  // namespace
}  // namespace fosssim
