#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace fosssim {

/// A step that could not be taken: Newton did not converge, a linear solve failed, or the state
/// became non-finite. `step` is the 1-based number of the step being taken (from frame step-1 to
/// frame step), so it matches the trajectory file and grading reports.
class StepError : public std::runtime_error {
 public:
  StepError(std::int64_t step, const std::string& problem)
      : std::runtime_error("step " + std::to_string(step) + ": " + problem), step_(step) {}
  std::int64_t step() const { return step_; }

 private:
  std::int64_t step_;
};

}  // namespace fosssim
