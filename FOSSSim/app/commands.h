#pragma once
// What the command line does once a scene is loaded; each returns the process exit status, and
// failures they do not report themselves reach main() as Error.

#include <exception>
#include <ostream>
#include <string>

#include "app/options.h"
#include "core/error.h"
#include "core/scene.h"
#include "grading/grader.h"

namespace fosssim {

/// Runs the scene to its end without a window, writing the trajectory if -o was given.
int run_headless(const Scene& scene, const Options& options);

/// Grades the trajectory of -i against the scene (docs/command-line.md, 'Grading').
int run_grading(const Scene& scene, const Options& options);

/// Prints the course's report of a finished grading, writes the residual file, explains a
/// failure; returns the exit status (0 passed, 1 failed, 4 residual file not written).
int report_grade(const Scene& scene, const Options& options, const GradeReport& report);

/// Opens the interactive window (docs/viewing.md) on the scene: a run, or with -i a
/// step-by-step grading replay that rings the particles where the file disagrees with the
/// reference. In a run the mouse pulls particles with a drag spring the window owns
/// (viewer/particle_grab.h).
int run_window(const Scene& scene, const Options& options);

/// Prints a failure as FOSSSim does and returns the exit status for it: a located input error
/// ("file:line: error: ...") as it is, running out of memory with a pointer to the limits,
/// anything else after "FOSSSim: error: "; then "; <kept>" when `kept` says what a stopped run
/// kept. The status is exit_status() of an Error's kind, and 2 (bad input) for anything else:
/// a run always ends with a message and a documented status, never an abort.
int report_failure(std::ostream& out, const std::exception& failure, const std::string& kept = "");

/// Finite-difference check of every force at the scene's initial state.
int run_derivative_check(const Scene& scene, const Options& options);

}  // namespace fosssim
