#pragma once
// The forces one simulation sums: the scene model's own, then forces owned by whoever runs it.

#include <memory>
#include <span>
#include <vector>

#include "core/force.h"
#include "core/scene_model.h"

namespace fosssim {

/// The forces an integrator sums, in order, with the model they act on: first the model's
/// forces (in the summation order of the force registry), then the model's contact force when
/// its contact method has one (ContactMethod::make_force: the penalty force of penalty and
/// hybrid, core/collisions/penalty_force.h, made here from model.collisions and summed after
/// every other force of the model, as the course does),
/// then interaction forces that the caller owns and hands to the simulation, such as the
/// window's drag spring (core/forces/drag_spring_force.h). An interaction force may change its
/// parameters between steps (grab, move, release) but not be added or removed; with none, results
/// are exactly those of the model alone. Non-owning: the model and the forces must outlive the set.
class ForceSet {
 public:
  /// The model's own forces.
  explicit ForceSet(const SceneModel& model);
  /// The model's forces, then `interaction`.
  ForceSet(const SceneModel& model, std::vector<const Force*> interaction);

  const SceneModel& model() const { return *model_; }
  /// Per-DOF masses, size dim·n.
  const Vector& mass() const { return model_->mass; }
  std::span<const Force* const> forces() const { return forces_; }
  auto begin() const { return forces_.begin(); }
  auto end() const { return forces_.end(); }

  /// True when every force's Jacobians are symmetric, so the step matrix is symmetric.
  bool has_symmetric_jacobians() const;
  /// True when every force derives from the potential energy its add_energy reports.
  bool is_conservative() const;

 private:
  const SceneModel* model_;
  std::unique_ptr<Force> contact_;  // the model's penalty force, or null
  std::vector<const Force*> forces_;
};

}  // namespace fosssim
