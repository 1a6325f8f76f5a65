#pragma once
// The course's trajectory file (docs/command-line.md, 'Trajectory files'): frames of positions
// then velocities, as little-endian IEEE doubles, no header. Frame 0 is the initial state.

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "core/error.h"
#include "core/state.h"
#include "io/input_files.h"
#include "io/output_file.h"

namespace fosssim {

/// Writes a trajectory so that an interrupted or failed run never leaves a file that looks
/// complete: frames go to "<path>.partial", which becomes <path> only on commit(). A writer
/// destroyed without commit() keeps its frames as "<path>.incomplete" and leaves any earlier
/// file at <path> untouched. A path that is a device or FIFO (-o /dev/null) is written in
/// place, never renamed over (io/output_file.h).
class TrajectoryWriter {
 public:
  /// Creates "<path>.partial". Throws Error (kCannotWrite) naming the path and the system's
  /// reason.
  static TrajectoryWriter open(const std::string& path);

  TrajectoryWriter(TrajectoryWriter&&) noexcept;
  TrajectoryWriter& operator=(TrajectoryWriter&&) noexcept;
  ~TrajectoryWriter();

  /// Appends state.q then state.v. Throws Error (kCannotWrite) on an I/O error (disk full).
  void write_frame(const State& state);
  /// Flushes to disk and renames the file to its final name. Throws on an I/O error.
  void commit();
  /// Closes the file and renames it to "<path>.incomplete"; returns that name.
  std::string abandon();

  const std::string& path() const { return path_; }

 private:
  TrajectoryWriter(std::string path, OutputFile output, std::FILE* file);
  void write_doubles(const double* data, std::size_t count);
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
  /// The same for a trajectory held in memory (fuzzers, tests); `name` stands for the file in
  /// messages.
  static TrajectoryReader from_bytes(std::string bytes, int dofs, const std::string& name);

  std::int64_t num_frames() const { return num_frames_; }
  int dofs() const { return dofs_; }
  const std::string& path() const { return path_; }
  /// Reads frame k (0-based) into q and v (resized to dofs). Throws Error (kBadInput) on an I/O
  /// error.
  void read_frame(std::int64_t k, Vector& q, Vector& v);

 private:
  TrajectoryReader(std::string path, RegularFile file, int dofs);

  std::string path_;
  std::shared_ptr<const std::string> bytes_;  ///< what file_ reads, for from_bytes
  RegularFile file_;
  int dofs_ = 0;
  std::int64_t num_frames_ = 0;
};

/// Bytes in one frame of `dofs` positions and velocities.
inline std::int64_t trajectory_frame_bytes(int dofs) {
  return 2 * static_cast<std::int64_t>(dofs) * 8;
}

}  // namespace fosssim
