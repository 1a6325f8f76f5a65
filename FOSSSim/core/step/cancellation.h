#pragma once
// How whoever runs a simulation asks a step in progress to end early.

#include <exception>

namespace fosssim {

/// Thrown out of a step whose caller asked it to stop (Cancellation::check). The step is
/// abandoned mid-way and the state it was working on means nothing. Not an Error: the caller
/// asked for it, and decides what to report.
class StepCancelled : public std::exception {
 public:
  const char* what() const noexcept override { return "the step was cancelled"; }
};

/// The question the long loops of a step ask once per iteration (Newton and local/global
/// iterations, hybrid impulse passes, impact-zone growth): "should this step stop now?". Core
/// knows nothing of what makes the answer yes; the FOSSSim program answers "a signal arrived"
/// (app/interrupt.h). A plain function pointer: asking costs a call and no locks, and a
/// default Cancellation never cancels.
class Cancellation {
 public:
  constexpr Cancellation() = default;
  explicit constexpr Cancellation(bool (*requested)()) : requested_(requested) {}

  bool requested() const { return requested_ != nullptr && requested_(); }
  /// Throws StepCancelled when the caller asked to stop.
  void check() const {
    if (requested()) throw StepCancelled();
  }

 private:
  bool (*requested_)() = nullptr;
};

}  // namespace fosssim
