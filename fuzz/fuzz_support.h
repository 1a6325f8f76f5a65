#pragma once
// What the fuzz targets share: small limits, so that an input cannot ask for more than a fuzzer
// can afford per input, and a few steps of every scene that loads, so that inputs the readers
// accept but that make no physical sense are run too.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/limits.h"
#include "core/scene.h"

namespace fosssim::fuzzing {

/// Limits for one fuzz input: scenes of at most a few hundred particles and files of 1 MiB.
Limits fuzz_limits();

/// The input as text.
inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// Takes up to `max_steps` steps of the scene (its scene tag's hook included), as a run does,
/// with its iteration counts (Newton, local/global, hybrid passes) capped at 20.
/// A step that fails with an Error is an expected outcome and ends the run quietly; anything
/// else escapes to the fuzzer as a finding.
void run_a_few_steps(Scene& scene, int max_steps = 3);

}  // namespace fosssim::fuzzing
