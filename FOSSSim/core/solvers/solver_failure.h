#pragma once
// How the sparse direct solvers (MUMPS, CHOLMOD, UMFPACK) report that they could not do their
// work on a step's matrix.

#include <string>

#include "core/error.h"

namespace fosssim {

/// A linear solver library failed on a matrix (its analysis, factorization or solve reported an
/// error). It is a failed step, not bad input: the step pipeline adds the step number
/// (StepError), so the programs exit with status 3 and name the step.
class SolverFailure : public Error {
 public:
  explicit SolverFailure(const std::string& problem) : Error(ErrorKind::kStepFailed, problem) {}
};

}  // namespace fosssim
