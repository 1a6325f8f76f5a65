#pragma once
// What to draw, in pixels: the one description that the window, the PNG and SVG pictures and
// the movies all paint, so that they show the same thing.

#include <string>
#include <vector>

#include "core/scene.h"
#include "render/camera.h"
#include "render/path_history.h"

namespace fosssim {

/// A filled circle.
struct Disc {
  Point2 center;
  double radius = 0.0;  ///< pixels
  Color color;
};

/// A segment with round ends: every point within `radius` of the segment a-b.
struct Capsule {
  Point2 a, b;
  double radius = 0.0;  ///< pixels
  Color color;
};

/// A connected line of constant width.
struct Polyline {
  std::vector<Point2> points;
  double width = 1.0;  ///< pixels
  Color color;
};

/// A circle outline.
struct Ring {
  Point2 center;
  double radius = 0.0;  ///< pixels, to the middle of the stroke
  double width = 1.0;   ///< stroke width, pixels
  Color color;
};

/// One picture, painted in this order (SPEC section 6): background, paths, edges, particles,
/// marks, then the text lines at the top-left corner.
struct Drawing {
  int width = 512, height = 512;  ///< pixels
  Color background{1.0, 1.0, 1.0};
  std::vector<Polyline> paths;
  std::vector<Capsule> edges;
  std::vector<Disc> particles;
  std::vector<Ring> marks;
  std::vector<std::string> text;  ///< top-left, one line each
  Color text_color;
  double font_size = 14.0;  ///< pixels
};

/// A ring around a particle (the window's grading mode marks disagreeing particles).
struct ParticleMark {
  int particle = 0;
  Color color;
};

/// What a viewer adds to a scene's own appearance.
struct Overlay {
  bool show_time = true;            ///< "t = 1.23" as the first text line
  std::vector<std::string> status;  ///< more text lines below the time
  std::vector<ParticleMark> marks;
};

/// The drawing of `state` seen through `camera` on a width × height picture: trails from
/// `paths`, edges as capsules and particles as discs with the scene's radii and colours, then
/// the overlay. 3D scenes are projected onto the x-y plane.
Drawing compose_drawing(const Scene& scene, const State& state, const PathHistory& paths,
                        const Camera& camera, int width, int height, const Overlay& overlay = {});

/// "t = 1.230": the time with as many decimals as the time step needs (at least 2, at most 6).
std::string format_time(double time, double dt);

/// Black or white, whichever reads better on `background`.
Color text_color_for(const Color& background);

}  // namespace fosssim
