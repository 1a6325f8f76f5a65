#pragma once
// How a rigid-body scene handles contact: <rigidbodycollisionhandling> (docs/rigid-bodies.md).

namespace fosssim {

struct RigidContactMethod;  // core/rigid/rigid_contact_method.h

struct RigidContactSettings {
  /// The response; null when the scene has no <rigidbodycollisionhandling> (no contact).
  const RigidContactMethod* method = nullptr;
  /// Generalized reflections: the most reflections one step may take (the course's loop has no
  /// limit and never ends when a fixed body declares a velocity into a resting body). FOSSSim's
  /// own attribute maxreflections="..." raises it.
  static constexpr int kDefaultMaxReflections = 10000;
  int max_reflections = kDefaultMaxReflections;
};

}  // namespace fosssim
