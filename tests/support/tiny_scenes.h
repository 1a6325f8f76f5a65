#pragma once
// The tiny scenes of the drawing, picture, window and command-line tests, whose pictures are easy
// to check, and the camera that sees 3D scenes simply.

#include <numbers>

#include "io/scene_loader.h"
#include "render/drawing.h"
#include "render/orbit_camera.h"

namespace fosssim::testing {

// Particle 0 (red, radius 0.1) starts at (-0.5, 0), pixel (128, 256), moving up at 1 m/s and
// leaving a yellow trail of 0.5 s. Particle 1 (fixed; default colour and radius 0.1) is at
// (0.5, 0.25), pixel (384, 192). The green edge between them (radius 0.05, 12.8 pixels) carries
// a spring and has its midpoint at pixel (256, 224). The background is dark blue-grey.
// 30 steps of explicit Euler.
inline constexpr const char* kTinyScene = R"(<scene>
  <duration time="0.3"/><integrator type="explicit-euler" dt="0.01"/>
  <particle m="1" px="-0.5" py="0" vx="0" vy="1" fixed="0" radius="0.1"/>
  <particle m="1" px="0.5" py="0.25" vx="0" vy="0" fixed="1"/>
  <edge i="0" j="1" radius="0.05"/>
  <springforce edge="0" k="20" l0="1"/>
  <particlecolor i="0" r="1" g="0" b="0"/>
  <edgecolor i="0" r="0" g="1" b="0"/>
  <backgroundcolor r="0.1" g="0.1" b="0.2"/>
  <particlepath i="0" duration="0.5" r="1" g="1" b="0"/>
  <viewport cx="0" cy="0" size="1"/>
</scene>)";
inline constexpr int kTinySteps = 30;

// One free particle on a damped spring to a fixed one, under gravity: implicit Euler, 100 steps.
// The edge is on line 6 (tests that add attributes to it name that line).
inline constexpr const char* kFixedSpringScene = R"(<scene>
  <duration time="1.0"/>
  <integrator type="implicit-euler" dt="0.01"/>
  <particle m="1" px="0" py="0" vx="0" vy="0" fixed="1"/>
  <particle m="1" px="1.2" py="0.1" vx="0" vy="0" fixed="0"/>
  <edge i="0" j="1"/>
  <springforce edge="0" k="20" l0="1" b="0.3"/>
  <simplegravity fx="0" fy="-9.81"/>
</scene>)";

inline constexpr Color kRed{1, 0, 0};
inline constexpr Color kGreen{0, 1, 0};
inline constexpr Color kYellow{1, 1, 0};
inline constexpr Color kBackground{0.1, 0.1, 0.2};

inline Scene tiny_scene() { return load_scene_text(kTinyScene, "tiny.xml"); }

/// The tiny scene's initial state drawn without the time text.
inline Drawing tiny_drawing(const Scene& scene) {
  Overlay overlay;
  overlay.show_time = false;
  return compose_drawing(scene, scene.initial, PathHistory(scene), Camera{0, 0, 1}, 512, 512,
                         overlay);
}

/// A 6 × 6 cloth hanging in the plane z = 0 from its two top corners, x from -0.5 to 0.5 and y
/// from 0 down to -1, falling for 30 steps of local/global; dark blue-grey background; the default
/// three-quarter view.
inline constexpr const char* kTinyScene3D = R"(<scene dim="3">
  <duration time="0.3"/><integrator type="local-global" dt="0.01"/>
  <generate type="cloth" nx="6" ny="6" plane="xy" pin="corners" k="100" mass="total" total="0.1"/>
  <simplegravity fx="0" fy="-9.8" fz="0"/>
  <backgroundcolor r="0.1" g="0.1" b="0.2"/>
</scene>)";

/// Two membrane triangles (elasticbodycstforce in 3D) in the plane z = 0, facing the front
/// camera (below; 51.2 pixels per unit there): particles 0-2 stretched to 1.5 times their rest
/// width along x (strain +0.5), particles 3-5 compressed to 0.75 of it (strain -0.25); both keep
/// their height. Centroids (-1.5, -1/3, 0) and (1, -1/3, 0): pixels (179.2, 273.07) and
/// (307.2, 273.07). Particle 0 is fixed; particle 6 is loose, joined by an edge to particle 5,
/// which an edge also joins to 4.
inline constexpr const char* kMembraneScene = R"(<scene dim="3">
  <duration time="0.1"/><integrator type="implicit-euler" dt="0.1"/>
  <particle m="1" px="-2" py="-1" pz="0" vx="0" vy="0" vz="0" fixed="1"/>
  <particle m="1" px="-0.5" py="-1" pz="0" vx="0" vy="0" vz="0" fixed="0"/>
  <particle m="1" px="-2" py="1" pz="0" vx="0" vy="0" vz="0" fixed="0"/>
  <particle m="1" px="0.5" py="-1" pz="0" vx="0" vy="0" vz="0" fixed="0"/>
  <particle m="1" px="2" py="-1" pz="0" vx="0" vy="0" vz="0" fixed="0"/>
  <particle m="1" px="0.5" py="1" pz="0" vx="0" vy="0" vz="0" fixed="0"/>
  <particle m="1" px="1.5" py="1.5" pz="0" vx="0" vy="0" vz="0" fixed="0"/>
  <edge i="4" j="5"/>
  <edge i="5" j="6"/>
  <elasticbodycstforce i1="0" i2="1" i3="2" youngsmodulus="10" poissonratio="0.3" xb2x="-1"/>
  <elasticbodycstforce i1="3" i2="4" i3="5" youngsmodulus="10" poissonratio="0.3" xb2x="2.5"/>
</scene>)";

inline Scene membrane_scene() { return load_scene_text(kMembraneScene, "membranes.xml"); }

/// Looking along -z at the origin from 5 units with a 90° field of view: on 512 × 512 pixels the
/// focal length is 256 pixels, so (x, y, z) goes to (256 + 256 x / (5 - z), 256 - 256 y / (5 - z)).
inline OrbitCamera front_camera() {
  OrbitCamera camera;
  camera.distance = 5.0;
  camera.fov = 0.5 * std::numbers::pi;
  return camera;
}

}  // namespace fosssim::testing
