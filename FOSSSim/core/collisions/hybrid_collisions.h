#pragma once
// Contact method `hybrid`: a penalty force, Jacobi passes of swept impulses, then rigid impact
// zones (docs/collisions.md).

#include <memory>

#include "core/collisions/candidate_pairs.h"
#include "core/collisions/contact_method.h"
#include "core/scene_model.h"
#include "core/step/step_stage.h"

namespace fosssim {

/// Type `hybrid` (course-compatible; its penalty force is summed with the model's forces): up to
/// max_iterations Jacobi passes of continuous-time impulses (all collisions of a pass are
/// detected first, then answered from the pass's start, their changes added up); the sync point
/// after them; then, if the last pass still found collisions (or max_iterations ≤ 0), the
/// geometric stage: collisions merge into rigid impact zones (core/collisions/impact_zones.h)
/// that are moved rigidly and grown until detection finds no new zone. Records no collisions.
/// 2D only: the rigid motion is a rotation about one axis.
class HybridStage final : public StepStage {
 public:
  explicit HybridStage(const SceneModel& model);
  void apply(const StepContext& context, State& state) override;

 private:
  std::unique_ptr<CandidatePairs> pairs_;
};

/// Registry entry: "hybrid".
extern const ContactMethod kHybridContactMethod;

}  // namespace fosssim
