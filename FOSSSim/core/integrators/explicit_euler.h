#pragma once

#include "core/integrators/integrator.h"

namespace fosssim {

/// Forward Euler in the course's update order (docs/integrators.md):
///   F = F(qⁿ, vⁿ) with fixed DOFs zeroed;  qⁿ⁺¹ = qⁿ + h vⁿ;  vⁿ⁺¹ = vⁿ + h F./m.
/// First order; gains energy on oscillators.
class ExplicitEuler final : public Integrator {
 protected:
  void advance(State& state) override;
};

/// Registry entry: "explicit-euler".
extern const IntegratorMethod kExplicitEulerMethod;

}  // namespace fosssim
