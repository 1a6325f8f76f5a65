#pragma once
// What the command line does once a scene is loaded; each returns the process exit status, and
// failures they do not report themselves reach main() as Error.

#include <ostream>

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

/// Prints an error as the programs do: a located input error ("file:line: error: ...") as it
/// is, anything else after "FOSSSim: error: ".
void print_error(std::ostream& out, const Error& error);

/// Finite-difference check of every force at the scene's initial state.
int run_derivative_check(const Scene& scene, const Options& options);

}  // namespace fosssim
