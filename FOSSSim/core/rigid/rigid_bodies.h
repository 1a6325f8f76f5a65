#pragma once
// Planar rigid bodies as generalized coordinates (docs/rigid-bodies.md).
//
// A scene of B rigid bodies is a SceneModel with dim = 3 and one "particle" per body whose
// three coordinates are (X_x, X_y, θ): the centre of mass and the angle. Its per-coordinate
// masses are (M, M, I), its velocities (V_x, V_y, ω), its forces (F_x, F_y, τ). Integrators,
// force sums, stages and the step pipeline run rigid bodies unchanged; what only bodies have
// (their polygons, radii, the velocity a fixed body reports) lives here, shared by the forces,
// the files and the pictures.

#include <span>
#include <vector>

#include "core/rigid/rigid_contact_settings.h"
#include "core/types.h"

namespace fosssim {

using Vec2 = Vec<2>;

/// Coordinates per rigid body in q and v: (X_x, X_y, θ) and (V_x, V_y, ω).
inline constexpr int kRigidBodyCoordinates = 3;

/// A body's mass M, centre of mass X and moment of inertia I about X, from its hull vertices
/// taken as point masses (the course's Theme 3 rule, not the polygon's area).
struct MassProperties {
  double mass = 0.0;
  Vec2 center = Vec2::Zero();
  double inertia = 0.0;
};

/// Mass properties of point masses `masses` at `points` (same size, at least one), in the
/// course program's order of operations, bit for bit: M sums the even-indexed and the
/// odd-indexed masses separately, adds the two, then the last mass when the count is odd;
/// X = (Σ m_i r_i)·(1/M) summed in order; I = Σ m_i ((y_i − X_y)² + (x_i − X_x)²) in order.
MassProperties compute_mass_properties(std::span<const Vec2> points,
                                       std::span<const double> masses);

/// One rigid body: what does not change while a scene runs.
struct RigidBody {
  std::vector<int> hull;               ///< indices into the scene's vertex list, in file order
  std::vector<Vec2> body_points;       ///< hull vertex minus the initial centre of mass, hull order
  double mass = 0.0;                   ///< M = Σ m_i
  double inertia = 0.0;                ///< I about the centre of mass
  Vec2 initial_center = Vec2::Zero();  ///< X at load time, for the file's start block
  double radius = 0.1;                 ///< thickness for contact and pictures (> 0)
  bool fixed = false;
  /// A fixed body never moves; the course still reports the velocity its scene declared
  /// (trajectory file, momentum, energies). State::v holds 0 for it, this holds what is reported.
  Vec2 reported_velocity = Vec2::Zero();
  double reported_omega = 0.0;

  int num_vertices() const { return static_cast<int>(body_points.size()); }
};

/// The bodies of a scene, numbered in file order (body b is coordinates 3b..3b+2).
struct RigidBodies {
  std::vector<RigidBody> bodies;
  /// Contact between the bodies (milestone 2), none by default.
  RigidContactSettings contact;
  int size() const { return static_cast<int>(bodies.size()); }
};

/// R(θ) p, with R rebuilt from cos θ and sin θ (the course's order: (c p_x − s p_y, s p_x + c
/// p_y)).
Vec2 rotate(double theta, const Vec2& p);
/// The centre of mass X of body b in q.
inline Vec2 body_center(const Vector& q, int b) { return {q[3 * b], q[3 * b + 1]}; }
inline double body_angle(const Vector& q, int b) { return q[3 * b + 2]; }
/// World position of vertex k of body b: R(θ) b_k + X.
Vec2 world_vertex(const RigidBody& body, const Vector& q, int b, int k);
/// Velocity of the world point p of body b: V + ω × (p − X), with s × u = (−s u_y, s u_x).
Vec2 point_velocity(const Vector& q, const Vector& v, int b, const Vec2& p);
/// The velocity a trajectory reports for body b: its own, or a fixed body's declared one.
Vec2 reported_velocity(const RigidBodies& bodies, const Vector& v, int b);
double reported_omega(const RigidBodies& bodies, const Vector& v, int b);

/// The derived quantities of one body that the course's trajectory file holds (its formulas
/// and order of operations): P = M V, L_cm = (X_x V_y − X_y V_x) M, L_spin = I ω,
/// T_cm = (½M)(V_y² + V_x²), T_spin = (½I) ω ω, with a fixed body's reported velocity.
struct BodyQuantities {
  Vec2 momentum = Vec2::Zero();
  double orbital_angular_momentum = 0.0;
  double spin_angular_momentum = 0.0;
  double orbital_kinetic_energy = 0.0;
  double spin_kinetic_energy = 0.0;
};
BodyQuantities compute_body_quantities(const RigidBodies& bodies, const Vector& q, const Vector& v,
                                       int b);

}  // namespace fosssim
