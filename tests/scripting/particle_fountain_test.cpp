#include "scripting/particle_fountain.h"

#include <gtest/gtest.h>

#include <set>

namespace fosssim {
namespace {

SceneModel model_of(int dim, int particles) {
  SceneModel model;
  model.dim = dim;
  model.mass = Vector::Ones(dim * particles);
  model.fixed.assign(particles, false);
  return model;
}

TEST(HashedUniform, IsInTheUnitIntervalAndDependsOnEveryArgument) {
  std::set<double> seen;
  for (int step = 0; step < 50; ++step) {
    for (int p = 0; p < 4; ++p) {
      for (int c = 0; c < 2; ++c) {
        const double u = hashed_uniform(7, step, p, c);
        EXPECT_GE(u, 0.0);
        EXPECT_LT(u, 1.0);
        seen.insert(u);
      }
    }
  }
  EXPECT_EQ(seen.size(), 400u);  // no collisions among 400 draws
  EXPECT_EQ(hashed_uniform(7, 3, 1, 0), hashed_uniform(7, 3, 1, 0));
  EXPECT_NE(hashed_uniform(7, 3, 1, 0), hashed_uniform(8, 3, 1, 0));
}

TEST(HashedUniform, LooksUniform) {
  // Mean and variance of 20,000 draws against 1/2 and 1/12 (standard errors ~0.002).
  double sum = 0.0, sum_squares = 0.0;
  const int n = 20000;
  for (int k = 0; k < n; ++k) {
    const double u = hashed_uniform(1, k, k % 7, 1);
    sum += u;
    sum_squares += u * u;
  }
  const double mean = sum / n;
  EXPECT_NEAR(mean, 0.5, 0.01);
  EXPECT_NEAR(sum_squares / n - mean * mean, 1.0 / 12.0, 0.005);
}

/// Applies the fountain as the step pipeline would at the end of `state`'s step.
void apply(ParticleFountain& fountain, const SceneModel& model, State& state) {
  const State start = state;
  StepRecord record;
  fountain.apply(StepContext{model, start, model.integrator.dt, record, {}}, state);
}

TEST(ParticleFountain, TeleportsTaggedParticlesBelowTheFloorToTheOriginGoingUp) {
  const SceneModel model = model_of(2, 3);
  ParticleFountain fountain({0, 2});
  State state;
  state.q.resize(6);
  state.q << 0.3, -1.3, 0.4, -1.4, 0.5, -1.2;  // 0 below (tagged), 1 below (untagged), 2 above
  state.v = Vector::Constant(6, -2.0);
  state.step = 17;
  apply(fountain, model, state);

  EXPECT_EQ(state.q.segment<2>(0), Vector::Zero(2));
  const Vector launched = state.v.segment<2>(0);
  EXPECT_EQ(launched, fountain.launch_velocity(2, 17, 0));
  EXPECT_GE(launched[0], -ParticleFountain::kMaxSidewaysSpeed);
  EXPECT_LT(launched[0], ParticleFountain::kMaxSidewaysSpeed);
  EXPECT_GE(launched[1], ParticleFountain::kMinUpwardSpeed);
  EXPECT_LT(launched[1], ParticleFountain::kMaxUpwardSpeed);
  // The untagged particle and the one above the floor are untouched.
  EXPECT_DOUBLE_EQ(state.q[2], 0.4);
  EXPECT_DOUBLE_EQ(state.q[3], -1.4);
  EXPECT_DOUBLE_EQ(state.v[2], -2.0);
  EXPECT_DOUBLE_EQ(state.q[5], -1.2);
  EXPECT_DOUBLE_EQ(state.v[5], -2.0);
}

TEST(ParticleFountain, TheFloorItselfIsNotBelowIt) {
  const SceneModel model = model_of(2, 1);
  ParticleFountain fountain({0});
  State state;
  state.q = Vector::Constant(2, ParticleFountain::kFloorHeight);
  state.v = Vector::Zero(2);
  apply(fountain, model, state);
  EXPECT_DOUBLE_EQ(state.q[1], ParticleFountain::kFloorHeight);
}

TEST(ParticleFountain, LaunchVelocityDependsOnlyOnStepAndParticle) {
  const ParticleFountain a({0}), b({0});
  EXPECT_EQ(a.launch_velocity(2, 5, 0), b.launch_velocity(2, 5, 0));
  EXPECT_NE(a.launch_velocity(2, 5, 0), a.launch_velocity(2, 6, 0));
  EXPECT_NE(a.launch_velocity(2, 5, 0), a.launch_velocity(2, 5, 1));
  const ParticleFountain other_seed({0}, 99);
  EXPECT_NE(a.launch_velocity(2, 5, 0), other_seed.launch_velocity(2, 5, 0));
}

TEST(ParticleFountain, WorksInThreeDimensionsWithYUp) {
  const SceneModel model = model_of(3, 1);
  ParticleFountain fountain({0});
  State state;
  state.q = Vector(3);
  state.q << 0.2, -2.0, 0.7;
  state.v = Vector::Zero(3);
  apply(fountain, model, state);
  EXPECT_EQ(state.q, Vector::Zero(3));
  EXPECT_GE(state.v[1], ParticleFountain::kMinUpwardSpeed);
  EXPECT_GE(state.v[2], -ParticleFountain::kMaxSidewaysSpeed);
  EXPECT_LT(state.v[2], ParticleFountain::kMaxSidewaysSpeed);
}

}  // namespace
}  // namespace fosssim
