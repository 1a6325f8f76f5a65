#pragma once
// The interface every force implements: energy, gradient and both Hessians.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/hessian_builder.h"
#include "core/spring_terms.h"
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

/// How a force enters the local/global solver of Liu et al. 2013 (core/integrators/local_global.h,
/// docs/integrators.md), which keeps its system matrix constant and so can take only forces of
/// a few shapes implicitly. Every force says which shape it has; sort_mass_spring_forces
/// (core/systems/local_global_system.h) sorts a force set by it.
enum class LocalGlobalRole {
  /// The force has not said: the local/global solver refuses a scene with it (Error kBadInput,
  /// naming the force) rather than guess. The default, so that a new force must choose.
  kUndeclared,
  /// Hookean springs ½ k (|x_i - x_j| - l0)² (with Laplacian damping b): their k enters the
  /// constant matrix, their directions the local step. Force::append_local_global_springs lists
  /// them.
  kSprings,
  /// One zero-rest-length spring ½ k |x_i - t|² to a point that may change between steps
  /// (the mouse's drag spring): Force::local_global_anchor says where, every step.
  kAnchor,
  /// The penalty force (core/collisions/penalty_force.h): contacts with obstacles implicit, its
  /// particle-edge pairs explicit.
  kContact,
  /// Evaluated once per step at (qⁿ, vⁿ) and held constant through the step's iterations: exact
  /// for forces that do not depend on the state (gravity, constant forces), an explicit term
  /// for the others, which limits the stable time step as in symplectic Euler.
  kExplicit,
};

/// A piece of a force that pictures show (render/drawing.h): a triangle of an elastic body,
/// drawn filled, or a hinge of a bending rod, drawn as its two edges; with how deformed it is
/// at the positions it was asked at, for colouring by strain or energy density.
struct ForceElement {
  enum class Kind { kTriangle, kHinge };
  Kind kind = Kind::kTriangle;
  /// A triangle's corners, or a hinge's particles (the middle one is the hinge).
  std::array<int, 3> particles{};
  /// Signed and dimensionless. Triangles: the principal stretch λ - 1 of largest magnitude
  /// (λ² the eigenvalues of FᵀF: > 0 stretched, < 0 compressed, 0 at rest). Hinges: θ - θ0 (rad).
  double strain = 0.0;
  /// Energy per rest area (triangles, J/m²) or per rest length (hinges, J/m), ≥ 0.
  double energy_density = 0.0;
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

  /// How the local/global solver takes this force (LocalGlobalRole); kUndeclared unless the
  /// force says otherwise.
  virtual LocalGlobalRole local_global_role() const { return LocalGlobalRole::kUndeclared; }
  /// For LocalGlobalRole::kSprings: appends the force's springs in its own order (the order
  /// fixes the solver's sums); other forces append nothing.
  virtual void append_local_global_springs(std::vector<SpringTerm>& /*springs*/) const {}
  /// For LocalGlobalRole::kAnchor: the anchor as it is now, or nothing when the force pulls
  /// nothing at the moment; other forces return nothing.
  virtual std::optional<AnchorTerm> local_global_anchor() const { return std::nullopt; }

  /// Appends the elements pictures show of this force at positions q (ForceElement): the
  /// elastic-body triangles and hinges; other forces append nothing.
  virtual void append_elements(const Vector& /*q*/, std::vector<ForceElement>& /*elements*/) const {}
};

}  // namespace fosssim
