#pragma once
// Sums the scene's forces, in the compat order, into global vectors and sparse matrices.

#include "core/hessian_builder.h"
#include "core/scene_model.h"
#include "core/types.h"

namespace fosssim {

/// gradE(q, v) = -F(q, v), summed over the model's forces in order.
Vector compute_gradient(const SceneModel& model, const Vector& q, const Vector& v);

/// F(q, v) = -gradE(q, v).
Vector compute_force(const SceneModel& model, const Vector& q, const Vector& v);

/// Total potential energy U(q) of the conservative parts of the forces.
double compute_potential_energy(const SceneModel& model, const Vector& q, const Vector& v);

/// T = ½ Σ m_p |v_p|².
double compute_kinetic_energy(const SceneModel& model, const Vector& v);

/// hessX = -dF/dq as an n×n sparse matrix (n = number of DOFs).
SparseMatrix compute_hessian_x(const SceneModel& model, const Vector& q, const Vector& v);

/// hessV = -dF/dv as an n×n sparse matrix.
SparseMatrix compute_hessian_v(const SceneModel& model, const Vector& q, const Vector& v);

/// Sets every DOF of every fixed particle of x to zero ("zero fixed", SPEC section 4).
void zero_fixed(const SceneModel& model, Vector& x);

/// The implicit step matrix A = diag(m) + h² hessX + h hessV at (q, v) with fixed particles
/// eliminated: their rows and columns are zero and their diagonal is 1 (SPEC section 4).
/// `scratch` keeps its capacity between calls so that stepping does not reallocate. Given
/// `hessian_x_times_v`, also sets it to h² hessX v (every DOF, before the elimination), from the
/// same entries, for a right-hand side that needs it.
SparseMatrix assemble_step_matrix(const SceneModel& model, const Vector& q, const Vector& v,
                                  double h, HessianBuilder& scratch,
                                  Vector* hessian_x_times_v = nullptr);

}  // namespace fosssim
