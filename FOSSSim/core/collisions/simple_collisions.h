#pragma once
// Contact method `simple`: discrete detection after each step and impulses (docs/collisions.md).

#include <memory>

#include "core/collisions/candidate_pairs.h"
#include "core/collisions/contact_method.h"
#include "core/scene_model.h"
#include "core/step/step_stage.h"

namespace fosssim {

/// Type `simple` (course-compatible): the pairs in the course's order, each tested at the end
/// positions with the current velocities (core/collisions/proximity.h) and, when colliding,
/// recorded and answered at once (Gauss-Seidel: later tests see the changed velocities).
/// Positions are not changed.
template <int D>
class SimpleCollisionStage final : public StepStage {
 public:
  explicit SimpleCollisionStage(const SceneModel& model);
  void apply(const StepContext& context, State& state) override;

 private:
  std::unique_ptr<CandidatePairs> pairs_;
};

/// Registry entry: "simple".
extern const ContactMethod kSimpleContactMethod;

}  // namespace fosssim
