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
};

/// Canonical XML name of an integrator kind ("explicit-euler", ...).
const char* integrator_name(IntegratorKind kind);

/// Settings of Newton's method in implicit Euler.
struct NewtonSettings {
  double tolerance = 1e-9;  ///< stop when the L2 norm of a correction is below this (compat)
  int max_iterations = 200;  ///< give up and report non-convergence after this many
};

struct IntegratorSettings {
  IntegratorKind kind = IntegratorKind::kExplicitEuler;
  double dt = 0.01;  ///< time step h, seconds
  NewtonSettings newton;
};

/// A line segment between two particles; springs live on edges.
struct Edge {
  int i = 0;
  int j = 0;
};

/// The fixed part of a scene: particles' masses and fixed flags, topology, forces in the compat
/// summation order, and how to step. Positions and velocities live in State.
struct SceneModel {
  int dim = 2;                  ///< 2 or 3
  Vector mass;                  ///< per degree of freedom: [m0, m0, m1, m1, ...], size dim*n
  std::vector<bool> fixed;      ///< per particle; fixed particles receive no force
  std::vector<Edge> edges;
  std::vector<std::unique_ptr<Force>> forces;  ///< summed in this order
  IntegratorSettings integrator;
  double duration = 0.0;  ///< simulated seconds

  int num_particles() const { return static_cast<int>(fixed.size()); }
  int num_dofs() const { return dim * num_particles(); }
  bool is_fixed_dof(int dof) const { return fixed[dof / dim]; }
  bool has_fixed_particles() const;
  /// ceil(duration / dt) in double precision (4.0 / 0.01 gives 400), the number of steps a run takes.
  std::int64_t num_steps() const;
  /// True when every force's Jacobians are symmetric, so the step matrix is symmetric.
  bool has_symmetric_jacobians() const;
  /// True when every force derives from the potential energy its add_energy reports.
  bool is_conservative() const;
};

}  // namespace fosssim
