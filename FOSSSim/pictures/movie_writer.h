#pragma once
// Movies through the ffmpeg program: raw frames down a pipe, H.264 in an MP4 file out.

#include <sys/types.h>

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

#include "core/error.h"
#include "io/output_file.h"
#include "pictures/image.h"

namespace fosssim {

struct MovieSettings {
  int width = 512, height = 512;  ///< pixels; both even (H.264 with 4:2:0 colour needs it)
  double fps = 30.0;              ///< frames per second of the movie
  int crf = 20;                   ///< x264 quality: 0 lossless .. 51 worst; 18-23 look good
};

/// Writes an MP4 movie (H.264, yuv420p, faststart) by running `ffmpeg` and piping it raw BGRA
/// frames. The movie is written to a temporary file beside `path` that FOSSSim creates and
/// hands to ffmpeg as an open descriptor, and renamed to `path` by commit() (see
/// io/output_file.h) only once ffmpeg succeeded and the file's MP4 boxes are whole, so a failed
/// or interrupted run, or a full disk, never leaves a file that looks complete.
/// ffmpeg runs in its own process group, so Ctrl-C reaches FOSSSim, which then stops it cleanly.
class MovieWriter {
 public:
  /// Checks the settings and the file name (must end in .mp4), finds ffmpeg on PATH and starts
  /// it. Throws Error saying what is wrong: bad settings (kBadInput); ffmpeg not installed, or no
  /// process or pipe (kCannotWrite: the movie cannot be written).
  static MovieWriter open(const std::string& path, const MovieSettings& settings);

  MovieWriter(MovieWriter&& other) noexcept;
  MovieWriter& operator=(MovieWriter&&) = delete;
  /// Abandons the movie if neither commit() nor abandon() was called.
  ~MovieWriter();

  /// Sends one frame (its size must be the settings' size). Throws Error (kCannotWrite) with
  /// ffmpeg's own message if ffmpeg has stopped.
  void write_frame(const Image& frame);
  /// Ends the movie: waits for ffmpeg and renames the file. Throws Error (kCannotWrite) with
  /// ffmpeg's message if it failed.
  void commit();
  /// Stops ffmpeg, keeps what it wrote as "<path>.incomplete" if anything, and returns that name
  /// (empty when nothing was kept).
  std::string abandon();

  const std::string& path() const { return path_; }

 private:
  MovieWriter(std::string path, OutputFile output, MovieSettings settings, pid_t pid, int pipe,
              std::FILE* log);
  /// Closes the pipe, waits for ffmpeg; returns its error message or nothing if it succeeded.
  std::optional<std::string> finish_process();

  std::string path_;
  OutputFile output_;
  MovieSettings settings_;
  pid_t pid_ = -1;
  int pipe_ = -1;
  std::FILE* log_ = nullptr;  ///< ffmpeg's standard error
  std::int64_t frames_ = 0;
  bool done_ = false;
};

/// Throws Error (kBadInput) saying why `path` and `settings` cannot make a movie (not *.mp4,
/// odd size, bad frame rate); returns when they can.
void check_movie_settings(const std::string& path, const MovieSettings& settings);

/// What is wrong with the MP4 file open as `fd`: "" when its top-level boxes cover the file
/// exactly, it starts with 'ftyp' and holds a 'moov' (a device or FIFO is not checked);
/// otherwise a phrase such as "its 'mdat' box at byte 48 is cut short".
std::string mp4_damage(int fd);

/// The full path of an executable `name` on PATH, or nothing.
std::optional<std::string> find_program(const std::string& name);

}  // namespace fosssim
