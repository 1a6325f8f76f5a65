#pragma once
// The interface every force implements: energy, gradient and both Hessians.

#include <string>
#include <vector>

#include "core/hessian_builder.h"
#include "core/types.h"

namespace fosssim {

/// The point at which a force is evaluated, and what its hessX should be.
struct ForceInput {
  const Vector& q;     ///< positions, size dim*n
  const Vector& v;     ///< velocities, size dim*n
  const Vector& mass;  ///< per-DOF masses, size dim*n
  /// For add_hessian_x: add each element's block projected onto the positive semi-definite
  /// matrices (a compressed spring loses its negative transverse stiffness), so that
  /// M + h² hessX stays positive definite. Forces whose blocks are always semi-definite, or
  /// that cannot project, add their exact hessX.
  bool definite_hessian = false;
};

/// A force on the particles, written as the derivatives of a potential U (docs/forces.md).
/// Every method *adds* into its output: the gradient gradE = -F, hessX = -dF/dq and
/// hessV = -dF/dv. Non-conservative forces still report gradE = -F and add no energy.
class Force {
 public:
  virtual ~Force() = default;

  /// Adds the potential energy U(q); non-conservative forces add nothing.
  virtual void add_energy(const ForceInput& in, double& energy) const = 0;
  /// Adds -F(q, v) into gradient (size dim*n).
  virtual void add_gradient(const ForceInput& in, Vector& gradient) const = 0;
  /// Adds -dF/dq.
  virtual void add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const = 0;
  /// Adds -dF/dv.
  virtual void add_hessian_v(const ForceInput& in, HessianBuilder& hessian) const = 0;

  /// True when F derives from the energy reported by add_energy alone.
  virtual bool is_conservative() const = 0;
  /// True when the force at rest, F(q, 0), is -dU/dq for the energy of add_energy: true for
  /// conservative forces and for damping that vanishes at zero velocity, false for vortices.
  virtual bool has_potential() const { return true; }
  /// False when the force deliberately leaves its position Jacobian out of hessX, so that
  /// implicit integrators use it in their right-hand side only (the course's penalty force).
  virtual bool has_jacobian() const { return true; }
  /// False when hessX or hessV may be non-symmetric (damped springs, vortices).
  virtual bool has_symmetric_jacobians() const { return true; }
  /// A short label for messages, such as "springforce(edge 3)".
  virtual std::string label() const = 0;
};

}  // namespace fosssim
