#include "core/scene_model.h"

#include <algorithm>
#include <cmath>

#include "core/limits.h"

namespace fosssim {

bool SceneModel::has_fixed_particles() const {
  return std::find(fixed.begin(), fixed.end(), true) != fixed.end();
}

std::int64_t SceneModel::num_steps() const {
  const double steps = step_count(duration, integrator.dt);
  return steps < kMaxStepCount ? static_cast<std::int64_t>(steps) : kMaxStepCount;
}

}  // namespace fosssim
