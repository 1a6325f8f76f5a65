#pragma once
// Contact method `continuous-time`: swept detection over each step and impulses
// (docs/collisions.md).

#include <memory>

#include "core/collisions/candidate_pairs.h"
#include "core/collisions/contact_method.h"
#include "core/scene_model.h"
#include "core/step/step_stage.h"

namespace fosssim {

/// Type `continuous-time` (course-compatible): the pairs in the course's order, each detected
/// over the step from the start positions to the current end positions (already moved by
/// earlier responses of the step), and when colliding recorded and answered at once: the
/// impulse is computed from the displacement velocities (X - xs)/h at the collision time's
/// geometry, and each free particle gets V += Δv, X += h Δv. In 2D the normal and the response
/// are the course's arithmetic, operation for operation (course_swept.h); 3D keeps the formulas
/// of impulses.h. The sync point is the end state.
template <int D>
class ContinuousTimeStage final : public StepStage {
 public:
  explicit ContinuousTimeStage(const SceneModel& model);
  void apply(const StepContext& context, State& state) override;

 private:
  std::unique_ptr<CandidatePairs> pairs_;
};

/// Registry entry: "continuous-time".
extern const ContactMethod kContinuousTimeContactMethod;

}  // namespace fosssim
