#pragma once
// Running programs as a user runs them, for tests of command-line behaviour: the exit status and
// everything the program printed.

#include <string>
#include <vector>

#include "support/scratch_folder.h"

namespace fosssim::testing {

/// What a finished program returned and printed.
struct ProgramResult {
  int status = -1;  ///< the exit status, or 128 + the signal's number if a signal ended it
  std::string out;  ///< everything written to standard output
  std::string err;  ///< everything written to standard error

  /// Everything the program printed: standard output, then standard error.
  std::string output() const { return out + err; }
};

/// Runs argv[0] (a path) with the arguments argv[1..] in `directory`, no shell involved, and
/// waits for it.
ProgramResult run_program(const std::vector<std::string>& argv, const std::string& directory);

/// Runs a shell command line (sh -c) in `folder`: for environment settings, pipes and
/// background jobs around the program.
ProgramResult run_command(const ScratchFolder& folder, const std::string& command_line);

/// `text` in single quotes, for a shell command line (`text` has no single quote).
std::string quoted(const std::string& text);

/// True when `name` is an executable on PATH.
bool on_path(const std::string& name);

/// "width,height,rate,frames," of the first video stream of `movie` (a name in `folder`), as
/// ffprobe reads them; needs ffprobe on PATH.
std::string probe_movie(const ScratchFolder& folder, const std::string& movie);

#ifdef FOSSSIM_EXECUTABLE
/// The FOSSSim program built with these tests.
inline std::string fosssim_program() { return FOSSSIM_EXECUTABLE; }
#endif

#ifdef FOSSSIM_GENERATE_EXECUTABLE
/// The FOSSSim-generate program built with these tests.
inline std::string fosssim_generate_program() { return FOSSSIM_GENERATE_EXECUTABLE; }
#endif

}  // namespace fosssim::testing
