#include "viewer/throttle.h"

#include <gtest/gtest.h>

namespace fosssim {
namespace {

// Times are multiples of 1/256 s and the rate 128 steps/s, so every product is exact.

TEST(Throttle, LetsThroughStepsAtItsRate) {
  Throttle throttle(128.0);
  throttle.restart(10.0);
  EXPECT_EQ(throttle.take_due(10.0), 0);
  EXPECT_EQ(throttle.take_due(10.0 + 7.0 / 256), 3);  // 3.5 due
  EXPECT_EQ(throttle.take_due(10.0 + 8.0 / 256), 1);  // the half left over and half a step more
  std::int64_t total = 4;
  for (int k = 9; k <= 256; ++k) total += throttle.take_due(10.0 + k / 256.0);
  EXPECT_EQ(total, 128);  // one wall second
}

TEST(Throttle, DoesNotBuildABacklogWhenTheWindowFallsBehind) {
  Throttle throttle(128.0, 0.25);
  throttle.restart(0.0);
  EXPECT_EQ(throttle.take_due(5.0), 32);  // at most 0.25 s worth
  EXPECT_EQ(throttle.take_due(5.0), 0);
}

TEST(Throttle, SlowRatesStillStep) {
  Throttle throttle(2.0);
  throttle.restart(0.0);
  EXPECT_EQ(throttle.take_due(0.25), 0);
  EXPECT_EQ(throttle.take_due(0.5), 1);
}

TEST(Throttle, RestartForgetsTheTimePaused) {
  Throttle throttle(128.0, 10.0);
  throttle.restart(0.0);
  throttle.restart(50.0);
  EXPECT_EQ(throttle.take_due(50.0 + 5.0 / 128), 5);
}

}  // namespace
}  // namespace fosssim
