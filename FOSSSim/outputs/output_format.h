#pragma once
// What the output registry knows of one output format: its command-line option, what it needs
// and its factory. Each format's file pair defines its entry; output_registry.cpp lists them.

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "core/scene.h"
#include "outputs/frame_output.h"
#include "pictures/movie_writer.h"

namespace fosssim {

/// What an output's option names.
enum class OutputTarget {
  kFile,    ///< one file, written through io/output_file (never a half-written file)
  kFolder,  ///< a folder of pictures frame_<step>.<extension>, each written whole
};

/// What a format needs and does, for the checks before a run and for the tests.
struct OutputNeeds {
  bool runs_2d = true;           ///< accepts <scene dim="2">
  bool runs_3d = true;           ///< accepts <scene dim="3">
  bool particles = true;         ///< accepts particle scenes
  bool rigid_bodies = true;      ///< accepts rigid-body scenes (<simtype type="rigid-body"/>)
  bool pictures = false;         ///< draws states: the pictures' camera frames the run (--frame)
  bool window = true;            ///< may be written by a run in the window (-d 1)
  bool with_grading = false;     ///< may be given with -i (otherwise refused)
};

/// The run-wide settings a factory may read (the command line's --size, --fps, ...).
struct OutputSettings {
  MovieSettings movie;              ///< picture size and frame rate (--size, --fps)
  std::optional<int> movie_stride;  ///< --movie-stride; nothing: about real time
};

/// Everything a factory is given besides the destination.
struct OutputContext {
  const Scene& scene;
  const OutputSettings& settings;
};

/// One entry of the output registry (outputs/output_registry.h).
struct OutputFormat {
  std::string_view name = {};  ///< for tests and messages: "trajectory", "movie", ...
  /// The option naming the destination, as CLI11 declares it: "-o,--output". Its first name is
  /// the one messages use ("-o x and --energy-csv x name the same file").
  std::string_view flags = {};
  std::string_view value_name = {};  ///< "FILE", "DIR"
  std::string_view help = {};        ///< for --help; may span lines
  /// The --help group: "" for the main options, else the group's title.
  std::string_view group = {};
  OutputTarget target = OutputTarget::kFile;
  /// Of a kFolder output: the extension of its pictures ("png").
  std::string_view picture_extension = {};
  /// The course's -g: an option "0|1" that asks for the output, written to the destination of
  /// `flags`, which then has a default (default_destination). Empty for outputs that are asked
  /// for by naming their destination. Its first name is the one messages about inputs use.
  std::string_view switch_flags = {};
  std::string_view switch_help = {};
  std::string_view default_destination = {};
  /// Of an output the window cannot write (needs.window false): why, after "<flag> ", in the
  /// refusal of -d 1; when -d is not given, such an output makes the run headless.
  std::string_view headless_reason = {};
  OutputNeeds needs = {};
  /// Throws Error (kBadInput) when the destination and settings cannot make this output
  /// (a movie not named *.mp4, say); null when anything goes.
  void (*check)(const std::string& destination, const OutputSettings& settings) = nullptr;
  /// Opens the output for a run of context.scene. Throws Error (kCannotWrite) when it cannot be
  /// written (an unwritable folder, no ffmpeg).
  std::unique_ptr<FrameOutput> (*open)(const std::string& destination,
                                       const OutputContext& context) = nullptr;

  /// The first name of `flags` ("-o").
  std::string_view option_name() const { return first_name(flags); }
  /// The first name of `switch_flags` when there is one, else option_name() ("-g", "-m").
  std::string_view request_name() const {
    return switch_flags.empty() ? option_name() : first_name(switch_flags);
  }

 private:
  static std::string_view first_name(std::string_view names) {
    return names.substr(0, names.find(','));
  }
};

}  // namespace fosssim
