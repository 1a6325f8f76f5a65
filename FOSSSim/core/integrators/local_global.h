#pragma once

#include <vector>

#include "core/integrators/integrator.h"
#include "core/solvers/spd_solver.h"
#include "core/spring_terms.h"

namespace fosssim {

/// Implicit Euler for mass-spring systems by the local/global solver of Liu, Bargteil, O'Brien
/// and Kavan, "Fast Simulation of Mass-Spring Systems", ACM TOG 32(6), 2013.
///
/// Implicit Euler's positions minimize
///   g(p) = 1/(2h²) (p - y)ᵀ M (p - y) + Σ_s ½ k_s (|p_i - p_j| - l_s)² - f_extᵀ p,
/// with y = pⁿ + h vⁿ (= 2pⁿ - pⁿ⁻¹ when vⁿ = (pⁿ - pⁿ⁻¹)/h, so no history is kept). Writing
/// each spring's energy as min over |d_s| = l_s of ½ k_s |p_i - p_j - d_s|², the solver
/// alternates a local step, d_s = l_s (p_i - p_j)/|p_i - p_j| for every spring, and a global
/// step, the linear solve  Q p = M y/h² + Aᵀ K d + f_ext  with the constant n×n matrix
///   Q = M/h² + Aᵀ K A  (A: signed spring-particle incidence, K = diag(k_s)).
/// Q is shared by the x, y and z columns, factored once per scene and time step (dense LLT for
/// tiny systems, sparse Cholesky otherwise) and every iteration is one sweep down and up its
/// factor for all columns. Then vⁿ⁺¹ = (pⁿ⁺¹ - pⁿ)/h. With enough iterations the result is
/// implicit Euler's (the Newton solution of ImplicitEuler) for undamped springs.
///
/// What else the solver takes implicitly, all of it keeping Q constant:
/// - spring damping b_s as Laplacian damping (Li, Liu and Kavan, "Laplacian Damping for
///   Projective Dynamics", VRIPHYS 2018): the force -b_s (v_i - v_j) acts along every
///   direction, not only along the spring as in SpringForce; Q gains Aᵀ diag(b_s/h) A;
/// - anchors (AnchorTerm: zero-rest-length springs to points, such as DragSpringForce), which
///   add k to Q's diagonal; Q is refactored (numerically only) when the set of anchored
///   particles or their stiffnesses change, and a moving target only changes the right side;
/// - fixed particles, either eliminated (their rows and columns removed from Q; they move
///   with their own velocity, exactly) or held by penalty springs of stiffness w to their
///   anchors (Liu et al.'s w·CᵀC): the positions they have at this integrator's first step,
///   moved on with their velocity at that step.
/// Every other force (gravity, constant forces, drag, vortices, Newtonian gravity) is
/// evaluated once per step at (pⁿ, vⁿ) and held constant as f_ext: exact for gravity and
/// constant forces, explicit for the rest. Fixed particles receive no force.
template <int D>
class LocalGlobal final : public Integrator {
 public:
  explicit LocalGlobal(const SceneModel& model) : settings_(model.integrator.local_global) {}

  /// Local/global iterations taken by the last step.
  int last_iterations() const { return last_iterations_; }
  /// The largest coordinate change of the last iteration of the last step (m).
  double last_change() const { return last_change_; }
  /// How many times Q has been factored (once per scene and time step, plus anchor changes).
  int factorizations() const { return factorizations_; }
  /// The factorization in use (after the first step).
  SpdSolver::Method solver_method() const { return solver_.method(); }

 protected:
  void advance(const SceneModel& model, State& state) override;

 private:
  /// A spring with the solver's indices: fi, fj are its ends among the free particles (-1 for
  /// an eliminated end).
  struct Spring {
    int i, j, fi, fj;
    double k, l0, b;
  };

  /// Sorts the forces into anchor and explicit ones; returns the springs (solved implicitly).
  std::vector<SpringTerm> classify_forces(const SceneModel& model);
  void choose_free_particles(const SceneModel& model, const State& state,
                             const std::vector<SpringTerm>& springs);
  /// Gathers this step's anchors; returns their (particle, stiffness) pairs, which Q depends on.
  std::vector<std::pair<int, double>> collect_anchors(const SceneModel& model, const State& state,
                                                      double h);
  /// Assembles and factors Q over the free particles for anchors_ and h_.
  void factor(const SceneModel& model, std::int64_t step);
  void assemble_constant_rhs(const SceneModel& model, const State& state);
  void add_spring_directions(Points<D>& rhs);
  double global_solve(Points<D>& rhs);

  LocalGlobalSettings settings_;
  bool prepared_ = false;
  double h_ = 0.0;                             // the time step Q was factored for
  std::vector<const Force*> anchor_forces_;    // asked for anchors every step
  std::vector<const Force*> explicit_forces_;  // evaluated at (pⁿ, vⁿ)
  std::vector<Spring> springs_;
  std::vector<int> free_;        // free particle -> particle
  std::vector<int> free_index_;  // particle -> free particle, or -1
  // Penalty pins: anchors taken at the first step.
  std::vector<int> pinned_;
  Points<D> pin_position_, pin_velocity_;
  std::int64_t pin_step_ = 0;
  std::vector<AnchorTerm> anchors_;  // this step's anchors (free particles only)
  std::vector<std::pair<int, double>> factored_anchors_;  // (particle, k) in Q
  SpdSolver solver_;
  Points<D> p_;             // the current iterate, every particle
  Points<D> d_;             // spring directions times rest lengths, kept between iterations
  Points<D> constant_rhs_;  // the right side without the springs' directions
  Points<D> rhs_;
  Vector explicit_gradient_;
  int last_iterations_ = 0;
  double last_change_ = 0.0;
  int factorizations_ = 0;
};

}  // namespace fosssim
