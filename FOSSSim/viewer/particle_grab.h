#pragma once
// Picking a particle with the mouse and pulling it with a drag spring the window owns: the
// window's ctrl + left drag, without window code.

#include <Eigen/Core>
#include <optional>

#include "core/forces/drag_spring_force.h"
#include "core/forces/rigid_body_drag_force.h"
#include "core/scene.h"
#include "core/state.h"
#include "render/drawing.h"
#include "render/scene_view.h"

namespace fosssim {

/// A particle is picked when the cursor's ray passes within this many pixels of its centre (or
/// within its radius, if that is larger).
inline constexpr double kPickPixels = 8.0;

/// A drag stiffness that is stiff but stable with every integrator: k = m_p / h² (N/m), the
/// stiffness at which one implicit Euler step covers half the distance to the target and
/// symplectic Euler stays stable (h²k/m = 1 < 4).
double suggest_drag_stiffness(const SceneModel& model, int particle);

/// The drag spring's stiffness for `particle`, N/m: k = M / h², with M the particle's mass for
/// explicit and symplectic Euler (suggest_drag_stiffness: stable, h²k/m = 1) and the total mass
/// of the free particles for the implicit integrators, which are stable at any stiffness: one
/// implicit step then takes a whole body half way to the cursor, as it would a lone particle.
double drag_stiffness(const SceneModel& model, int particle);

/// The drag spring's stiffness for point `arm` (R(θ)p, world orientation, from the centre of
/// mass) of rigid body `body`: k = m_a / h² with m_a = 1 / (1/M + |arm|²/I), the body's mass as
/// felt at that point across the arm, so that symplectic Euler stays stable (h²k/m_a = 1 < 4)
/// wherever the body is grabbed (k = M/h², right at the centre, would be unstable at a point far
/// out on a body of small I).
double rigid_drag_stiffness(const SceneModel& model, int body, const Vec<2>& arm);

/// The rigid body under world point `point` (z ignored) of a rigid-body scene's state: the last
/// body (drawn on top) whose hull contains it, else the nearest whose hull thickened by its
/// radius and `slack` contains it; nullopt when none.
std::optional<int> pick_rigid_body(const SceneModel& model, const State& state,
                                   const Vec<2>& point, double slack);

/// Grabs the particle under the cursor and pulls it with its drag spring (a zero-rest-length
/// spring, core/forces/drag_spring_force.h) toward the point under the cursor on the drag
/// plane: the plane through the particle, where it was grabbed, facing the camera (in 2D the
/// plane z = 0). The pull starts at the particle itself and keeps the offset between the cursor
/// and the particle, so grabbing does not jerk it.
///
/// The grab owns the spring; the window hands it to the simulation as an interaction force
/// (interaction_force(), passed in StepAdditions::interaction_forces), so the scene's model
/// never holds it. The simulation sees each change at its next step.
///
/// In a rigid-body scene the grab picks a body (pick_rigid_body) and pulls the point of the
/// body under the cursor toward the cursor with the rigid-body spring to a world point
/// (RigidBodyDragForce, stiffness rigid_drag_stiffness): the body turns as well as moves, as
/// the course's rigid-body springs make it.
class ParticleGrab {
 public:
  /// scene: the running scene; it outlives this.
  explicit ParticleGrab(const Scene& scene);
  /// The drag spring must stay where it is: the simulation holds its address.
  ParticleGrab(const ParticleGrab&) = delete;
  ParticleGrab& operator=(const ParticleGrab&) = delete;

  /// The particles' drag spring; idle until something is grabbed.
  const DragSpringForce& force() const { return spring_; }
  /// The rigid bodies' drag spring; idle until a body is grabbed.
  const RigidBodyDragForce& rigid_force() const { return rigid_spring_; }
  /// The drag spring of this scene's kind (rigid bodies or particles), for the simulation's
  /// interaction forces.
  const Force& interaction_force() const;

  /// Picks the particle under pixel (px, py) of `view`, which shows `state`
  /// (pick_particle: the nearest along the ray within the pick distance) and grabs it with
  /// drag_stiffness. Fixed particles cannot be pulled: picking one grabs nothing. Returns true
  /// when a particle was grabbed.
  bool press(const SceneView& view, const State& state, double px, double py);
  /// Pulls toward the point under (px, py) on the drag plane (unchanged when the ray misses it).
  void move(const SceneView& view, double px, double py);
  /// Lets go.
  void release() {
    spring_.release();
    rigid_spring_.release();
  }

  bool active() const { return spring_.active() || rigid_spring_.active(); }
  /// The line to draw while a particle or a body is pulled.
  std::optional<DragGuide> guide() const;

 private:
  const SceneModel& model_;
  DragSpringForce spring_;
  RigidBodyDragForce rigid_spring_;
  /// Rigid bodies: picks the body under the cursor and grabs its point there.
  bool press_rigid(const SceneView& view, const State& state, double px, double py);
  double largest_radius_ = 0.0;  ///< of the scene's particles, world units
  Eigen::Vector3d plane_point_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d plane_normal_ = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d offset_ = Eigen::Vector3d::Zero();  ///< particle minus the cursor's point
};

}  // namespace fosssim
