#pragma once
// Accuracy against time on the 81×81 cloth: how long each method takes per step to bring the
// implicit Euler step within a relative error of its exact value.

namespace fosssim::bench {

/// Prints the accuracy table (run in a process of its own by bench_implicit). Returns 0.
int run_accuracy_case();

}  // namespace fosssim::bench
