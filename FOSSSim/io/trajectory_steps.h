#pragma once
// What one state of a run adds to its trajectory file, in the layout of the scene's collision
// method: shared by the FOSSSim program's -o and the Python module, so both write the same bytes.

#include "core/state.h"
#include "core/step/step_record.h"
#include "io/trajectory_file.h"

namespace fosssim {

/// Writes `state` to `writer` in `layout`: the initial state (record null) as one record, a step
/// as its end-of-step record, preceded in the layout kCollisionsAndPolynomials by its sync
/// record (the sync point's state and the polynomials logged before it; the end state when the
/// step had no sync point). Throws Error (kCannotWrite) on an I/O error.
void write_trajectory_state(TrajectoryWriter& writer, TrajectoryLayout layout, const State& state,
                            const StepRecord* record);

}  // namespace fosssim
