#pragma once
// What a window needs to pick a particle and drag it with a spring; no window code.

#include <Eigen/Core>
#include <optional>

#include "core/forces/drag_spring_force.h"
#include "core/scene_model.h"
#include "core/types.h"

namespace fosssim {

/// A half-line origin + t·direction, t ≥ 0, in world coordinates. For a 2D scene seen from
/// +z, a mouse position (x, y) is the ray from (x, y, 1) along (0, 0, -1).
struct Ray {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = -Eigen::Vector3d::UnitZ();  ///< need not be unit length
};

/// Appends an inactive DragSpringForce to model.forces and returns it. It sums after every
/// other force, so results are unchanged until something is grabbed. Call it before a
/// Simulation (and its integrator) is made from the model; the model owns the force.
DragSpringForce& add_drag_spring(SceneModel& model);

/// The model's drag spring (the last one added), or nullptr.
DragSpringForce* find_drag_spring(const SceneModel& model);

/// The particle to grab under a ray: among particles whose distance to the ray is at most
/// `radius` (world units), the one nearest the ray's origin along it; of those equally near
/// (all of them in a 2D scene seen from above), the one nearest the ray. Positions q are
/// interleaved in dimension dim (2D particles lie in the plane z = 0). nullopt when none.
std::optional<int> pick_particle(const Vector& q, int dim, const Ray& ray, double radius);

/// Where to pull a grabbed particle: the ray's intersection with the plane through
/// plane_point with normal plane_normal (typically the grabbed particle's position and the
/// view direction, so the particle follows the mouse at constant depth). nullopt when the
/// ray is parallel to the plane or points away from it.
std::optional<Eigen::Vector3d> drag_target(const Ray& ray, const Eigen::Vector3d& plane_point,
                                           const Eigen::Vector3d& plane_normal);

/// A drag stiffness that is stiff but stable with every integrator: k = m_p / h² (N/m), the
/// stiffness at which one implicit Euler step covers half the distance to the target and
/// symplectic Euler stays stable (h²k/m = 1 < 4).
double suggest_drag_stiffness(const SceneModel& model, int particle);

}  // namespace fosssim
