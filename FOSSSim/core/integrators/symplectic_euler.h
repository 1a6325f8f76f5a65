#pragma once

#include "core/integrators/integrator.h"

namespace fosssim {

/// Symplectic (semi-implicit, forward-backward) Euler in the course's update order
/// (docs/integrators.md):
///   F = F(qⁿ, vⁿ) with fixed DOFs zeroed;  vⁿ⁺¹ = vⁿ + h F./m;  qⁿ⁺¹ = qⁿ + h vⁿ⁺¹.
/// First order; symplectic, so the energy of a conservative system oscillates without drift.
class SymplecticEuler final : public Integrator {
 protected:
  void advance(State& state) override;
};

/// Registry entry: "symplectic-euler", also "forward-backward-euler" and "semi-implicit-euler".
extern const IntegratorMethod kSymplecticEulerMethod;

}  // namespace fosssim
