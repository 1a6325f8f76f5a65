#pragma once
// The one way FOSSSim reports a failure a user must hear about.

#include <stdexcept>
#include <string>

namespace fosssim {

/// What went wrong, which is all the command line needs to choose its exit status
/// (cli/exit_codes.h): only `main` turns an Error into a status.
enum class ErrorKind {
  kBadInput,     ///< a scene, mesh, trajectory file or command-line value is wrong
  kStepFailed,   ///< the simulation could not take a step (non-finite state, no convergence)
  kCannotWrite,  ///< an output could not be written
  kUnavailable,  ///< something the run needs is missing here (a display, the ffmpeg program)
};

/// A failure with a message that names what failed and why, complete enough to print as is.
/// Functions that can fail on user input, on a step or on a file throw an Error (or a class
/// derived from it, which adds structured detail such as a file and line); they never exit.
class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  ErrorKind kind() const { return kind_; }

 private:
  ErrorKind kind_;
};

}  // namespace fosssim
