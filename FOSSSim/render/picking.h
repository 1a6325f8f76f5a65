#pragma once
// Which particle lies under a ray, and where a ray meets a plane: picking with the mouse.

#include <Eigen/Core>
#include <optional>

#include "core/types.h"

namespace fosssim {

/// A half-line origin + t·direction, t ≥ 0, in world coordinates. For a 2D scene seen from
/// +z, a mouse position (x, y) is the ray from (x, y, 1) along (0, 0, -1).
struct Ray {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = -Eigen::Vector3d::UnitZ();  ///< need not be unit length
};

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

}  // namespace fosssim
