#include "outputs/trajectory_output.h"

#include <cstdint>
#include <string>
#include <utility>

#include "io/rigid_trajectory.h"
#include "io/trajectory_file.h"
#include "io/trajectory_steps.h"

namespace fosssim {

namespace {

/// What an abandoned trajectory output kept: `kept` is where its frames are now (the writer's
/// abandon(): empty when nothing was written, `path` itself for a device or FIFO).
std::string trajectory_kept_note(const std::string& kept, const std::string& path,
                                 std::int64_t frames) {
  if (kept.empty()) return path + " was not written";
  if (kept == path) return "";  // a device or FIFO: the frames went there
  return "the " + std::to_string(frames) + " frames computed so far are in " + kept + " (" + path +
         " was not written)";
}

/// What both trajectory outputs share: the file's writer, the frames written so far, and how a
/// finished, described or abandoned run reports them. `Writer` has commit(), path() and
/// abandon() like TrajectoryWriter.
template <class Writer>
class CountedTrajectoryOutput : public FrameOutput {
 public:
  void commit() override { writer_.commit(); }
  std::string describe() const override {
    return "the trajectory " + writer_.path() + " (" + std::to_string(frames_) + " frames)";
  }
  std::string abandon() override {
    return trajectory_kept_note(writer_.abandon(), writer_.path(), frames_);
  }

 protected:
  explicit CountedTrajectoryOutput(Writer writer) : writer_(std::move(writer)) {}
  Writer writer_;
  std::int64_t frames_ = 0;
};

/// A particle scene's trajectory: continuous-time and hybrid steps write their sync record,
/// then their end-of-step record (docs/collisions.md).
class TrajectoryOutput final : public CountedTrajectoryOutput<TrajectoryWriter> {
 public:
  TrajectoryOutput(TrajectoryWriter writer, TrajectoryLayout layout)
      : CountedTrajectoryOutput(std::move(writer)), layout_(layout) {}
  void write(Frame& frame) override {
    write_trajectory_state(writer_, layout_, frame.state(), frame.record());
    ++frames_;
  }

 private:
  TrajectoryLayout layout_;
};

/// A rigid-body scene's trajectory: the course's Theme 3 layout.
class RigidTrajectoryOutput final : public CountedTrajectoryOutput<RigidTrajectoryWriter> {
 public:
  RigidTrajectoryOutput(TrajectoryWriter writer, const SceneModel& model)
      : CountedTrajectoryOutput(RigidTrajectoryWriter(std::move(writer), model)) {}
  void write(Frame& frame) override {
    writer_.write(frame.state());
    ++frames_;
  }
};

std::unique_ptr<FrameOutput> open_trajectory_output(const std::string& path,
                                                    const OutputContext& context) {
  const SceneModel& model = context.scene.model;
  if (model.rigid_bodies) {
    return std::make_unique<RigidTrajectoryOutput>(TrajectoryWriter::open(path), model);
  }
  return std::make_unique<TrajectoryOutput>(TrajectoryWriter::open(path),
                                            trajectory_layout(model));
}

}  // namespace

constinit const OutputFormat kTrajectoryOutput{
    .name = "trajectory",
    .flags = "-o,--output",
    .value_name = "FILE",
    .help = "Write the trajectory here (frames of positions then velocities, little-endian "
            "doubles).\n"
            "It appears only when the run completes; a failed run leaves FILE.incomplete",
    .group = "",
    .target = OutputTarget::kFile,
    .needs = {.window = true},
    .open = &open_trajectory_output,
};

}  // namespace fosssim
