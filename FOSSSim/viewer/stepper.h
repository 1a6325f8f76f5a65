#pragma once
// What the window advances: a simulation, or a grading replay of a trajectory file.

#include <memory>
#include <optional>

#include "core/scene.h"
#include "core/step/simulation.h"
#include "grading/step_grader.h"
#include "render/drawing.h"

namespace fosssim {

/// One step at a time, with what the window should show of it.
class Stepper {
 public:
  virtual ~Stepper() = default;
  /// The state to show.
  virtual const State& state() const = 0;
  /// True when there are no more steps.
  virtual bool finished() const = 0;
  /// Takes one step. Throws StepError when it cannot be taken.
  virtual void step() = 0;
  /// Marks and status lines to draw over the state.
  virtual Overlay overlay() const { return {}; }
};

/// Runs the scene: its step pipeline with its tag's scripted hook, as a headless run does,
/// plus the window's interaction forces (the drag spring of ParticleGrab).
class SimulationStepper final : public Stepper {
 public:
  /// The scene and the interaction forces must outlive the stepper. `cancellation` lets the
  /// caller end a step in progress (step() then throws StepCancelled).
  explicit SimulationStepper(const Scene& scene, std::vector<const Force*> interaction_forces = {},
                             Cancellation cancellation = {});
  const State& state() const override { return simulation_.state(); }
  bool finished() const override { return simulation_.finished(); }
  void step() override { simulation_.step(); }
  const Simulation& simulation() const { return simulation_; }

 private:
  Simulation simulation_;
};

/// Colours of the grading marks.
inline constexpr Color kDisagreeColor{0.9, 0.0, 0.0};  ///< kDisagreeFactor times a limit or more
inline constexpr Color kFailColor{1.0, 0.6, 0.0};      ///< fails its limit, by less than that
/// A particle whose position or velocity residual exceeds this many times its limit is ringed
/// in kDisagreeColor.
inline constexpr double kDisagreeFactor = 10.0;

/// Replays a trajectory file step by step against the scene (grading mode, docs/viewing.md) and
/// shows the file's frames. A particle whose step residual fails the scene's criteria
/// (criteria_for: position residual at least the maximum limit, 1e-10, or velocity residual at
/// least the maximum velocity limit, 1e-10 for Theme 1 scenes and 1e-9 for Theme 4 ones) gets
/// an orange ring, a red one when either residual exceeds ten times its limit.
class GradingStepper final : public Stepper {
 public:
  explicit GradingStepper(StepGrader grader) : grader_(std::move(grader)) {}
  const State& state() const override { return grader_.file_state(); }
  bool finished() const override { return grader_.finished(); }
  void step() override;
  Overlay overlay() const override;

  const StepGrader& grader() const { return grader_; }

 private:
  StepGrader grader_;
};

/// The marks of one graded step: for every particle whose position residual is at least
/// criteria.maximum_limit or whose velocity residual is at least
/// criteria.maximum_velocity_limit (or NaN), a ring: kDisagreeColor beyond kDisagreeFactor
/// times the limit (or NaN), kFailColor otherwise.
std::vector<ParticleMark> grading_marks(const std::vector<double>& position_residuals,
                                        const std::vector<double>& velocity_residuals,
                                        const GradingCriteria& criteria);

}  // namespace fosssim
