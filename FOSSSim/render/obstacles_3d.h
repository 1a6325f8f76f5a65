#pragma once
// The obstacles of a 3D picture: half-spaces as tiled patches of their boundary, spheres as
// shaded facets.

#include <Eigen/Core>
#include <vector>

#include "core/scene.h"
#include "render/drawing.h"
#include "render/orbit_camera.h"

namespace fosssim {

/// Tiles along each side of a half-space's patch; facets of a sphere around and from pole to pole.
inline constexpr int kTiles = 16;
inline constexpr int kSphereSlices = 32;
inline constexpr int kSphereStacks = 16;

/// Where a 3D scene is, for drawing its half-spaces: a half-space is drawn as the square patch of
/// its boundary around the projection of `center`, of half-width kPatchScale · size.
struct ObstacleFrame {
  static constexpr double kPatchScale = 2.0;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double size = 1.0;  ///< world units, > 0
};

/// The frame of `scene`: the bounding box of its initial particles and its spheres, centre and
/// half-diagonal (at least 1).
ObstacleFrame compute_obstacle_frame(const Scene& scene);

/// The half-spaces of a 3D scene, as `regions` (painted before every shape, docs/viewing.md):
/// each boundary patch cut into kTiles × kTiles square tiles in two alternating shades of its
/// colour (a checkerboard, so the floor reads in perspective), shaded like a surface, each
/// tile clipped to the free side of the other half-spaces. A half-space is drawn only when the
/// eye is on its free side (looking at it from outside the solid); then nothing on the free
/// side of it can be behind it, which is why painting it first is right. Tiles with a corner
/// behind the near plane are left out.
void add_half_space_regions(const Scene& scene, const ObstacleFrame& frame,
                            const OrbitCamera& camera, const OrbitProjection& projection,
                            std::vector<Region>& regions);

/// A triangle with the depth it is sorted by.
struct DepthShape {
  double depth;
  Triangle triangle;
};

/// The triangles of a UV sphere of kSphereSlices × kSphereStacks facets for each of the scene's
/// spheres, shaded, with the depth of each (the mean of its corners'), for depth sorting with
/// the other shapes. Facets with a corner behind the near plane are left out.
std::vector<DepthShape> sphere_triangles(const Scene& scene, const OrbitCamera& camera,
                                         const OrbitProjection& projection);

}  // namespace fosssim
