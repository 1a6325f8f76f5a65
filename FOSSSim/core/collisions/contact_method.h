#pragma once
// What the registry knows of one contact method: its name, options, the bodies and dimensions it
// handles, what its steps record, and the factories of its response stage and force.

#include <memory>
#include <span>
#include <string_view>

#include "core/integrators/integrator_options.h"

namespace fosssim {

class Force;
class StepStage;
struct RigidResponse;  // core/rigid/rigid_contact_stage.h
struct SceneModel;

/// The kinds of bodies a scene holds (docs/architecture.md, "A new kind of body").
enum class BodyKind {
  kParticles,          ///< particles (2D or 3D) with edges, half-planes and spheres
  kPlanarRigidBodies,  ///< planar rigid bodies (SceneModel::rigid_bodies is set)
};

/// The kind of body a model holds.
BodyKind body_kind(const SceneModel& model);
/// The dimension of the space a model's bodies move in: model.dim for particles, 2 for planar
/// rigid bodies (whose model.dim counts their three coordinates X, Y, θ).
int body_dimension(const SceneModel& model);

/// Which body kinds and dimensions a method handles: particles in 2D, particles in 3D, planar
/// rigid bodies (2D). A scene that names a method for bodies it does not handle is refused when
/// it is read, with `restriction` as the reason.
struct ContactScope {
  bool particles = true;             ///< particle scenes
  bool planar_rigid_bodies = false;  ///< planar rigid-body scenes (always 2D)
  bool runs_2d = true;
  bool runs_3d = true;
  /// Why a dimension is refused: "its rigid impact zones rotate in the plane".
  std::string_view restriction;

  bool handles(BodyKind kind) const {
    return kind == BodyKind::kParticles ? particles : planar_rigid_bodies;
  }
  bool handles_dim(int dim) const { return dim == 3 ? runs_3d : runs_2d; }
};

/// The scope of a particle method that runs in both dimensions.
inline constexpr ContactScope kParticlesIn2DAnd3D{};
/// The scope of a method of planar rigid bodies (<rigidbodycollisionhandling>).
inline constexpr ContactScope kPlanarRigidBodies{
    .particles = false,
    .planar_rigid_bodies = true,
    .runs_2d = true,
    .runs_3d = false,
    .restriction = "rigid bodies are planar",
};

/// Which parts of a step's StepRecord (core/step/step_record.h) a method fills, and so what a
/// particle trajectory file holds after each frame (docs/collisions.md, "Trajectory files"; the
/// layouts of the course's second milestone). io/trajectory_file.h calls it TrajectoryLayout.
enum class StepRecordLayout {
  kFrames,  ///< nothing: positions then velocities (Theme 1; types none and penalty)
  /// Each frame followed by int32 count and that many collision records (type simple).
  kCollisions,
  /// Each frame followed by its collisions, then int32 count and that many polynomials (int32
  /// length, then the coefficients, highest degree first); two records per step, the sync
  /// record and the end-of-step record (types continuous-time and hybrid).
  kCollisionsAndPolynomials,
};

/// One entry of the contact registry (contact_registry.h): how a scene handles contact, for
/// every kind of body: the `type` of a particle scene's <collision> element, the `response` of a
/// rigid-body scene's <rigidbodycollisionhandling>. Each method's file pair defines its entry
/// (a method without code of its own, "none", is defined in the registry; the four rigid-body
/// responses, which share one stage, are defined beside it); the registry lists them. The
/// loaders, --help, Python, the step pipeline (through ForceSet and make_contact_stage), the
/// trajectory writer and the tests read the entries; nothing else names a method.
struct ContactMethod {
  std::string_view name;     ///< the type (particles) or response (rigid bodies) string
  std::string_view summary;  ///< one line for --help and messages
  /// The method's settings, attributes of <collision>, read in this order (an attribute of
  /// <collision> that is no option of its method is reported as unknown). The particle methods'
  /// values land in CollisionSettings' fields of the same meaning (COR, k, thickness,
  /// penalty-jacobian, maxiters); every method's values are in CollisionSettings::options.
  std::span<const OptionSpec> options = {};
  ContactScope scope;  ///< by default, particles in 2D and 3D
  /// What a particle trajectory records after each frame. A rigid-body method records nothing
  /// (kFrames): the Theme 3 trajectory's layout is the body kind's (io/rigid_trajectory.h).
  StepRecordLayout records = StepRecordLayout::kFrames;
  /// The response stage run after the integrator in every step (core/step/step_pipeline.h), or
  /// null for a method without one. It reads everything it needs from `model`: the settings in
  /// model.collisions (the method, its option values, the particle methods' parameters) and
  /// the bodies (particles, edges, obstacles, model.rigid_bodies). `model` outlives the stage.
  std::unique_ptr<StepStage> (*make_stage)(const SceneModel& model) = nullptr;
  /// The contact force every integrator sums after the model's forces (core/force_set.h), or
  /// null for a method without one. `model` outlives the force.
  std::unique_ptr<Force> (*make_force)(const SceneModel& model) = nullptr;
  /// A planar rigid-body method's response (the inelastic problem it solves, whether it
  /// reflects), which its stage runs and the loader's warnings describe; null for the others.
  const RigidResponse* rigid_response = nullptr;
  /// True when the course's own messages list it among the valid values of its attribute;
  /// false for methods they leave out (gr-lcp and gr-velocity-projection, which the course's
  /// Theme 3 message does not name), which FOSSSim's messages add after the course's text.
  bool in_course_messages = true;
};

}  // namespace fosssim
