#pragma once
// Sums a simulation's forces, in order, into global vectors and sparse matrices.

#include "core/force_set.h"
#include "core/scene_model.h"
#include "core/types.h"

namespace fosssim {

/// gradE(q, v) = -F(q, v), summed over the forces in order.
Vector compute_gradient(const ForceSet& forces, const Vector& q, const Vector& v);

/// F(q, v) = -gradE(q, v).
Vector compute_force(const ForceSet& forces, const Vector& q, const Vector& v);

/// Total potential energy U(q) of the conservative parts of the forces.
double compute_potential_energy(const ForceSet& forces, const Vector& q, const Vector& v);

/// One force's gradient of energy at (q, v) with per-coordinate masses `mass`.
Vector gradient_of(const Force& force, const Vector& q, const Vector& v, const Vector& mass);

/// One force's energy at (q, v) with per-coordinate masses `mass`.
double energy_of(const Force& force, const Vector& q, const Vector& v, const Vector& mass);

/// T = ½ Σ m_p |v_p|².
double compute_kinetic_energy(const SceneModel& model, const Vector& v);

/// hessX = -dF/dq as an n×n sparse matrix (n = number of DOFs).
SparseMatrix compute_hessian_x(const ForceSet& forces, const Vector& q, const Vector& v);

/// hessV = -dF/dv as an n×n sparse matrix.
SparseMatrix compute_hessian_v(const ForceSet& forces, const Vector& q, const Vector& v);

/// Sets every DOF of every fixed particle of x to zero: fixed particles receive no force
/// (docs/integrators.md).
void zero_fixed(const SceneModel& model, Vector& x);

}  // namespace fosssim
