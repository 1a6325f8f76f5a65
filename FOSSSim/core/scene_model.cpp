#include "core/scene_model.h"

#include <algorithm>
#include <cmath>

namespace fosssim {

const char* integrator_name(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::kExplicitEuler:
      return "explicit-euler";
    case IntegratorKind::kSymplecticEuler:
      return "symplectic-euler";
    case IntegratorKind::kLinearizedImplicitEuler:
      return "linearized-implicit-euler";
    case IntegratorKind::kImplicitEuler:
      return "implicit-euler";
    case IntegratorKind::kLocalGlobal:
      return "local-global";
    case IntegratorKind::kLinearlyImplicitEuler:
      return "linearly-implicit-euler";
  }
  return "unknown";
}

bool SceneModel::has_fixed_particles() const {
  return std::find(fixed.begin(), fixed.end(), true) != fixed.end();
}

std::int64_t SceneModel::num_steps() const {
  return static_cast<std::int64_t>(std::ceil(duration / integrator.dt));
}

bool SceneModel::has_symmetric_jacobians() const {
  return std::all_of(forces.begin(), forces.end(),
                     [](const auto& force) { return force->has_symmetric_jacobians(); });
}

bool SceneModel::is_conservative() const {
  return std::all_of(forces.begin(), forces.end(),
                     [](const auto& force) { return force->is_conservative(); });
}

}  // namespace fosssim
