#pragma once
// What the exit status of a FOSSSim program means: FOSSSim, FOSSSim-generate and fosssim-oracle
// share these numbers.

#include "core/error.h"

namespace fosssim {

/// Exit statuses (FOSSSim lists them in --help, fosssim-oracle in docs/grading.md).
enum ExitCode : int {
  kExitOk = 0,                ///< the run finished, or the trajectory passed grading
  kExitGradingFailed = 1,     ///< grading mode: the trajectory failed the course's criteria
  kExitBadInput = 2,          ///< bad command line, scene file or trajectory file
  kExitSimulationFailed = 3,  ///< a step failed: non-finite state, Newton did not converge
  kExitIoError = 4,           ///< an output file could not be written
  kExitInterrupted = 130,     ///< stopped by Ctrl-C; partial output kept as *.incomplete
};

/// The exit status for a failure of this kind: bad input and something missing here (a
/// display, ffmpeg) 2, a failed step 3, an output that cannot be written 4.
constexpr ExitCode exit_status(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::kBadInput:
    case ErrorKind::kUnavailable:
      return kExitBadInput;
    case ErrorKind::kStepFailed:
      return kExitSimulationFailed;
    case ErrorKind::kCannotWrite:
      return kExitIoError;
  }
  return kExitBadInput;
}

}  // namespace fosssim
