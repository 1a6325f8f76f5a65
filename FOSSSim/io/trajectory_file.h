#pragma once
// The course's trajectory file (docs/command-line.md, 'Trajectory files'): frames of positions
// then velocities, as little-endian IEEE doubles, no header. Frame 0 is the initial state.
// Scenes with collisions add collision records and polynomial logs to each frame
// (docs/collisions.md, 'Trajectory files').

#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/collisions/collision_record.h"
#include "core/collisions/contact_method.h"
#include "core/collisions/polynomial.h"
#include "core/error.h"
#include "core/scene_model.h"
#include "core/state.h"
#include "io/input_files.h"
#include "io/output_file.h"

namespace fosssim {

/// What each record of a trajectory file holds (course-compatible layouts): the record layout
/// of the scene's contact method (core/collisions/contact_method.h), kFrames, kCollisions or
/// kCollisionsAndPolynomials.
using TrajectoryLayout = StepRecordLayout;

/// The layout of a model's trajectory files: its contact method's (ContactMethod::records).
TrajectoryLayout trajectory_layout(const SceneModel& model);

/// One record of a trajectory file: a state and, in the layouts that have them, collisions and
/// polynomials.
struct TrajectoryRecord {
  Vector q, v;
  std::vector<CollisionRecord> collisions;
  std::vector<Polynomial> polynomials;
};

/// Bytes of one collision record in `dim` dimensions: int32 type, int32 first, int32 second,
/// the normal's dim doubles and the time (36 bytes in 2D, as the course writes them; 44 in 3D).
inline std::int64_t collision_record_bytes(int dim) { return 12 + 8 * (dim + 1); }

/// Writes a trajectory so that an interrupted or failed run never leaves a file that looks
/// complete: frames go to a new temporary file beside it ("<path>.<random>.partial",
/// io/output_file.h), which becomes <path> only on commit(). A writer
/// destroyed without commit() keeps its frames as "<path>.incomplete" and leaves any earlier
/// file at <path> untouched. A path that is a device or FIFO (-o /dev/null) is written in
/// place, never renamed over (io/output_file.h).
class TrajectoryWriter {
 public:
  /// Creates the temporary file. Throws Error (kCannotWrite) naming the path and the system's
  /// reason, or (kBadInput) for a name that cannot be an output (io/output_file.h).
  static TrajectoryWriter open(const std::string& path);

  TrajectoryWriter(TrajectoryWriter&&) noexcept;
  TrajectoryWriter& operator=(TrajectoryWriter&&) noexcept;
  ~TrajectoryWriter();

  /// Appends state.q then state.v. Throws Error (kCannotWrite) on an I/O error (disk full).
  void write_frame(const State& state);
  /// Appends q and v, then (layout kCollisions and up) int32 count and the collisions, then
  /// (kCollisionsAndPolynomials) int32 count and the polynomials. Throws like write_frame.
  void write_record(TrajectoryLayout layout, const Vector& q, const Vector& v,
                    const std::vector<CollisionRecord>& collisions,
                    const std::vector<Polynomial>& polynomials);
  /// Appends `values` as little-endian doubles (layouts written elsewhere: io/rigid_trajectory.h).
  /// Throws like write_frame.
  void write_values(const Vector& values) {
    write_doubles(values.data(), static_cast<std::size_t>(values.size()));
  }
  /// Flushes to disk and renames the file to its final name. Throws on an I/O error.
  void commit();
  /// Closes the file and renames it to "<path>.incomplete"; returns that name ("" when nothing
  /// was written or nothing could be kept; the path itself for a device or FIFO).
  std::string abandon();

  const std::string& path() const { return path_; }

 private:
  TrajectoryWriter(std::string path, OutputFile output, std::FILE* file);
  void write_doubles(const double* data, std::size_t count);
  void write_int(std::int32_t value);
  void close_file();

  std::string path_;
  OutputFile output_;
  std::FILE* file_ = nullptr;
  bool finished_ = false;
};

/// Reads frames of a trajectory file with random access.
class TrajectoryReader {
 public:
  /// Opens a trajectory whose frames hold `dofs` positions and `dofs` velocities. Throws Error
  /// (kBadInput) when the file is missing, is not a regular file (a FIFO, a device: see
  /// open_regular_file in io/input_files.h) or its size is not a whole number of frames.
  static TrajectoryReader open(const std::string& path, int dofs);
  /// Opens a trajectory of `layout` for particles in `dim` dimensions (dofs = dim·particles).
  /// Records with collisions have no fixed size: the file is read through once to check them,
  /// and Error (kBadInput) names the record and what is wrong when the file ends inside a
  /// record, holds a negative or impossible count, or an unknown collision type.
  static TrajectoryReader open(const std::string& path, int dofs, int dim, TrajectoryLayout layout);
  /// The same for a trajectory held in memory (fuzzers, tests); `name` stands for the file in
  /// messages.
  static TrajectoryReader from_bytes(std::string bytes, int dofs, const std::string& name,
                                     int dim = 2,
                                     TrajectoryLayout layout = TrajectoryLayout::kFrames);

  /// The number of end-of-step frames, the initial state included: steps + 1.
  std::int64_t num_frames() const { return num_frames_; }
  int dofs() const { return dofs_; }
  const std::string& path() const { return path_; }
  TrajectoryLayout layout() const { return layout_; }
  /// Reads frame k (0-based: the initial state, then the end of step k) into q and v (resized
  /// to dofs). Throws Error (kBadInput) on an I/O error.
  void read_frame(std::int64_t k, Vector& q, Vector& v);
  /// Reads frame k whole: state, collisions and polynomials. A record holding more than
  /// `max_polynomials` polynomials gets only the first max_polynomials + 1 of them, enough to
  /// tell that it holds too many: a grader that knows how many to expect caps what a padded
  /// file makes it read and keep.
  void read_record(std::int64_t k, TrajectoryRecord& record,
                   std::int64_t max_polynomials = kAllPolynomials);
  /// True when the layout has a sync record for each step (kCollisionsAndPolynomials).
  bool has_sync_records() const { return layout_ == TrajectoryLayout::kCollisionsAndPolynomials; }
  /// Reads the sync record of step k ≥ 1 (written before the step's end-of-step record), its
  /// polynomials capped like read_record's.
  void read_sync_record(std::int64_t k, TrajectoryRecord& record,
                        std::int64_t max_polynomials = kAllPolynomials);
  /// No cap on the polynomials read_record reads (the file's size bounds them).
  static constexpr std::int64_t kAllPolynomials = std::numeric_limits<std::int32_t>::max();

 private:
  TrajectoryReader(std::string path, RegularFile file, int dofs, int dim, TrajectoryLayout layout);
  /// Checks the records of a layout with collisions and counts the frames.
  void check_records();
  /// The offset just past the record that starts at `at` (record number `index`), checking its
  /// counts against the file's size; throws Error (kBadInput) naming the record otherwise.
  std::int64_t record_end(std::int64_t at, std::int64_t index);
  /// The offset of record `index` (0-based over all records) in a layout with collisions.
  /// Records are found by walking from the last one read (from the start when going back), so
  /// reading in order costs one step per record and memory does not grow with the file.
  std::int64_t record_offset(std::int64_t index);
  /// Reads the record at position `index` in the file (0-based over all records), at most
  /// max_polynomials + 1 of its polynomials.
  void read_record_at(std::int64_t index, TrajectoryRecord& record,
                      std::int64_t max_polynomials = kAllPolynomials);

  std::string path_;
  std::shared_ptr<const std::string> bytes_;  ///< what file_ reads, for from_bytes
  RegularFile file_;
  int dofs_ = 0;
  int dim_ = 2;
  std::int64_t num_frames_ = 0;
  std::int64_t num_records_ = 0;
  TrajectoryLayout layout_ = TrajectoryLayout::kFrames;
  std::int64_t cursor_index_ = 0;   ///< a record whose offset is known: the last one found
  std::int64_t cursor_offset_ = 0;  ///< its offset
};

/// Opens a trajectory of `model`'s scene in the layout of its collision method.
inline TrajectoryReader open_trajectory(const std::string& path, const SceneModel& model) {
  return TrajectoryReader::open(path, model.num_dofs(), model.dim, trajectory_layout(model));
}

/// Bytes in one frame of `dofs` positions and velocities.
inline std::int64_t trajectory_frame_bytes(int dofs) {
  return 2 * static_cast<std::int64_t>(dofs) * 8;
}

}  // namespace fosssim
