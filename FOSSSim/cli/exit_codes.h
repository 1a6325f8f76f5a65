#pragma once
// What the exit status of a FOSSSim program means: FOSSSim, FOSSSim-generate and fosssim-oracle
// share these numbers.

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

}  // namespace fosssim
