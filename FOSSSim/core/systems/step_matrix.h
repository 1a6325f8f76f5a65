#pragma once
// The matrix of an implicit Euler step, A = M + h² hessX + h hessV, with fixed particles.

#include <Eigen/Core>

#include "core/force_set.h"
#include "core/hessian_builder.h"
#include "core/hessian_pattern.h"
#include "core/systems/free_dofs.h"
#include "core/types.h"

namespace fosssim {

/// How a step's linear system keeps fixed particles in place (they receive no force and keep
/// their velocity, docs/integrators.md).
enum class FixedParticleRule {
  /// The course's rule (compat): every DOF stays an unknown; a fixed DOF's row and column of A
  /// are zero, its diagonal is 1 and its right-hand side 0, so its velocity change is exactly 0.
  kIdentityRows,
  /// Fixed DOFs are removed: with the selection P of the free DOFs (FreeDofs) the system is
  /// P A Pᵀ x̂ = P b. Smaller, with the same solution on the free DOFs.
  kElimination,
};

/// Assembles A = M + h² hessX(q, v) + h hessV(q, v) over the unknowns of a rule. The first
/// assembly records where every block the forces write lands (HessianPattern); later ones
/// scatter the values straight into a matrix of that fixed pattern, with no triplets, no sort
/// and no allocation, while the forces write the same blocks (a changed set of writes, such as a
/// grabbed particle, is recorded anew). Entries are summed in a fixed order (hessX, then hessV,
/// force by force, then the diagonal), the order Eigen's setFromTriplets would sum them in, so
/// the same input gives the same bits as building the matrix from triplets.
class StepMatrix {
 public:
  /// forces: what A is assembled from (they and their model must outlive this);
  /// definite_hessian: ask forces for semi-definite hessX blocks (ForceInput).
  StepMatrix(const ForceSet& forces, FixedParticleRule rule, bool definite_hessian = false);

  /// Assembles A at (q, v) for the time step h. When `rhs` is given, also subtracts
  /// h² hessX(q, v) u from it (every DOF, before the fixed-particle rule), entry by entry from
  /// the same blocks, for a right-hand side that needs hessX times a vector.
  const SparseMatrix& assemble(const Vector& q, const Vector& v, double h,
                               const Vector* u = nullptr, Vector* rhs = nullptr);
  const SparseMatrix& matrix() const { return matrix_; }
  /// A at (q, v) with every force's semi-definite hessX (ForceInput::definite_hessian), in a
  /// matrix of its own with the pattern of assemble()'s: a positive definite matrix near A
  /// when A is not (Newton's `hessian="projected"` and `"adaptive"` step with it, alone or
  /// blended with A: core/integrators/newton.cpp).
  const SparseMatrix& assemble_definite(const Vector& q, const Vector& v, double h);
  /// What assemble() gives, bit for bit, computed the plain way: the forces' values as
  /// triplets, filtered by the fixed-particle rule and summed by Eigen's setFromTriplets. The
  /// reference for tests, and the old path of the benchmarks.
  const SparseMatrix& assemble_from_triplets(const Vector& q, const Vector& v, double h,
                                             const Vector* u = nullptr, Vector* rhs = nullptr);

  /// A as the course's reference programs assemble it, dense, over every DOF (the rule must be
  /// kIdentityRows): starting from +0, every force in order adds its hessX blocks; every entry
  /// is multiplied by h; every force adds its hessV blocks; every entry is multiplied by h again
  /// and the masses are added on the diagonal; then each fixed DOF's row and column become 0
  /// and its diagonal 1. So each entry is h (h ΣhessX + ΣhessV) + m, summed in force order:
  /// the course's bits (docs/solvers.md, 'The course-exact dense path'). n² storage: for small
  /// systems only.
  const Eigen::MatrixXd& assemble_course(const Vector& q, const Vector& v, double h);

  /// A full right-hand side over the unknowns: b with fixed DOFs zeroed (kIdentityRows) or P b.
  Vector restrict(const Vector& b) const;
  /// full += the solution x over the unknowns (x itself, or Pᵀ x).
  void add_solution(const Vector& x, Vector& full) const;

  FixedParticleRule rule() const { return rule_; }
  /// The number of unknowns: every DOF, or the free ones.
  int size() const;
  /// Bytes the assembly keeps besides the matrices (the recorded pattern), for benchmarks.
  std::size_t pattern_bytes() const { return pattern_.bytes(); }

 private:
  HessianPattern make_pattern() const;
  /// Records the writes of the forces at `in` and the pattern they make.
  void record(const ForceInput& in);
  /// Scatters A's values at `in` into `out` (of the recorded pattern); false when the forces
  /// wrote other blocks than those recorded (`rhs` is then as it was).
  bool scatter(const ForceInput& in, double h, const Vector* u, Vector* rhs, SparseMatrix& out);
  /// Triplets, filtered and summed (the fallback for patterns HessianPattern cannot hold).
  void build_from_triplets(const ForceInput& in, double h, const Vector* u, Vector* rhs,
                           SparseMatrix& out);

  const ForceSet* forces_;
  FixedParticleRule rule_;
  bool definite_hessian_;
  FreeDofs free_;
  bool any_fixed_ = false;
  HessianPattern pattern_;
  bool recorded_ = false;
  bool pattern_usable_ = false;
  HessianBuilder scratch_;  // triplets, for the fallback
  Vector saved_rhs_;
  SparseMatrix matrix_;
  SparseMatrix definite_;
  Eigen::MatrixXd dense_;
};

}  // namespace fosssim
