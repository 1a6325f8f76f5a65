#pragma once
// A tiny scene whose pictures are easy to check: 256 pixels per unit on 512 x 512.

#include "io/scene_loader.h"
#include "render/drawing.h"

namespace fosssim::testing {

// Particle 0 (red, radius 0.1) at (-0.5, 0) is pixel (128, 256); particle 1 (default colour
// and radius) at (0.5, 0.25) is pixel (384, 192); the green edge between them (radius 0.05,
// 12.8 pixels) has its midpoint at pixel (256, 224). The background is dark blue-grey.
inline constexpr const char* kTinyScene = R"(<scene>
  <duration time="0.02"/><integrator type="explicit-euler" dt="0.01"/>
  <particle m="1" px="-0.5" py="0" vx="0" vy="0" fixed="0" radius="0.1"/>
  <particle m="1" px="0.5" py="0.25" vx="0" vy="0" fixed="1"/>
  <edge i="0" j="1" radius="0.05"/>
  <particlecolor i="0" r="1" g="0" b="0"/>
  <edgecolor i="0" r="0" g="1" b="0"/>
  <backgroundcolor r="0.1" g="0.1" b="0.2"/>
  <viewport cx="0" cy="0" size="1"/>
</scene>)";

inline constexpr Color kRed{1, 0, 0};
inline constexpr Color kGreen{0, 1, 0};
inline constexpr Color kBackground{0.1, 0.1, 0.2};

inline Scene tiny_scene() {
  auto scene = load_scene_text(kTinyScene, "tiny.xml");
  return std::move(scene).value();
}

/// The tiny scene's initial state drawn without the time text.
inline Drawing tiny_drawing(const Scene& scene) {
  Overlay overlay;
  overlay.show_time = false;
  return compose_drawing(scene, scene.initial, PathHistory(scene), Camera{0, 0, 1}, 512, 512,
                         overlay);
}

}  // namespace fosssim::testing
