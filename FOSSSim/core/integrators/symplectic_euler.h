#pragma once

#include "core/integrators/integrator.h"

namespace fosssim {

/// Symplectic (semi-implicit, forward-backward) Euler (SPEC section 4, compat order):
///   F = F(qⁿ, vⁿ) with fixed DOFs zeroed;  vⁿ⁺¹ = vⁿ + h F./m;  qⁿ⁺¹ = qⁿ + h vⁿ⁺¹.
/// First order and symplectic: the energy of a conservative system stays bounded.
class SymplecticEuler final : public Integrator {
 protected:
  void advance(const SceneModel& model, State& state) override;
};

}  // namespace fosssim
