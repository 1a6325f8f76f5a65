#pragma once

#include <deque>
#include <utility>
#include <vector>

#include "core/integrators/integrator.h"
#include "core/solvers/spd_solver.h"
#include "core/systems/backward_euler.h"
#include "core/systems/free_dofs.h"
#include "core/systems/local_global_system.h"

namespace fosssim {

/// Settings of the "quasi-newton" integrator.
struct QuasiNewtonOptions {
  int iterations = 100;  ///< at most this many per step (the last iterate is kept)
  /// Stop once a correction is this small relative to the new velocities:
  /// ‖Δ‖∞ ≤ tolerance · max(‖vⁿ⁺¹‖∞, 1e-3 m/s); 0: always take `iterations`.
  double tolerance = 1e-6;
  int history = 5;  ///< L-BFGS pairs kept
};

/// Backward Euler by the quasi-Newton method of Liu, Bouaziz and Kavan, "Quasi-Newton Methods
/// for Real-time Simulation of Hyperelastic Materials", ACM TOG 36(3), 2017: L-BFGS on the
/// incremental potential Φ(dv) = ½ dvᵀM dv + U(qⁿ + h(vⁿ + dv)) (BackwardEulerStep), whose
/// initial Hessian is the constant matrix of the local/global solver, h² Q = M + h² Aᵀ K A
/// (+ h Aᵀ B A for damping, anchors on the diagonal; assemble_local_global_matrix), factored
/// once in precompute and applied to the x, y and z columns together. Each iteration takes the
/// L-BFGS direction (Nocedal's two-loop recursion over the last `history` pairs of steps and
/// gradient changes) and a backtracking line search on Φ (Armijo), then stops when the
/// correction is below the tolerance. Every force enters exactly, through its gradient and
/// energy: the solution is implicit Euler's (the Newton solution), not local/global's model.
/// Forces without a potential (damping, vortices) are taken the same way with full steps, as
/// there is then no Φ to search on. Fixed particles are eliminated: they keep their velocity.
///
/// Per iteration it costs one gradient, about one energy and one sweep of Q's factor, little
/// more than a local/global iteration, and it converges far faster on stiff springs, where
/// local/global's linear rate approaches 1.
class QuasiNewton final : public Integrator {
 public:
  explicit QuasiNewton(QuasiNewtonOptions options) : options_(options) {}

  /// Iterations taken by the last step.
  int last_iterations() const { return last_iterations_; }
  /// How many times Q has been factored (once in precompute, plus anchor changes).
  int factorizations() const { return factorizations_; }
  SolverReport solver_report() const override {
    return {.iterations_of = "quasi-newton",
            .last_step_iterations = last_iterations_,
            .factorizations = factorizations_};
  }

 protected:
  void prepare() override;
  void advance(State& state) override;

 private:
  /// The anchors of this step (drag springs), and Q factored for them.
  void update_anchors();
  void factor();
  /// d = H r over the free DOFs: the L-BFGS inverse Hessian applied to r.
  Vector lbfgs_direction(const Vector& r);
  /// x ← (h² Q)⁻¹ x over the free DOFs.
  void apply_initial_inverse(Vector& x) const;

  QuasiNewtonOptions options_;
  MassSpringForces split_;
  FreeDofs free_;
  std::vector<AnchorTerm> anchors_;
  std::vector<std::pair<int, double>> factored_anchors_;
  SpdSolver solver_;
  int factorizations_ = 0;
  std::deque<std::pair<Vector, Vector>> pairs_;  // (s, y) with y the change of -r
  int last_iterations_ = 0;
};

/// Registry entry: "quasi-newton", also "lbfgs". Options: iterations, tolerance, history.
extern const IntegratorMethod kQuasiNewtonMethod;

}  // namespace fosssim
