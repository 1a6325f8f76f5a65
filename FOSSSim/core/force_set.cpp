#include "core/force_set.h"

#include <algorithm>

#include "core/collisions/contact_method.h"

namespace fosssim {

ForceSet::ForceSet(const SceneModel& model) : ForceSet(model, {}) {}

ForceSet::ForceSet(const SceneModel& model, std::vector<const Force*> interaction)
    : model_(&model) {
  forces_.reserve(model.forces.size() + 1 + interaction.size());
  for (const auto& force : model.forces) forces_.push_back(force.get());
  if (const auto make_contact_force = model.collisions.method->make_force) {
    contact_ = make_contact_force(model);
    forces_.push_back(contact_.get());
  }
  forces_.insert(forces_.end(), interaction.begin(), interaction.end());
}

bool ForceSet::has_symmetric_jacobians() const {
  return std::all_of(forces_.begin(), forces_.end(),
                     [](const Force* force) { return force->has_symmetric_jacobians(); });
}

bool ForceSet::is_conservative() const {
  return std::all_of(forces_.begin(), forces_.end(),
                     [](const Force* force) { return force->is_conservative(); });
}

}  // namespace fosssim
