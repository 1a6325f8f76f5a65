#pragma once

#include "core/integrators/integrator.h"

namespace fosssim {

/// Forward Euler (SPEC section 4, compat order):
///   F = F(qⁿ, vⁿ) with fixed DOFs zeroed;  qⁿ⁺¹ = qⁿ + h vⁿ;  vⁿ⁺¹ = vⁿ + h F./m.
/// First order; gains energy on oscillators.
class ExplicitEuler final : public Integrator {
 protected:
  void advance(const SceneModel& model, State& state) override;
};

}  // namespace fosssim
