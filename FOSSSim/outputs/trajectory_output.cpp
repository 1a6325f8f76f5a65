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

/// A particle scene's trajectory: continuous-time and hybrid steps write their sync record,
/// then their end-of-step record (docs/collisions.md).
class TrajectoryOutput final : public FrameOutput {
 public:
  TrajectoryOutput(TrajectoryWriter writer, TrajectoryLayout layout)
      : writer_(std::move(writer)), layout_(layout) {}
  void write(Frame& frame) override {
    write_trajectory_state(writer_, layout_, frame.state(), frame.record());
    ++frames_;
  }
  void commit() override { writer_.commit(); }
  std::string describe() const override {
    return "the trajectory " + writer_.path() + " (" + std::to_string(frames_) + " frames)";
  }
  std::string abandon() override {
    return trajectory_kept_note(writer_.abandon(), writer_.path(), frames_);
  }

 private:
  TrajectoryWriter writer_;
  TrajectoryLayout layout_;
  std::int64_t frames_ = 0;
};

/// A rigid-body scene's trajectory: the course's Theme 3 layout.
class RigidTrajectoryOutput final : public FrameOutput {
 public:
  RigidTrajectoryOutput(TrajectoryWriter writer, const SceneModel& model)
      : writer_(std::move(writer), model) {}
  void write(Frame& frame) override {
    writer_.write(frame.state());
    ++frames_;
  }
  void commit() override { writer_.commit(); }
  std::string describe() const override {
    return "the trajectory " + writer_.path() + " (" + std::to_string(frames_) + " frames)";
  }
  std::string abandon() override {
    return trajectory_kept_note(writer_.abandon(), writer_.path(), frames_);
  }

 private:
  RigidTrajectoryWriter writer_;
  std::int64_t frames_ = 0;
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
