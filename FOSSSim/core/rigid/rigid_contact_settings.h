#pragma once
// How a rigid-body scene handles contact: <rigidbodycollisionhandling> (docs/rigid-bodies.md).

namespace fosssim {

/// FOSSSim's limits of rigid-body contact. The response itself is the scene's contact method,
/// model.collisions.method (an entry of core/collisions/contact_registry.h; "none" when the
/// scene has no <rigidbodycollisionhandling>).
struct RigidContactSettings {
  /// Generalized reflections: the most reflections one step may take (the course's loop has no
  /// limit and never ends when a fixed body declares a velocity into a resting body). FOSSSim's
  /// own attribute maxreflections="..." raises it.
  static constexpr int kDefaultMaxReflections = 10000;
  int max_reflections = kDefaultMaxReflections;
  /// The most contacts one group (bodies linked by contacts) may hold: its problem is dense (A
  /// has their square of doubles: 32 MB at the default). FOSSSim's own attribute
  /// maxgroupcontacts="..." raises it.
  static constexpr int kDefaultMaxGroupContacts = 2000;
  int max_group_contacts = kDefaultMaxGroupContacts;
};

}  // namespace fosssim
