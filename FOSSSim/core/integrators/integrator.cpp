#include "core/integrators/integrator.h"

#include "core/integrators/explicit_euler.h"
#include "core/integrators/implicit_euler.h"
#include "core/integrators/linearized_implicit_euler.h"
#include "core/integrators/linearly_implicit_euler.h"
#include "core/integrators/local_global.h"
#include "core/integrators/symplectic_euler.h"

namespace fosssim {

std::unique_ptr<Integrator> make_integrator(const SceneModel& model) {
  switch (model.integrator.kind) {
    case IntegratorKind::kExplicitEuler:
      return std::make_unique<ExplicitEuler>();
    case IntegratorKind::kSymplecticEuler:
      return std::make_unique<SymplecticEuler>();
    case IntegratorKind::kLinearizedImplicitEuler:
      return std::make_unique<LinearizedImplicitEuler>(model);
    case IntegratorKind::kImplicitEuler:
      return std::make_unique<ImplicitEuler>(model);
    case IntegratorKind::kLocalGlobal:
      if (model.dim == 3) return std::make_unique<LocalGlobal<3>>(model);
      return std::make_unique<LocalGlobal<2>>(model);
    case IntegratorKind::kLinearlyImplicitEuler:
      return std::make_unique<LinearlyImplicitEuler>(model);
  }
  return nullptr;
}

}  // namespace fosssim
