#pragma once
// What a step reports besides its end state: the collisions it handled, the polynomials
// continuous-time detection built, and the state at the step's sync point.

#include <optional>
#include <vector>

#include "core/collisions/collision_record.h"
#include "core/collisions/polynomial.h"
#include "core/types.h"

namespace fosssim {

/// The state a response stage declares final for its impulse part (the course's "sync point",
/// written to trajectory files as a record of its own, docs/collisions.md): continuous-time
/// handling after all its responses, hybrid handling after its impulse passes, before the
/// geometric stage.
struct SyncPoint {
  Vector q, v;
  /// How many polynomials the step had logged at that moment.
  std::size_t polynomials_logged = 0;
};

/// A per-step record that the pipeline hands to every stage (StepContext::record) and returns
/// to its caller; stages append to it, and the pipeline clears it before each step, so it
/// always describes exactly one step.
struct StepRecord {
  /// The collisions the step's response handled, in the order they were found.
  std::vector<CollisionRecord> collisions;
  /// Every polynomial continuous-time detection built during the step, in the order built.
  std::vector<Polynomial> polynomials;
  /// Set by stages that have a sync point.
  std::optional<SyncPoint> sync;

  void clear() {
    collisions.clear();
    polynomials.clear();
    sync.reset();
  }
};

}  // namespace fosssim
