#pragma once
// The course's Theme 3 trajectory file (docs/rigid-bodies.md, 'Trajectory files'): per frame
// each body's state, the derived quantities, and in frame 0 the bodies' mass properties.
//
// Little-endian doubles, no header. B bodies, K steps:
//   frame 0:  state (6B: per body X_x X_y θ V_x V_y ω), start block (4B: all M, all X as
//             pairs, all I), quantities (6B + 1)
//   frame k:  state (6B), quantities (6B + 1)
//   quantities: all P as pairs, all L_cm, all L_spin, all T_cm, all T_spin, then U.
// Total 8 (4B + (K + 1)(12B + 1)) bytes.

#include <cstdint>
#include <string>

#include "core/force_set.h"
#include "core/scene_model.h"
#include "core/state.h"
#include "io/input_files.h"
#include "io/trajectory_file.h"

namespace fosssim {

/// Bytes of a Theme 3 trajectory of `bodies` bodies and `steps` steps.
std::int64_t rigid_trajectory_bytes(int bodies, std::int64_t steps);

/// The state block of one frame (6B): positions and angles, then the reported velocities
/// (a fixed body's declared velocity; core/rigid/rigid_bodies.h).
Vector rigid_state_block(const SceneModel& model, const State& state);
/// The start block (4B): every M, every initial X (pairs), every I.
Vector rigid_start_block(const SceneModel& model);
/// The quantities block (6B + 1) of a state; U sums `forces`' energies in their order.
Vector rigid_quantities_block(const ForceSet& forces, const Vector& q, const Vector& v);

/// Writes a Theme 3 trajectory: frame 0 with its start block, then one frame per step.
class RigidTrajectoryWriter {
 public:
  RigidTrajectoryWriter(TrajectoryWriter writer, const SceneModel& model);
  /// Appends the frame of `state` (the start block after the first).
  void write(const State& state);
  void commit() { writer_.commit(); }
  std::string abandon() { return writer_.abandon(); }
  const std::string& path() const { return writer_.path(); }

 private:
  TrajectoryWriter writer_;
  const SceneModel* model_;
  ForceSet forces_;
  bool wrote_first_ = false;
};

/// One frame of a Theme 3 trajectory as read back.
struct RigidFrame {
  Vector state;       ///< 6B
  Vector start;       ///< 4B, frame 0 only
  Vector quantities;  ///< 6B + 1
};

/// Reads a Theme 3 trajectory with random access.
class RigidTrajectoryReader {
 public:
  /// Opens `path` for a scene of `bodies` bodies and `steps` steps. Throws Error (kBadInput)
  /// unless the file is a regular file of exactly rigid_trajectory_bytes(bodies, steps) bytes
  /// (the course's grader does not check; a file cut short by a few bytes would pass it).
  static RigidTrajectoryReader open(const std::string& path, int bodies, std::int64_t steps);
  /// Frame k of 0..steps. Throws Error (kBadInput) on an I/O error.
  RigidFrame read_frame(std::int64_t k);
  const std::string& path() const { return path_; }

 private:
  RigidTrajectoryReader(std::string path, RegularFile file, int bodies)
      : path_(std::move(path)), file_(std::move(file)), bodies_(bodies) {}
  void read_doubles(std::int64_t offset_doubles, Vector& out);

  std::string path_;
  RegularFile file_;
  int bodies_;
};

/// The state a frame's state block describes: q, and v with 0 for fixed bodies (they never
/// move; the block's velocity of a fixed body is what it reports, compared by grading).
State rigid_state_from_block(const SceneModel& model, const Vector& block);

}  // namespace fosssim
