#include "io/trajectory_steps.h"

#include <cstddef>
#include <vector>

namespace fosssim {

void write_trajectory_state(TrajectoryWriter& writer, TrajectoryLayout layout, const State& state,
                            const StepRecord* record) {
  if (record == nullptr) {
    writer.write_record(layout, state.q, state.v, {}, {});
    return;
  }
  if (layout == TrajectoryLayout::kCollisionsAndPolynomials) {
    const SyncPoint sync =
        record->sync.value_or(SyncPoint{state.q, state.v, record->polynomials.size()});
    const std::vector<Polynomial> logged(
        record->polynomials.begin(),
        record->polynomials.begin() + static_cast<std::ptrdiff_t>(sync.polynomials_logged));
    writer.write_record(layout, sync.q, sync.v, record->collisions, logged);
  }
  writer.write_record(layout, state.q, state.v, record->collisions, record->polynomials);
}

}  // namespace fosssim
