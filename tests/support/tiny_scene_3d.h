#pragma once
// Small 3D scenes built in code for the drawing, picture and viewer tests, and the camera that
// sees them simply.

#include <numbers>
#include <vector>

#include "core/scene.h"
#include "render/orbit_camera.h"

namespace fosssim::testing {

/// A 6 × 6 cloth hanging in the plane z = 0 from its two top corners, x from -0.5 to 0.5 and y
/// from 0 down to -1, falling for 30 steps of local/global; dark blue-grey background; the default
/// three-quarter view.
inline constexpr const char* kTinyScene3D = R"(<scene dim="3">
  <duration time="0.3"/><integrator type="local-global" dt="0.01"/>
  <generate type="cloth" nx="6" ny="6" plane="xy" pin="corners" k="100" mass="total" total="0.1"/>
  <simplegravity fx="0" fy="-9.8" fz="0"/>
  <backgroundcolor r="0.1" g="0.1" b="0.2"/>
</scene>)";

/// A 3D scene of particles at `points` (mass 1, radius 0.05, default colours), dt = 0.01,
/// nothing else.
inline Scene particles_at(const std::vector<Eigen::Vector3d>& points) {
  Scene scene;
  scene.model.dim = 3;
  scene.model.integrator.dt = 0.01;
  const int n = static_cast<int>(points.size());
  scene.model.mass = Vector::Ones(3 * n);
  scene.model.fixed.assign(n, false);
  scene.initial.q.resize(3 * n);
  scene.initial.v = Vector::Zero(3 * n);
  for (int p = 0; p < n; ++p) scene.initial.q.segment<3>(3 * p) = points[p];
  scene.appearance.particle_radius.assign(n, 0.05);
  scene.appearance.particle_color.assign(n, Appearance::kDefaultParticleColor);
  return scene;
}

/// Adds an edge (radius 0.02, default colour) between particles i and j.
inline void add_edge(Scene& scene, int i, int j) {
  scene.model.edges.push_back({i, j});
  scene.appearance.edge_radius.push_back(0.02);
  scene.appearance.edge_color.push_back(Appearance::kDefaultEdgeColor);
}

/// Looking along -z at the origin from 5 units with a 90° field of view: on 512 × 512 pixels the
/// focal length is 256 pixels, so (x, y, z) goes to (256 + 256 x / (5 - z), 256 - 256 y / (5 - z)).
inline OrbitCamera front_camera() {
  OrbitCamera camera;
  camera.distance = 5.0;
  camera.fov = 0.5 * std::numbers::pi;
  return camera;
}

}  // namespace fosssim::testing
