#include "render/obstacles_3d.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/shading.h"

namespace fosssim {

namespace {

/// The second shade of a checkerboard: lighter for dark colours, darker for light ones.
Color checker_shade(const Color& c) {
  const double luminance = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
  if (luminance < 0.5) return {0.75 * c.r + 0.25, 0.75 * c.g + 0.25, 0.75 * c.b + 0.25};
  return {0.8 * c.r, 0.8 * c.g, 0.8 * c.b};
}

/// Cuts a convex polygon to the side (x - point)·normal ≤ 0 (Sutherland-Hodgman).
std::vector<Eigen::Vector3d> clip_to_solid_side(const std::vector<Eigen::Vector3d>& polygon,
                                                const Eigen::Vector3d& point,
                                                const Eigen::Vector3d& normal) {
  std::vector<Eigen::Vector3d> out;
  const std::size_t n = polygon.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector3d& a = polygon[k];
    const Eigen::Vector3d& b = polygon[(k + 1) % n];
    const double sa = (a - point).dot(normal), sb = (b - point).dot(normal);
    if (sa <= 0.0) out.push_back(a);
    if ((sa < 0.0 && sb > 0.0) || (sa > 0.0 && sb < 0.0))
      out.push_back(a + sa / (sa - sb) * (b - a));
  }
  return out;
}

/// Two unit vectors that make an orthonormal frame with the unit vector n.
std::pair<Eigen::Vector3d, Eigen::Vector3d> tangents(const Eigen::Vector3d& n) {
  const Eigen::Vector3d helper =
      std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d u = n.cross(helper).normalized();
  return {u, n.cross(u)};
}

/// True when the eye looks at the boundary from the free side (the outward normal's side).
bool seen_from_free_side(const OrbitProjection& projection, bool orthographic,
                         const Eigen::Vector3d& point, const Eigen::Vector3d& normal) {
  if (orthographic) return projection.forward().dot(normal) < 0.0;
  return (projection.eye() - point).dot(normal) > 0.0;
}

}  // namespace

ObstacleFrame compute_obstacle_frame(const Scene& scene) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY);
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-INFINITY);
  const int n = scene.model.num_particles();
  for (int p = 0; p < n; ++p) {
    const Eigen::Vector3d x = scene.initial.q.segment<3>(3 * p);
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  for (const Sphere& s : scene.model.spheres) {
    const Eigen::Vector3d c = s.center.head<3>();
    const Eigen::Vector3d r = Eigen::Vector3d::Constant(s.radius);
    lo = lo.cwiseMin(c - r);
    hi = hi.cwiseMax(c + r);
  }
  ObstacleFrame frame;
  if (lo.x() <= hi.x()) {
    frame.center = 0.5 * (lo + hi);
    frame.size = std::max(1.0, 0.5 * (hi - lo).norm());
  }
  return frame;
}

void add_half_space_regions(const Scene& scene, const ObstacleFrame& frame,
                            const OrbitCamera& camera, const OrbitProjection& projection,
                            std::vector<Region>& regions) {
  const auto& planes = scene.model.half_planes;
  const bool orthographic = camera.projection == Projection::kOrthographic;
  const Lighting light = camera_lighting(projection.right(), projection.up(), projection.forward());
  for (std::size_t h = 0; h < planes.size(); ++h) {
    const Eigen::Vector3d P = planes[h].point.head<3>();
    const Eigen::Vector3d N = planes[h].normal.head<3>();
    if (N.isZero(0.0) || !seen_from_free_side(projection, orthographic, P, N)) continue;
    const Eigen::Vector3d n = N.normalized();
    const auto [u, w] = tangents(n);
    const Eigen::Vector3d middle = frame.center - (frame.center - P).dot(n) * n;
    const double half = ObstacleFrame::kPatchScale * frame.size;
    const double tile = 2.0 * half / kTiles;
    const Color base = h < scene.appearance.half_plane_color.size()
                           ? scene.appearance.half_plane_color[h]
                           : Appearance::kDefaultHalfPlaneColor;
    // Every tile of a plane faces the same way: one shade per checker colour.
    const Eigen::Vector3d a = middle, b = middle + u, c = middle + w;
    const Eigen::Vector3d view =
        orthographic ? projection.forward() : Eigen::Vector3d(middle - projection.eye());
    const Color shades[2] = {shade_triangle(base, a, b, c, view, light),
                             shade_triangle(checker_shade(base), a, b, c, view, light)};
    for (int i = 0; i < kTiles; ++i) {
      for (int j = 0; j < kTiles; ++j) {
        const Eigen::Vector3d corner = middle + (i * tile - half) * u + (j * tile - half) * w;
        std::vector<Eigen::Vector3d> polygon = {corner, corner + tile * u, corner + tile * (u + w),
                                                corner + tile * w};
        for (std::size_t o = 0; o < planes.size() && polygon.size() >= 3; ++o) {
          if (o == h) continue;  // keep the part outside every other solid
          const Eigen::Vector3d No = planes[o].normal.head<3>();
          if (!No.isZero(0.0))
            polygon = clip_to_solid_side(polygon, planes[o].point.head<3>(), -No);
        }
        if (polygon.size() < 3) continue;
        Region region;
        region.color = shades[(i + j) % 2];
        bool visible = true;
        for (const Eigen::Vector3d& x : polygon) {
          const ProjectedPoint seen = projection.project(x);
          visible = visible && seen.visible;
          region.corners.push_back(seen.pixel);
        }
        if (visible) regions.push_back(std::move(region));
      }
    }
  }
}

std::vector<DepthShape> sphere_triangles(const Scene& scene, const OrbitCamera& camera,
                                         const OrbitProjection& projection) {
  std::vector<DepthShape> out;
  const Lighting light = camera_lighting(projection.right(), projection.up(), projection.forward());
  const bool orthographic = camera.projection == Projection::kOrthographic;
  const auto& spheres = scene.model.spheres;
  for (std::size_t s = 0; s < spheres.size(); ++s) {
    const Eigen::Vector3d center = spheres[s].center.head<3>();
    const double r = spheres[s].radius;
    const Color base = s < scene.appearance.sphere_color.size() ? scene.appearance.sphere_color[s]
                                                                : Appearance::kDefaultSphereColor;
    const auto point = [&](int slice, int stack) -> Eigen::Vector3d {
      const double phi = 2.0 * std::numbers::pi * slice / kSphereSlices;
      const double theta = std::numbers::pi * stack / kSphereStacks;
      return center + r * Eigen::Vector3d(std::sin(theta) * std::cos(phi), std::cos(theta),
                                          std::sin(theta) * std::sin(phi));
    };
    const auto add = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         const Eigen::Vector3d& c) {
      const ProjectedPoint pa = projection.project(a), pb = projection.project(b),
                           pc = projection.project(c);
      if (!pa.visible || !pb.visible || !pc.visible) return;
      const Eigen::Vector3d mid = (a + b + c) / 3.0;
      // Cull the far side: the facet's outward normal points away from the eye.
      const Eigen::Vector3d view =
          orthographic ? projection.forward() : Eigen::Vector3d(mid - projection.eye());
      if ((mid - center).dot(view) >= 0.0) return;
      Triangle t;
      t.corners = {pa.pixel, pb.pixel, pc.pixel};
      t.color = shade_triangle(base, a, b, c, view, light);
      out.push_back({(pa.depth + pb.depth + pc.depth) / 3.0, t});
    };
    for (int i = 0; i < kSphereSlices; ++i) {
      for (int j = 0; j < kSphereStacks; ++j) {
        const Eigen::Vector3d p00 = point(i, j), p10 = point(i + 1, j), p01 = point(i, j + 1),
                              p11 = point(i + 1, j + 1);
        if (j > 0) add(p00, p10, p11);  // no zero-area facets at the poles
        if (j < kSphereStacks - 1) add(p00, p11, p01);
      }
    }
  }
  return out;
}

}  // namespace fosssim
