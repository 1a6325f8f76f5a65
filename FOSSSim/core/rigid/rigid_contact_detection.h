#pragma once
// Contact detection between planar rigid bodies (docs/rigid-bodies.md, "Contact"): the course's
// vertex–edge test, its ordered de-duplicating set of contacts, and a broad phase that finds
// exactly the same set without testing every pair of bodies.

#include <set>
#include <vector>

#include "core/rigid/rigid_bodies.h"

namespace fosssim {

/// One contact between bodies i0 < i1, as the course stores it: the contact point on each body
/// in body space (ρ, the arm R(θ)ᵀ(q − X) of the surface point q) and the unit normal n̂, which
/// points from body i0 towards body i1.
struct RigidContact {
  int i0 = 0, i1 = 0;
  Vec2 arm0 = Vec2::Zero(), arm1 = Vec2::Zero();
  Vec2 normal = Vec2::Zero();
};

/// The course's order of contacts: lexicographic on (i0, i1, ρ0x, ρ0y, ρ1x, ρ1y, n̂x, n̂y); the
/// bodies compare exactly, each pair of doubles counts as equal when |a − b| ≤ 1e-9 and
/// otherwise the smaller comes first. Not a strict weak order (equality within a tolerance is
/// not transitive), so a set built with it depends on the order of insertion, as the course's
/// does: contacts must be inserted in the course's order (detect_rigid_contacts_all_pairs).
struct RigidContactOrder {
  static constexpr double kTolerance = 1e-9;
  bool operator()(const RigidContact& a, const RigidContact& b) const;
};

/// An ordered set of contacts: inserting one equal (in RigidContactOrder's sense) to one already
/// present keeps the first. This drops the two reports of one vertex–vertex contact and a vertex
/// touching two adjacent edges at their shared vertex.
using RigidContactSet = std::set<RigidContact, RigidContactOrder>;

/// The course's vertex–edge test of vertex `p` of body `a` against the edge from `e0` to `e1`
/// of body `b` (world coordinates): α = ((p − e0)·E)/|E|² clamped to [0, 1] (NaN → 0), the
/// closest point c = e0 + αE, n = c − p, d = |n|; a contact iff d < r_a + r_b (strict). The
/// contact points are n̂ r_a + p on a and c − n̂ r_b on b, stored as body-space arms; the
/// contact is oriented from the lower body index to the higher one. Returns false when there
/// is no contact. d = 0 gives a non-finite normal, as in the course (see has_finite_normal).
bool test_vertex_edge(const RigidBodies& bodies, const Vector& q, int a, const Vec2& p, int b,
                      const Vec2& e0, const Vec2& e1, RigidContact& out);

/// Inserts into `set` the contacts of bodies i < j in the course's order: every vertex of i
/// against every edge of j, then every vertex of j against every edge of i.
void add_pair_contacts(const RigidBodies& bodies, const Vector& q, int i, int j,
                       RigidContactSet& set);

/// The course's detection ("all-pairs"): every pair i < j in order. O(B²) pairs; a reference for
/// tests and small scenes.
std::vector<RigidContact> detect_rigid_contacts_all_pairs(const RigidBodies& bodies,
                                                          const Vector& q);

/// The same contacts, in the same order, bit for bit, found with a broad phase: bounding boxes
/// of each body's world vertices grown by its radius (and a round-off allowance) are filed in a
/// BoxGrid (core/collisions/box_grid.h), the pairs whose boxes overlap are sorted into the
/// course's pair order, and only they are tested. A pair whose boxes do not overlap has no
/// vertex within r_a + r_b of the other's edges, so it would add nothing. With a body whose
/// position is not finite every pair is tested.
std::vector<RigidContact> detect_rigid_contacts(const RigidBodies& bodies, const Vector& q);

/// The pairs (i < j) the broad phase of detect_rigid_contacts tests, in the course's order.
std::vector<std::pair<int, int>> rigid_candidate_pairs(const RigidBodies& bodies, const Vector& q);

/// False for a contact whose normal is NaN: a vertex exactly on another body's edge (d = 0).
bool has_finite_normal(const RigidContact& contact);

}  // namespace fosssim
