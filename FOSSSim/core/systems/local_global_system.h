#pragma once
// The pieces of the local/global solver of Liu et al. 2013 that do not depend on its iteration.

#include <span>
#include <vector>

#include "core/force_set.h"
#include "core/forces/drag_spring_force.h"
#include "core/spring_terms.h"
#include "core/systems/free_dofs.h"
#include "core/types.h"

namespace fosssim {

/// A force set sorted the way the local/global solver takes it. Springs (SpringForce,
/// SpringSetForce) and anchors (DragSpringForce: a zero-rest-length spring to a point) are
/// quadratic in a projection and go into its constant matrix; every other force is evaluated
/// explicitly, once per step, but the penalty force's contacts with obstacles (`contact`).
struct MassSpringForces {
  std::vector<SpringTerm> springs;  ///< in force order; they must not change during a run
  /// Anchors may change between steps (a dragged particle); the solver asks them every step.
  std::vector<const DragSpringForce*> anchors;
  std::vector<const Force*> others;  ///< in force order
  /// The model's penalty force (core/collisions/penalty_force.h), also among `others`, or
  /// null: the solver takes its obstacle pairs implicitly and only the rest explicitly.
  const Force* contact = nullptr;
};

/// Sorts `forces` into springs, anchors and the rest.
MassSpringForces sort_mass_spring_forces(const ForceSet& forces);

/// The constant matrix of the global step over the free particles (Liu et al. 2013, eq. 10,
/// with Laplacian damping and anchors):
///   Q = M/h² + Aᵀ diag(k_s + b_s/h) A + Σ_anchors k_a e_a e_aᵀ,
/// A the signed spring-particle incidence restricted to the free particles (a spring with an
/// eliminated end contributes to the other end's diagonal only). `mass` is per DOF (size
/// dim·n); the matrix is n_free × n_free, shared by the x, y and z columns.
SparseMatrix assemble_local_global_matrix(const Vector& mass, const FreeDofs& free,
                                          std::span<const SpringTerm> springs,
                                          std::span<const AnchorTerm> anchors, double h);

}  // namespace fosssim
