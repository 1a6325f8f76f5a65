#pragma once
// Everything a run writes besides what it prints: trajectory, pictures, movie, energy.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/options.h"
#include "core/scene.h"
#include "core/step/step_record.h"
#include "pictures/image.h"
#include "render/drawing.h"
#include "render/scene_view.h"

namespace fosssim {

/// One state to write, with its picture composed and rendered at most once however many
/// outputs want it.
class Frame {
 public:
  /// `view` draws the state as the run's pictures show it; `record` is what the step that
  /// produced the state reported (null for the initial state).
  Frame(const State& state, const SceneView& view, const StepRecord* record = nullptr)
      : state_(state), view_(view), record_(record) {}
  const State& state() const { return state_; }
  /// The step's collisions, polynomials and sync point; null for the initial state.
  const StepRecord* record() const { return record_; }
  const Drawing& drawing();
  const Image& image();

 private:
  const State& state_;
  const SceneView& view_;
  const StepRecord* record_;
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

/// The outputs a command line asks for, fed together.
class FrameOutputs {
 public:
  /// Opens every output of `options` (-o, -g, -m, --movie, --energy-plot, --energy-csv) for a
  /// run of `scene`. Throws Error (kCannotWrite): an unwritable file or folder, no ffmpeg for
  /// --movie.
  static FrameOutputs open(const Scene& scene, const Options& options);

  bool empty() const { return outputs_.empty(); }
  /// Feeds every output the next state and the record of the step that produced it (null for
  /// the initial state).
  void write(const State& state, const SceneView& view, const StepRecord* record = nullptr);
  void commit();
  /// After commit(): what was written and where, one phrase per output ("the trajectory
  /// out.bin (101 frames)"), joined as a sentence; "" when there were no outputs.
  std::string describe() const;
  /// Abandons every output; returns their notes joined with "; " (may be empty).
  std::string abandon();

 private:
  std::vector<std::unique_ptr<FrameOutput>> outputs_;
};

/// The movie stride --movie-stride gives, or the one that plays the run at about real time:
/// max(1, round(1 / (fps · dt))).
int movie_stride(const Options& options, double dt);

/// The colouring of elastic bodies that --color-by and --color-scale ask for.
ElementColors element_colors(const Options& options);

}  // namespace fosssim
