#pragma once
// Responses to contact between rigid bodies (docs/rigid-bodies.md, "Contact"): the course's LCP
// and velocity projection, inelastic, and their generalized reflections (elastic). They change
// only the velocities (V, ω) of bodies that are not fixed.

#include <string>
#include <vector>

#include "core/rigid/contact_lcp.h"
#include "core/rigid/rigid_contact_detection.h"
#include "core/rigid/rigid_contact_settings.h"
#include "core/step/cancellation.h"

namespace fosssim {

/// The inelastic problem a response solves.
enum class ContactSolver {
  kLcp,                 ///< the course's LCP: b from every body's velocity, fixed ones included
  kVelocityProjection,  ///< the course's QP: fixed bodies' velocities ignored
};

/// What a response did, for tests and warnings.
struct ContactReport {
  int contacts = 0;  ///< contacts detected (fixed–fixed ones included)
  int groups = 0;    ///< independent groups of contacts solved (one problem each)
  /// LCP only: groups of contacts whose LCP was degenerate or whose library answer failed the
  /// check, answered with the velocity-projection solver instead.
  int fallbacks = 0;
  std::string fallback_reason;  ///< why the first fallback happened
  int reflections = 0;          ///< generalized reflections: inelastic solves taken
};

/// The normal Jacobian of one contact over the free bodies: η = (n̂, (R₁ρ₁) × n̂) on body i1 and
/// (−n̂, −(R₀ρ₀) × n̂) on body i0, nothing on a fixed body (its index is then -1).
struct ContactColumn {
  int body[2] = {-1, -1};  ///< i0 and i1, or -1 for a fixed body
  Vec<3> entries[2];
};
ContactColumn contact_column(const RigidBodies& bodies, const Vector& q,
                             const RigidContact& contact);

/// ġ = n̂·(v_{i1}(q₁) − v_{i0}(q₀)) at the contact points q_k = R_k ρ_k + X_k, with every
/// body's velocity as the course stores it (a fixed body's declared one): the LCP's b.
double contact_normal_velocity(const RigidBodies& bodies, const Vector& q, const Vector& v,
                               const RigidContact& contact);

/// The problem of `solver` for all `contacts` as one group, in their order, leaving out
/// contacts between two fixed bodies (for tests; the responses assemble one per group).
ContactProblem assemble_contact_problem(ContactSolver solver, const RigidBodies& bodies,
                                        const Vector& q, const Vector& v,
                                        const std::vector<RigidContact>& contacts);

/// Solves the inelastic problem of `solver` for `contacts` and adds M⁻¹Nλ to the velocities of
/// the free bodies. Contacts are split into independent groups (bodies linked by contacts,
/// fixed bodies linking nothing); contacts between two fixed bodies are left out (they cannot
/// change any velocity). LCP: ODE's Dantzig solver on each group whose A is not degenerate,
/// checked; a degenerate group, or one whose answer fails the check, gets the exact QP's answer
/// (the same velocities any valid impulse gives), counted in report.fallbacks.
/// A group of more than `max_group_contacts` contacts (its dense A alone holds their square of
/// doubles) is refused with SolverFailure (RigidContactSettings::max_group_contacts).
void apply_inelastic_response(
    ContactSolver solver, const RigidBodies& bodies, const Vector& q,
    const std::vector<RigidContact>& contacts, Vector& v, ContactReport& report,
    int max_group_contacts = RigidContactSettings::kDefaultMaxGroupContacts);

/// Generalized reflections (Smith, Kaufman, Vouga, Tamstorf, Grinspun 2012, Algorithm 2, fully
/// elastic): while some contact approaches (η·q̇ < −1e-14 over the free bodies), solve the
/// inelastic problem on the approaching contacts only, giving q̇*, and reflect q̇ ← 2q̇* − q̇.
/// Throws SolverFailure after `max_reflections` solves; asks `cancellation` once per reflection.
void apply_generalized_reflections(
    ContactSolver solver, const RigidBodies& bodies, const Vector& q,
    const std::vector<RigidContact>& contacts, int max_reflections, Vector& v,
    ContactReport& report, Cancellation cancellation = {},
    int max_group_contacts = RigidContactSettings::kDefaultMaxGroupContacts);

/// The course's threshold of an approaching contact in generalized reflections.
inline constexpr double kReflectionThreshold = -1e-14;

}  // namespace fosssim
