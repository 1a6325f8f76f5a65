#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "core/collisions/candidate_pairs.h"
#include "core/collisions/penalty_force.h"
#include "core/integrators/integrator.h"
#include "core/solvers/anderson_acceleration.h"
#include "core/solvers/spd_solver.h"
#include "core/spring_terms.h"
#include "core/systems/free_dofs.h"
#include "core/systems/local_global_system.h"

namespace fosssim {

/// How the local/global solver keeps fixed particles in place.
enum class PinMethod {
  kElimination,  ///< remove their rows and columns from the system: exact
  kPenalty,      ///< a stiff spring w·CᵀC to their anchor, as in Liu et al. 2013
};

/// Which factorization the local/global solver uses for its constant matrix.
enum class LinearSolverChoice {
  kAuto,    ///< dense below LocalGlobalSettings::kDenseLimit free particles, sparse above
  kDense,   ///< dense Cholesky (Eigen::LLT), for tiny systems
  kSparse,  ///< sparse Cholesky (Eigen::SimplicialLLT), factored once and reused
};

/// How the local/global iterations are accelerated.
enum class Acceleration {
  kNone,       ///< plain local/global
  kAnderson,   ///< Anderson acceleration with an energy safeguard (Peng et al. 2018)
  kChebyshev,  ///< Chebyshev semi-iterative acceleration (Wang 2015)
};

/// Where each step's local/global iterations begin.
enum class IterationStart {
  kInertial,  ///< at y = pⁿ + h vⁿ, where the old velocity carries the particles
  kCurrent,   ///< at the current positions pⁿ (the fast mass-springs assignment's choice)
};

/// Settings of the local/global solver (options of the "local-global" registry entry).
struct LocalGlobalSettings {
  /// kAuto solves systems of at most this many free particles densely.
  static constexpr int kDenseLimit = 64;
  int iterations = 10;     ///< local/global iterations per step (the most, with a tolerance)
  double tolerance = 0.0;  ///< stop once no coordinate moved more than this (m); 0: never
  IterationStart start = IterationStart::kInertial;
  PinMethod pins = PinMethod::kElimination;
  double penalty_weight = 1e10;  ///< w of the penalty pins, N/m
  LinearSolverChoice solver = LinearSolverChoice::kAuto;
  Acceleration acceleration = Acceleration::kNone;
  int window = 5;     ///< Anderson: differences kept
  double rho = 0.99;  ///< Chebyshev: the estimated spectral radius of the plain iteration
};

/// Implicit Euler for mass-spring systems by the local/global solver of Liu, Bargteil, O'Brien
/// and Kavan, "Fast Simulation of Mass-Spring Systems", ACM TOG 32(6), 2013.
///
/// Implicit Euler's positions minimize
///   g(p) = 1/(2h²) (p - y)ᵀ M (p - y) + Σ_s ½ k_s (|p_i - p_j| - l_s)² - f_extᵀ p,
/// with y = pⁿ + h vⁿ (= 2pⁿ - pⁿ⁻¹ when vⁿ = (pⁿ - pⁿ⁻¹)/h, so no history is kept). Writing
/// each spring's energy as min over |d_s| = l_s of ½ k_s |p_i - p_j - d_s|², the solver
/// alternates a local step, d_s = l_s (p_i - p_j)/|p_i - p_j| for every spring, and a global
/// step, the linear solve  Q p = M y/h² + Aᵀ K d + f_ext  with the constant matrix Q of
/// assemble_local_global_matrix (core/systems/local_global_system.h). Q is shared by the x, y
/// and z columns and factored in precompute (dense LLT for tiny systems, sparse Cholesky
/// otherwise); every iteration is one sweep down and up its factor for all columns. The
/// iterations start at y or, with IterationStart::kCurrent, at pⁿ; with few iterations the
/// start shapes the result. Then vⁿ⁺¹ = (pⁿ⁺¹ - pⁿ)/h. With enough iterations the result is
/// implicit Euler's (the Newton solution of ImplicitEuler) for undamped springs, from either
/// start.
///
/// Every force declares how it enters (Force::local_global_role, core/force.h): springs
/// (SpringForce, SpringSetForce, ElasticBodySpringForce with k = α / l0) as above; a force that
/// declares nothing makes precompute throw Error (kBadInput) naming it, rather than being
/// treated explicitly without a word. What else the solver takes implicitly, all of it keeping
/// Q constant:
/// - spring damping b_s as Laplacian damping (Li, Liu and Kavan, "Laplacian Damping for
///   Projective Dynamics", VRIPHYS 2018): the force -b_s (v_i - v_j) acts along every
///   direction, not only along the spring as in SpringForce; Q gains Aᵀ diag(b_s/h) A;
/// - anchors (DragSpringForce: a zero-rest-length spring to a point), which add k to Q's
///   diagonal; Q is refactored (numerically only) when the set of anchored particles or their
///   stiffnesses change, and a moving target only changes the right side;
/// - fixed particles, either eliminated (their rows and columns removed from Q; they move
///   with their own velocity, exactly, and receive no force) or held by penalty springs of
///   stiffness w to their anchors (Liu et al.'s w·CᵀC): the positions they have at this
///   integrator's first step, moved on with their velocity at that step. A penalty-pinned
///   particle is otherwise an ordinary particle, as in Liu et al. and the fast mass-springs
///   assignment: it receives every force, and the penalty holds it within about |f|/w.
/// - the penalty force's contacts with obstacles (half-planes, spheres; core/collisions/
///   penalty_force.h), each ½ k δ² = ½ k |p_i - t|² with t the nearest point of p_i out of
///   the obstacle's reach (radii plus thickness), which the local step recomputes like a
///   spring's direction. Particles within reach of an obstacle at the start of a step, with a
///   margin of twice the distance the old velocity carries them, get the term for the whole
///   step and add k to Q's diagonal: Q is refactored (numerically) when that set changes.
/// The forces declared explicit (gravity, constant forces, drag, vortices, Newtonian gravity,
/// the elastic bending and constant-strain-triangle forces, the penalty force between particles
/// and edges) are evaluated once per step at (pⁿ, vⁿ) and held constant as f_ext: exact for
/// gravity and constant forces, explicit for the rest, whose stiffness then bounds the stable
/// time step as in symplectic Euler. (Bending and CST energies are not squared distances to a
/// projection, so they have no constant matrix to join.)
template <int D>
class LocalGlobal final : public Integrator {
 public:
  explicit LocalGlobal(const LocalGlobalSettings& settings) : settings_(settings) {}

  /// Local/global iterations taken by the last step.
  int last_iterations() const { return last_iterations_; }
  /// The largest coordinate change of the last iteration of the last step (m).
  double last_change() const { return last_change_; }
  /// How many times Q has been factored (once in precompute, plus anchor and contact changes).
  int factorizations() const { return factorizations_; }
  SolverReport solver_report() const override {
    return {.iterations_of = "local-global",
            .last_step_iterations = last_iterations_,
            .factorizations = factorizations_};
  }
  /// The obstacle contacts of the last step (particle-obstacle pairs in Q).
  int last_contacts() const { return static_cast<int>(contacts_.size()); }
  /// The factorization in use.
  SpdSolver::Method solver_method() const { return solver_.method(); }

 protected:
  void prepare() override;
  void advance(State& state) override;

 private:
  /// A spring with the solver's indices: fi, fj are its ends among the free particles (-1 for
  /// an eliminated end).
  struct Spring {
    int i, j, fi, fj;
    double k, l0, b;
  };

  /// Remembers where penalty-pinned particles are at the first step, and how they move.
  void take_pins(const State& state);
  /// Gathers this step's anchors; returns their (particle, stiffness) pairs, which Q depends on.
  std::vector<std::pair<int, double>> collect_anchors(const State& state);
  /// Gathers this step's obstacle contacts (from pⁿ and y_); appends their (particle, k) to
  /// `signature`.
  void collect_contacts(const State& state, std::vector<std::pair<int, double>>& signature);
  /// Assembles and factors Q for anchors_ and contacts_.
  void factor();
  void assemble_constant_rhs(const State& state);
  /// Lists every free particle's springs (incidence_start_, incidence_).
  void list_incidences();
  /// The local step of every spring: kd_.
  void project_springs();
  /// `rhs` = constant_rhs_ plus, in every row, the k_s d_s of its springs (minus at a spring's j).
  void gather_spring_terms(Points<D>& rhs) const;
  /// The local step at p_, and the global step's right side it makes: constant_rhs_, every
  /// spring's k_s d_s added to its ends' rows, and the obstacle contacts' targets.
  void local_step(Points<D>& rhs);
  /// The local step of the obstacle contacts: k times each one's target.
  void add_contact_targets(Points<D>& rhs) const;
  double global_solve(Points<D>& rhs);
  /// The iterations of a step from p_ = y, plain or accelerated; p_ ends at the last iterate.
  void iterate();
  void iterate_anderson();
  void iterate_chebyshev();
  /// The free particles' rows of p_ as one vector, and back.
  Vector free_positions() const;
  void set_free_positions(const Vector& u);
  /// The energy local/global iterations decrease, at p_: ½|p - y|²_M / h² + the springs'
  /// ½ k (|δ| - l)² and Laplacian damping ½ (b/h) |δ - δⁿ|², the anchors' ½ k |p - a|², and the
  /// explicit forces' -f·p (over the free particles; up to a constant). *round_off: the size
  /// of its rounding error.
  double energy(double* round_off) const;

  LocalGlobalSettings settings_;
  MassSpringForces split_;
  FreeDofs free_;
  std::vector<Spring> springs_;
  // Penalty pins: anchors taken at the first step.
  std::vector<int> pinned_;
  bool pins_taken_ = false;
  Points<D> pin_position_, pin_velocity_;
  std::int64_t pin_step_ = 0;
  std::vector<AnchorTerm> anchors_;                       // this step's anchors (free particles)
  std::vector<std::pair<int, double>> factored_anchors_;  // (particle, k) in Q
  const PenaltyForce<D>* penalty_ = nullptr;              // the model's, or null
  /// A free particle (f, its index among them) and an obstacle within its reach this step.
  struct ObstacleContact {
    int f;
    CandidatePair pair;
  };
  std::vector<ObstacleContact> contacts_;
  SpdSolver solver_;
  Vector start_q_;  // qⁿ, for the energy of accelerated iterations
  AndersonAcceleration anderson_;
  Points<D> y_;  // pⁿ + h vⁿ, every particle
  Points<D> p_;  // the current iterate, every particle
  // k_s d_s: the springs' directions times rest lengths and stiffnesses, kept between
  // iterations (a spring of length 0 keeps its last direction)
  Points<D> kd_;
  // The springs of free particle f: incidence_[incidence_start_[f] .. incidence_start_[f+1]),
  // s + 1 where it is the spring's i, -(s + 1) where it is its j, in increasing s.
  std::vector<int> incidence_start_, incidence_;
  Points<D> constant_rhs_;  // the right side without the springs' directions
  Points<D> rhs_;
  Vector explicit_gradient_;
  int last_iterations_ = 0;
  double last_change_ = 0.0;
  int factorizations_ = 0;
};

/// Registry entry: "local-global", also "fast-mass-springs". Options: iterations, tolerance,
/// start, pins, penalty, solver.
extern const IntegratorMethod kLocalGlobalMethod;

/// Registry entry: "accelerated-local-global", also "anderson-local-global": LocalGlobal with
/// Acceleration::kAnderson (or kChebyshev). Options: those of local-global, and acceleration,
/// window, rho.
extern const IntegratorMethod kAcceleratedLocalGlobalMethod;

/// The settings the options of kLocalGlobalMethod hold.
LocalGlobalSettings local_global_settings(const OptionValues& options);

}  // namespace fosssim
