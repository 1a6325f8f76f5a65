#pragma once
// The diagnosis of a failing scene, for the student who has to find the bug: where it first
// diverges, by how much, the reference state there, and a plot of the residual over time.

#include <optional>
#include <string>

#include "grading/grader.h"
#include "grading/rigid_grader.h"
#include "residual_history.h"
#include "scene_result.h"

namespace fosssim {

/// The diagnosis as text: verdict and reason, the details (first divergence with the start
/// state, the reference step's result and the file's frame), and the candidate's standard error.
std::string diagnosis_text(const SceneResult& result);

/// Writes the diagnosis files of a failing scene under `folder`, named after the scene (its
/// name without ".xml"): NAME.diagnosis.txt always, and when the trajectory was graded
/// (`report` not null) NAME.residuals.tsv (the table of every step of `history`, which must keep
/// it) and NAME.residuals.svg. Throws Error (kCannotWrite).
void write_diagnosis(const std::string& folder, const SceneResult& result,
                     const GradeReport* report, const ResidualHistory& history);

/// The same for a failing Theme 3 scene whose trajectory was graded: NAME.diagnosis.txt,
/// NAME.residuals.tsv (every step: the larger of the X and θ residuals as the position column,
/// of V and ω as the velocity column, with their bodies) and NAME.residuals.svg, marking the
/// first divergence. Throws Error (kCannotWrite).
void write_rigid_diagnosis(const std::string& folder, const SceneResult& result,
                           const RigidGradeReport& report, const ResidualHistory& history);

/// The path without extension that write_diagnosis uses for a scene: "<folder>/assets/t1m1/x".
std::string diagnosis_stem(const std::string& folder, const std::string& scene_name);

}  // namespace fosssim
