#pragma once
// Collision handling as response stages of the step pipeline (core/step/step_stage.h): written
// once for every integrator, run on the integrated state of each step.

#include <memory>

#include "core/collisions/candidate_pairs.h"
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

/// Type `continuous-time` (course-compatible): the pairs in the course's order, each detected
/// over the step from the start positions to the current end positions (already moved by
/// earlier responses of the step), and when colliding recorded and answered at once: the
/// impulse is computed from the displacement velocities (X - xs)/h at the collision time's
/// geometry, and each free particle gets V += Δv, X += h Δv. The sync point is the end state.
template <int D>
class ContinuousTimeStage final : public StepStage {
 public:
  explicit ContinuousTimeStage(const SceneModel& model);
  void apply(const StepContext& context, State& state) override;

 private:
  std::unique_ptr<CandidatePairs> pairs_;
};

/// Type `hybrid` (course-compatible; its penalty force is in the model's forces): up to
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

/// The response stage model.collisions asks for (simple, continuous-time, hybrid), or null
/// when there is none (no collisions, or only a penalty force). `model` must outlive it.
std::unique_ptr<StepStage> make_collision_stage(const SceneModel& model);

}  // namespace fosssim
