#pragma once
// The outputs of one run, fed together: what the registry's formats make of a command line.

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "outputs/output_registry.h"

namespace fosssim {

/// Throws Error (kBadInput) naming the option when `format` cannot be written for `scene`
/// (OutputNeeds: its dimension, particles or rigid bodies), before anything is opened.
void check_needs(const OutputFormat& format, const Scene& scene);

/// The outputs a run writes, in registry order.
class FrameOutputs {
 public:
  FrameOutputs() = default;
  /// Opens every output of `requests` for a run of `scene`, after check_needs() of each.
  /// Throws Error: kBadInput from check_needs; kCannotWrite for an unwritable file or folder,
  /// no ffmpeg for --movie.
  static FrameOutputs open(const Scene& scene, std::span<const OutputRequest> requests,
                           const OutputSettings& settings);

  bool empty() const { return outputs_.empty(); }
  /// Feeds every output the next state, the record of the step that produced it (null for the
  /// initial state) and the run's integrator (null when there is none to report on).
  void write(const State& state, const SceneView& view, const StepRecord* record = nullptr,
             const Integrator* integrator = nullptr);
  void commit();
  /// After commit(): what was written and where, one phrase per output ("the trajectory
  /// out.bin (101 frames)"), joined as a sentence; "" when there were no outputs.
  std::string describe() const;
  /// Abandons every output; returns their notes joined with "; " (may be empty).
  std::string abandon();

 private:
  std::vector<std::unique_ptr<FrameOutput>> outputs_;
};

}  // namespace fosssim
