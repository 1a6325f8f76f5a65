#pragma once
// Grading many scenes with N workers at once.

#include <cstddef>
#include <functional>
#include <vector>

#include "scene_grading.h"

namespace fosssim {

/// Calls work(i) for every i in [0, count) on `jobs` threads (at least one); each call runs on
/// one thread, in an unspecified order. Returns when all calls have returned.
void for_each_in_parallel(std::size_t count, int jobs,
                          const std::function<void(std::size_t)>& work);

/// Called once per finished scene, from the worker that graded it but never concurrently.
using SceneFinished =
    std::function<void(const SceneResult& result, std::size_t done, std::size_t total)>;

/// Grades every scene with `jobs` workers; the results are in the order of `scenes`. After
/// stop_all_children() the scenes not yet started are not run and come back kInterrupted.
std::vector<SceneResult> grade_scenes(const std::vector<SceneEntry>& scenes,
                                      const GradingOptions& options, int jobs,
                                      const SceneFinished& on_finished = {});

}  // namespace fosssim
