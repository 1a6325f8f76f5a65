#pragma once
// The FOSSSim command line: the course's flags plus our own.

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/limits.h"
#include "core/scene.h"
#include "outputs/output_registry.h"
#include "pictures/movie_writer.h"
#include "render/drawing.h"

namespace fosssim {

struct Options {
  std::string scene;               ///< -s
  int display = 1;                 ///< -d 0|1
  int paused = 1;                  ///< -p 0|1
  std::string input;               ///< -i trajectory to grade
  /// The outputs of the output registry (-o, -g, -m, --movie, ...): one option each, declared
  /// from the registry (outputs/output_registry.h).
  OutputChoices outputs;
  std::optional<double> duration;  ///< --duration override, seconds
  std::optional<double> dt;        ///< --dt override, seconds
  /// --integrator-option NAME=VALUE, in order; --newton-max-iterations N and
  /// --newton-tolerance TOL are shorthands for two of them.
  std::vector<std::string> integrator_options;
  std::string residual_file = "residual.txt";
  bool check_derivatives = false;
  int threads = 1;  ///< --threads: of the BLAS behind the sparse solvers
  bool quiet = false;
  std::string progress = "auto";  ///< --progress auto|bar|lines|off
  double progress_every = 10.0;   ///< --progress-every SECONDS between progress lines

  // Pictures (docs/viewing.md).
  std::optional<int> movie_stride;  ///< every how many steps a movie frame; default ~real time
  double fps = 30.0;                ///< movie frames per second
  std::string size = "512x512";     ///< --size WxH of the window, pictures and movie
  int width = 512, height = 512;    ///< parsed from size by check_picture_options
  std::string view;                 ///< --view YAW,PITCH[,DISTANCE] of 3D scenes
  bool orthographic = false;        ///< --orthographic: parallel projection of 3D scenes
  std::string frame = "run";        ///< --frame run|first: what the pictures' camera fits
  std::string color_by = "plain";   ///< --color-by plain|strain|energy: elastic bodies' colours
  double color_scale = 0.0;         ///< --color-scale: the value in full colour; 0: default
  std::string window_screenshot;    ///< test aid: PNG of the window at window_screenshot_step
  std::int64_t window_screenshot_step = 0;
  bool display_given = false;  ///< -d appeared on the command line

  // Limits (docs/limits-and-failures.md).
  std::int64_t max_steps = Limits{}.max_steps;                  ///< --max-steps
  std::int64_t max_particles = Limits{}.max_particles;          ///< --max-particles
  std::int64_t max_file_mib = Limits{}.max_file_bytes >> 20;    ///< --max-file-size, MiB
  std::int64_t max_face_corners = Limits{}.max_face_corners;    ///< --max-face-corners
  std::int64_t max_attributes = Limits{}.max_attributes;        ///< --max-attributes
  std::int64_t max_hybrid_passes = Limits{}.max_hybrid_passes;  ///< --max-hybrid-passes
  std::int64_t max_polygon_corners = Limits{}.max_polygon_corners;  ///< --max-polygon-corners
};

/// The limits the options set.
Limits limits_of(const Options& options);

/// Declares every option on `app`, writing into `options`.
void add_options(CLI::App& app, Options& options);

/// Checks the picture and output options against each other and the mode (each output
/// format's own check, outputs/output_format.h), parses --size, and makes an output the window
/// cannot write (--movie) run headless when -d was not given. Throws Error (kBadInput) for a bad combination.
void check_picture_options(Options& options);

/// The movie settings of --size and --fps.
MovieSettings movie_settings(const Options& options);

/// The settings the outputs read: --size, --fps, --movie-stride.
OutputSettings output_settings(const Options& options);

/// The outputs the options ask for, in registry order.
std::vector<OutputRequest> output_requests(const Options& options);

/// True when the options ask for an output that draws states (-g, -m, --movie).
bool asks_for_pictures(const Options& options);

/// The colouring of elastic bodies that --color-by and --color-scale ask for.
ElementColors element_colors(const Options& options);

/// Refuses, with an Error (kBadInput) naming the option and the input, every output of the
/// options that would replace or overwrite an input of the run: the scene file, its mesh files
/// (scene.files) or the trajectory to grade, compared by file identity (io/file_identity.h),
/// under every name an output is written to on the way (app/protected_inputs.cpp).
void check_outputs_spare_inputs(const Options& options, const Scene& scene);

/// Refuses, with an Error (kBadInput) naming both options, two outputs of the run that name
/// the same file (-o X --energy-csv X, a movie and -o through a link, a file output and a
/// picture folder), compared by absolute path with links resolved and by file identity.
/// Character devices (/dev/null) may be named more than once.
void check_outputs_distinct(const Options& options);

/// Applies the command line's overrides to a loaded scene. Throws Error (kBadInput) when one is
/// invalid; an integrator option the scene's integrator does not have becomes a warning in
/// scene.warnings when it came from a shorthand (--newton-*), an error otherwise.
void apply_overrides(const Options& options, Scene& scene);

}  // namespace fosssim
