#pragma once
// The FOSSSim command line: the course's flags plus our own.

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "core/expected.h"
#include "core/scene.h"

namespace fosssim {

struct Options {
  std::string scene;        ///< -s
  int display = 1;          ///< -d 0|1
  int paused = 1;           ///< -p 0|1
  std::string output;       ///< -o trajectory to write
  std::string input;        ///< -i trajectory to grade
  std::optional<double> duration;  ///< --duration override, seconds
  std::optional<double> dt;        ///< --dt override, seconds
  std::optional<int> newton_max_iterations;
  std::optional<double> newton_tolerance;
  std::string residual_file = "residual.txt";
  bool check_derivatives = false;
  bool quiet = false;
};

/// Declares every option on `app`, writing into `options`.
void add_options(CLI::App& app, Options& options);

/// Applies the command line's overrides to a loaded scene; returns a message if one is invalid.
std::optional<std::string> apply_overrides(const Options& options, Scene& scene);

}  // namespace fosssim
