#pragma once
// Asserting that code fails the way FOSSSim fails: by throwing an Error.

#include <gtest/gtest.h>

#include <stdexcept>
#include <utility>

#include "core/error.h"

namespace fosssim {

/// Runs `action`, which must throw an E (Error, SceneError, StepError, ...), and returns what it
/// threw. When it throws nothing, the test fails and std::logic_error ends it.
template <typename E = Error, typename Action>
E thrown_by(Action&& action) {
  try {
    std::forward<Action>(action)();
  } catch (const E& error) {
    return error;
  }
  ADD_FAILURE() << "expected an exception, and none was thrown";
  throw std::logic_error("expected an exception, and none was thrown");
}

}  // namespace fosssim
