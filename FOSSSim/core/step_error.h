#pragma once

#include <cstdint>
#include <string>

#include "core/error.h"

namespace fosssim {

/// A step that could not be taken: Newton did not converge, a linear solve failed, or the state
/// became non-finite. `step` is the 1-based number of the step being taken (from frame step-1 to
/// frame step), so it matches the trajectory file and grading reports.
class StepError : public Error {
 public:
  StepError(std::int64_t step, const std::string& problem)
      : Error(ErrorKind::kStepFailed, "step " + std::to_string(step) + ": " + problem),
        step_(step) {}
  std::int64_t step() const { return step_; }

 private:
  std::int64_t step_;
};

}  // namespace fosssim
