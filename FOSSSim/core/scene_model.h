#pragma once
// What a scene *is*: everything that does not change while it runs.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/force.h"
#include "core/types.h"

namespace fosssim {

/// The time-stepping method of a scene (SPEC section 4).
enum class IntegratorKind {
  kExplicitEuler,
  kSymplecticEuler,
  kLinearizedImplicitEuler,
  kImplicitEuler,
  /// The local/global solver of Liu et al. 2013 for mass-spring systems
  /// (integrators/local_global.h).
  kLocalGlobal,
  /// Linearly implicit Euler linearized at (qⁿ, vⁿ) with fixed particles projected out, as in
  /// the CSC417 mass-spring assignment (integrators/linearly_implicit_euler.h). Not the compat
  /// kLinearizedImplicitEuler, which linearizes at the predicted position qⁿ + h vⁿ.
  kLinearlyImplicitEuler,
};

/// Canonical XML name of an integrator kind ("explicit-euler", ...).
const char* integrator_name(IntegratorKind kind);

/// Settings of Newton's method in implicit Euler.
struct NewtonSettings {
  double tolerance = 1e-9;   ///< stop when the L2 norm of a correction is below this (compat)
  int max_iterations = 200;  ///< give up and report non-convergence after this many
};

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

/// Settings of the local/global solver (Liu et al. 2013).
struct LocalGlobalSettings {
  /// kAuto solves systems of at most this many free particles densely.
  static constexpr int kDenseLimit = 64;
  int iterations = 10;     ///< local/global iterations per step (the most, with a tolerance)
  double tolerance = 0.0;  ///< stop once no coordinate moved more than this (m); 0: never
  PinMethod pins = PinMethod::kElimination;
  double penalty_weight = 1e10;  ///< w of the penalty pins, N/m
  LinearSolverChoice solver = LinearSolverChoice::kAuto;
};

/// Settings of the linearly implicit Euler integrator.
struct LinearlyImplicitSettings {
  /// Project each spring's Hessian onto the positive semi-definite matrices (a compressed
  /// spring loses its negative transverse stiffness), so the step matrix is positive definite.
  bool project_hessian = false;
};

struct IntegratorSettings {
  IntegratorKind kind = IntegratorKind::kExplicitEuler;
  double dt = 0.01;  ///< time step h, seconds
  NewtonSettings newton;
  LocalGlobalSettings local_global;
  LinearlyImplicitSettings linearly_implicit;
};

/// A line segment between two particles; springs live on edges.
struct Edge {
  int i = 0;
  int j = 0;
};

/// The fixed part of a scene: particles' masses and fixed flags, topology, forces in the compat
/// summation order, and how to step. Positions and velocities live in State.
struct SceneModel {
  int dim = 2;              ///< 2 or 3
  Vector mass;              ///< per degree of freedom: [m0, m0, m1, m1, ...], size dim*n
  std::vector<bool> fixed;  ///< per particle; fixed particles receive no force
  std::vector<Edge> edges;
  std::vector<std::unique_ptr<Force>> forces;  ///< summed in this order
  IntegratorSettings integrator;
  double duration = 0.0;  ///< simulated seconds

  int num_particles() const { return static_cast<int>(fixed.size()); }
  int num_dofs() const { return dim * num_particles(); }
  bool is_fixed_dof(int dof) const { return fixed[dof / dim]; }
  bool has_fixed_particles() const;
  /// ceil(duration / dt) in double precision (4.0 / 0.01 gives 400), the number of steps a run
  /// takes.
  std::int64_t num_steps() const;
  /// True when every force's Jacobians are symmetric, so the step matrix is symmetric.
  bool has_symmetric_jacobians() const;
  /// True when every force derives from the potential energy its add_energy reports.
  bool is_conservative() const;
};

}  // namespace fosssim
