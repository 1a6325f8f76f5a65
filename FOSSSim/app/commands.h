#pragma once
// What the command line does once a scene is loaded; each returns the process exit status.

#include "app/options.h"
#include "core/scene.h"

namespace fosssim {

/// Runs the scene to its end without a window, writing the trajectory if -o was given.
int run_headless(const Scene& scene, const Options& options);

/// Grades the trajectory of -i against the scene (SPEC section 5).
int run_grading(const Scene& scene, const Options& options);

/// Finite-difference check of every force at the scene's initial state.
int run_derivative_check(const Scene& scene, const Options& options);

}  // namespace fosssim
