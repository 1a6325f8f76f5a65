#include "core/scene_model.h"

#include <algorithm>
#include <cmath>

namespace fosssim {

bool SceneModel::has_fixed_particles() const {
  return std::find(fixed.begin(), fixed.end(), true) != fixed.end();
}

std::int64_t SceneModel::num_steps() const {
  return static_cast<std::int64_t>(std::ceil(duration / integrator.dt));
}

}  // namespace fosssim
