#pragma once

#include "outputs/output_format.h"

namespace fosssim {

/// Registry entry "trajectory" (-o FILE): the trajectory file (docs/command-line.md,
/// 'Trajectory files') in the layout of the scene's collision method, or the course's Theme 3
/// layout for rigid-body scenes (io/rigid_trajectory.h).
extern const OutputFormat kTrajectoryOutput;

}  // namespace fosssim
