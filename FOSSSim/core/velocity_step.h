#pragma once
// The velocity change h M⁻¹ F of the explicit methods, in each kind of body's course order.

#include "core/scene_model.h"
#include "core/types.h"

namespace fosssim {

/// v += h M⁻¹ F for every coordinate (fixed ones get F = 0 from zero_fixed). Particles:
/// v += h (F ./ m), the course's Theme 1 order. Rigid bodies (model.rigid_bodies): per body
/// V += (F h)(1/M) and ω += (h τ)/I, the Theme 3 program's order, so that explicit and
/// symplectic Euler reproduce it bit for bit (docs/rigid-bodies.md).
void add_velocity_step(const SceneModel& model, double h, const Vector& force, Vector& v);

}  // namespace fosssim
