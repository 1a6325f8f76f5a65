// Tests of the step pipeline (core/step/step_pipeline.h).
//
// Checked:
// - stages run after the integrator, by phase (responses, constraints, scripts) whatever the
//   order they were added in, and in the order added within a phase; each sees the start state
//   (step n) and the state so far (step n + 1, already integrated);
// - the health check throws StepError on a non-finite state a stage leaves, and can be turned
//   off (the grader compares such states instead);
// - a solver library's failure (SolverFailure) during a step becomes a StepError naming that
//   step, so the programs report a failed step (exit 3), not bad input;
// - an interaction force handed to the pipeline acts exactly as the same force in the model
//   would, summed last: identical bits, with every integrator of the registry.

#include "core/step/step_pipeline.h"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "core/forces/drag_spring_force.h"
#include "core/solvers/solver_failure.h"
#include "core/step_error.h"
#include "support/scene_builder.h"
#include "support/typed_tests.h"

namespace fosssim::testing {
namespace {

/// Records its name and what it saw; optionally spoils the state.
class RecordingStage final : public StepStage {
 public:
  RecordingStage(std::string name, std::vector<std::string>& log, bool spoil = false)
      : name_(std::move(name)), log_(log), spoil_(spoil) {}
  void apply(const StepContext& context, State& state) override {
    log_.push_back(name_ + " " + std::to_string(context.start.step) + "->" +
                   std::to_string(state.step) +
                   (state.q == context.start.q ? " unmoved" : " moved"));
    if (spoil_) state.v[0] = std::numeric_limits<double>::quiet_NaN();
  }

 private:
  std::string name_;
  std::vector<std::string>& log_;
  bool spoil_;
};

TestScene moving_particle() {
  TestScene scene(2, "symplectic-euler", 0.1);
  scene.add_particle(1.0, vec({0.0, 0.0}), vec({1.0, 0.0}));
  return scene;
}

TEST(StepPipeline, StagesRunAfterTheIntegratorByPhaseThenInOrderAdded) {
  const TestScene scene = moving_particle();
  std::vector<std::string> log;
  StepPipeline pipeline(scene.model);
  pipeline.add_stage(StagePhase::kScript, std::make_unique<RecordingStage>("script", log));
  pipeline.add_stage(StagePhase::kResponse, std::make_unique<RecordingStage>("response1", log));
  pipeline.add_stage(StagePhase::kConstraint, std::make_unique<RecordingStage>("constraint", log));
  pipeline.add_stage(StagePhase::kResponse, std::make_unique<RecordingStage>("response2", log));
  State state = scene.initial;
  pipeline.step(state);
  const std::vector<std::string> expected = {"response1 0->1 moved", "response2 0->1 moved",
                                             "constraint 0->1 moved", "script 0->1 moved"};
  EXPECT_EQ(log, expected);
}

TEST(StepPipeline, TheHealthCheckCatchesWhatAStageSpoilsUnlessTurnedOff) {
  const TestScene scene = moving_particle();
  std::vector<std::string> log;
  StepAdditions additions;
  additions.stages.emplace_back(StagePhase::kScript,
                                std::make_unique<RecordingStage>("spoiler", log, true));
  StepPipeline pipeline(scene.model, std::move(additions));
  State state = scene.initial;
  EXPECT_THROW(pipeline.step(state), StepError);
  pipeline.set_health_check(false);
  state = scene.initial;
  EXPECT_NO_THROW(pipeline.step(state));
  EXPECT_TRUE(std::isnan(state.v[0]));
}

/// Throws what a sparse solver throws when its library gives up.
class FailingSolveStage final : public StepStage {
 public:
  void apply(const StepContext&, State&) override { throw SolverFailure("MUMPS: the solve failed"); }
};

TEST(StepPipeline, ASolverFailureIsAFailedStepNamingTheStep) {
  const TestScene scene = moving_particle();
  StepPipeline pipeline(scene.model);
  State state = scene.initial;
  pipeline.step(state);
  pipeline.step(state);
  pipeline.add_stage(StagePhase::kResponse, std::make_unique<FailingSolveStage>());
  try {
    pipeline.step(state);
    FAIL() << "expected a StepError";
  } catch (const StepError& error) {
    EXPECT_EQ(error.step(), 3);
    EXPECT_EQ(error.kind(), ErrorKind::kStepFailed);
    EXPECT_STREQ(error.what(), "step 3: MUMPS: the solve failed");
  }
}

TEST(StepPipeline, AnInteractionForceActsAsTheSameForceInTheModelWould) {
  for (const IntegratorMethod* method : all_integrators()) {
    SCOPED_TRACE(method->name);
    const auto build = [&] {
      TestScene scene(3, method->name, 0.01);
      scene.add_particle(1.0, vec({0.0, 0.0, 0.0}), vec({0.0, 0.0, 0.0}), /*fixed=*/true);
      scene.add_particle(2.0, vec({1.0, 0.0, 0.0}), vec({0.0, 0.5, 0.0}));
      scene.add_particle(1.5, vec({2.0, 0.1, 0.0}), vec({0.0, 0.0, 0.3}));
      scene.add_spring(0, 1, 40.0, 1.0);
      scene.add_spring(1, 2, 30.0, 1.0);
      scene.add_simple_gravity(vec({0.0, -9.81, 0.0}));
      return scene;
    };
    const Eigen::Vector3d target(2.5, 1.0, 0.5);
    TestScene in_model = build();
    in_model.add_force(std::make_unique<DragSpringForce>(3)).grab(2, target, 200.0);
    const TestScene outside = build();
    DragSpringForce pull(3);
    pull.grab(2, target, 200.0);
    StepAdditions additions;
    additions.interaction_forces = {&pull};
    StepPipeline with_model_force(in_model.model);
    StepPipeline with_interaction(outside.model, std::move(additions));
    State a = in_model.initial, b = outside.initial;
    for (int s = 0; s < 20; ++s) {
      with_model_force.step(a);
      with_interaction.step(b);
    }
    EXPECT_EQ(std::memcmp(a.q.data(), b.q.data(), sizeof(double) * a.q.size()), 0);
    EXPECT_EQ(std::memcmp(a.v.data(), b.v.data(), sizeof(double) * a.v.size()), 0);
    EXPECT_GT((b.q.segment(6, 3) - outside.initial.q.segment(6, 3)).norm(), 1e-3);
  }
}

// Issue 24: a caller's cancellation reaches the iterations inside a step. The question counts
// how often it is asked and says yes at the 10th time: every integrator that iterates asks once
// per iteration, so the step ends within its iterations (a step of 1000 iterations that ran to
// the end would have asked 1000 times), throwing StepCancelled.
int g_questions = 0;
bool yes_at_the_tenth_question() { return ++g_questions >= 10; }

TEST(StepPipeline, ACancellationEndsAStepWithinItsIterations) {
  for (const char* method : {"local-global", "quasi-newton"}) {
    TestScene scene = cloth(6, 1000.0, method, 0.01);
    scene.model.integrator.options.set("iterations", 1000.0);
    scene.model.integrator.options.set("tolerance", 0.0);  // never converged: all 1000 run
    StepAdditions additions;
    additions.cancellation = Cancellation(&yes_at_the_tenth_question);
    StepPipeline pipeline(scene.model, std::move(additions));
    State state = scene.initial;
    g_questions = 0;
    EXPECT_THROW(pipeline.step(state), StepCancelled) << method;
    EXPECT_EQ(g_questions, 10) << method;
  }
  // Without one, nothing cancels.
  TestScene scene = cloth(6, 1000.0, "local-global", 0.01);
  StepPipeline pipeline(scene.model);
  State state = scene.initial;
  EXPECT_NO_THROW(pipeline.step(state));
}

}  // namespace
}  // namespace fosssim::testing
