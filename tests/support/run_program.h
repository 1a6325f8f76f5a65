#pragma once
// Runs a program as a child process and captures its exit status and output, for tests of
// command-line behaviour.

#include <string>
#include <vector>

namespace fosssim::testing_support {

struct ProgramResult {
  int exit_code = -1;  ///< the exit status, or 128 + signal number if it was killed
  std::string out;     ///< everything written to standard output
  std::string err;     ///< everything written to standard error
};

/// Runs argv[0] with the arguments argv[1..] in `directory` (no shell involved).
ProgramResult run_program(const std::vector<std::string>& argv, const std::string& directory);

}  // namespace fosssim::testing_support
