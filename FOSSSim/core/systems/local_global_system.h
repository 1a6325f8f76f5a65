#pragma once
// The pieces of the local/global solver of Liu et al. 2013 that do not depend on its iteration.

#include <span>
#include <string_view>
#include <vector>

#include "core/force_set.h"
#include "core/spring_terms.h"
#include "core/systems/free_dofs.h"
#include "core/types.h"

namespace fosssim {

/// A force set sorted the way the local/global solver takes it, by each force's own
/// declaration (Force::local_global_role): springs are quadratic in a projection and go into
/// its constant matrix; anchors (zero-rest-length springs to points) add to its diagonal and
/// are asked for every step; explicit forces are evaluated once per step; the penalty force
/// (`contact`) has its contacts with obstacles taken implicitly and the rest explicitly.
struct MassSpringForces {
  std::vector<SpringTerm> springs;  ///< in force order; they must not change during a run
  /// Forces declared LocalGlobalRole::kAnchor. They may change between steps (a dragged
  /// particle); the solver asks them (Force::local_global_anchor) every step.
  std::vector<const Force*> anchors;
  /// Forces declared kExplicit, and the contact force, in force order.
  std::vector<const Force*> others;
  /// The force declared kContact (the model's penalty force, core/collisions/penalty_force.h),
  /// also among `others`, or null.
  const Force* contact = nullptr;
  /// Forces that declare nothing (LocalGlobalRole::kUndeclared), in force order: the
  /// local/global solver refuses them (check_local_global_roles); solvers that use the sorting
  /// only for a preconditioner (quasi-Newton) may ignore them.
  std::vector<const Force*> undeclared;
};

/// Sorts `forces` by their LocalGlobalRole. Throws Error (kBadInput) when more than one force
/// declares kContact.
MassSpringForces sort_mass_spring_forces(const ForceSet& forces);

/// Throws Error (kBadInput) naming the first force of `sorted.undeclared`, if any, and saying
/// that `solver` cannot take it: a force the local/global solver does not know is reported, not
/// silently made explicit.
void check_local_global_roles(const MassSpringForces& sorted, std::string_view solver);

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
