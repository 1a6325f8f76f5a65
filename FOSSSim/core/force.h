#pragma once
// The interface every force implements: energy, gradient and both Hessians.

#include <string>
#include <vector>

#include "core/hessian_builder.h"
#include "core/spring_terms.h"
#include "core/types.h"

namespace fosssim {

/// The point at which a force is evaluated.
struct ForceInput {
  const Vector& q;     ///< positions, size dim*n
  const Vector& v;     ///< velocities, size dim*n
  const Vector& mass;  ///< per-DOF masses, size dim*n
};

/// A force on the particles, written as the derivatives of a potential U (SPEC section 3).
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
  /// False when hessX or hessV may be non-symmetric (damped springs, vortices).
  virtual bool has_symmetric_jacobians() const { return true; }
  /// A short label for messages, such as "springforce(edge 3)".
  virtual std::string label() const = 0;

  /// For solvers that take springs implicitly (the local/global solver of Liu et al. 2013):
  /// when this force is exactly a set of springs (SpringTerm, with their damping), appends them
  /// and returns true. Otherwise returns false and appends nothing; the default. The springs
  /// must not change while a simulation runs.
  virtual bool append_springs(std::vector<SpringTerm>& springs) const {
    (void)springs;
    return false;
  }
  /// Likewise for zero-rest-length springs to points in space (AnchorTerm). Unlike springs,
  /// anchors may change between steps (a particle dragged with the mouse); solvers ask again
  /// every step. A force that returns true and appends nothing currently adds no force.
  virtual bool append_anchors(std::vector<AnchorTerm>& anchors) const {
    (void)anchors;
    return false;
  }
};

}  // namespace fosssim
