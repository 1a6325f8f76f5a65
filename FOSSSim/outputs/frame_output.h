#pragma once
// What every output format implements: it is fed each state of a run, then committed or
// abandoned (outputs/output_format.h says how a format is registered).

#include <optional>
#include <string>

#include "core/state.h"
#include "core/step/step_record.h"
#include "pictures/image.h"
#include "render/drawing.h"
#include "render/scene_view.h"

namespace fosssim {

class Integrator;

/// One state to write, with its picture composed and rendered at most once however many
/// outputs want it.
class Frame {
 public:
  /// `view` draws the state as the run's pictures show it; `record` is what the step that
  /// produced the state reported (null for the initial state); `integrator` is the run's, for
  /// outputs that report what its solvers did (null when the caller has none to show).
  Frame(const State& state, const SceneView& view, const StepRecord* record = nullptr,
        const Integrator* integrator = nullptr)
      : state_(state), view_(view), record_(record), integrator_(integrator) {}
  const State& state() const { return state_; }
  /// The step's collisions, polynomials and sync point; null for the initial state.
  const StepRecord* record() const { return record_; }
  /// The run's integrator, or null.
  const Integrator* integrator() const { return integrator_; }
  const Drawing& drawing();
  const Image& image();

 private:
  const State& state_;
  const SceneView& view_;
  const StepRecord* record_;
  const Integrator* integrator_;
  std::optional<Drawing> drawing_;
  std::optional<Image> image_;
};

/// Receives every state of a run in order: the initial state, then one per step. Outputs
/// appear whole or not at all: commit() makes them final, abandon() keeps what a stopped run
/// produced under a name that says so.
class FrameOutput {
 public:
  virtual ~FrameOutput() = default;
  /// Takes the next state. Throws Error (kCannotWrite) on an I/O error.
  virtual void write(Frame& frame) = 0;
  /// The run reached its end. Throws Error (kCannotWrite) on an I/O error.
  virtual void commit() = 0;
  /// What a committed output holds and where, for the user: "the movie run.mp4 (151 frames)".
  virtual std::string describe() const = 0;
  /// The run stopped early; returns a note on what was kept ("out.bin.incomplete holds the 12
  /// frames computed"), or "" when there is nothing to say.
  virtual std::string abandon() = 0;
};

}  // namespace fosssim
