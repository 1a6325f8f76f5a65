#pragma once
// What to draw, in pixels: the one description that the window, the PNG and SVG pictures and
// the movies all paint, so that they show the same thing.

#include <array>
#include <optional>
#include <string>
#include <variant>
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

/// A filled triangle: a face of a shaded surface in a 3D picture.
struct Triangle {
  std::array<Point2, 3> corners;
  Color color;
  double outline_width = 0.0;  ///< pixels; 0: no outline
  Color outline_color;
};

/// A filled convex polygon: the part of a half-plane inside a 2D picture.
struct Region {
  std::vector<Point2> corners;
  Color color;
};

/// One shape of a 3D picture.
using Shape = std::variant<Triangle, Capsule, Disc, Ring>;

/// One picture, painted in this order (docs/viewing.md): background, regions, paths, the shapes,
/// edges, particles, marks, guides, then the text lines at the top-left corner. The shapes of
/// 2D pictures are the elastic bodies' triangles (filled) and hinges (two capsules each), in
/// the forces' summation order; 3D pictures have only shapes, depth-sorted, instead of paths, edges and
/// particles.
struct Drawing {
  int width = 512, height = 512;  ///< pixels
  Color background{1.0, 1.0, 1.0};
  std::vector<Region> regions;  ///< 2D: the half-planes, in their colours
  std::vector<Polyline> paths;
  std::vector<Shape> shapes;  ///< 2D: elastic triangles and hinges; 3D: farthest first
  std::vector<Capsule> edges;
  std::vector<Disc> particles;
  std::vector<Ring> marks;
  std::vector<Polyline> guides;   ///< over everything but the text: the mouse's drag line
  std::vector<std::string> text;  ///< top-left, one line each
  Color text_color;
  double font_size = 14.0;  ///< pixels
};

/// Marks ring their particle this many pixels outside its edge, with this stroke width.
inline constexpr double kMarkGap = 3.0;
inline constexpr double kMarkWidth = 2.0;

/// A ring around a particle (the window's grading mode marks disagreeing particles).
struct ParticleMark {
  int particle = 0;
  Color color;
};

/// A particle pulled toward a point with the mouse: drawn as a line from it to the point.
struct DragGuide {
  int particle = 0;  ///< the particle pulled, or in a rigid-body scene the body
  Eigen::Vector3d target = Eigen::Vector3d::Zero();  ///< world units (z ignored in 2D)
  /// Rigid bodies: the pulled point in body space (the line starts at R(θ)p + X).
  std::optional<Eigen::Vector2d> body_point;
};

/// How the triangles and hinges of elastic bodies (Force::append_elements) are coloured.
enum class ElementColoring {
  kPlain,   ///< triangles kPlainTriangleColor with a darker outline, hinges kPlainHingeColor
  kStrain,  ///< by ForceElement::strain: blue compressed, grey at rest, red stretched
  kEnergy,  ///< by ForceElement::energy_density: pale yellow at 0 to dark red
};

/// The colouring of elastic bodies and the value drawn in full colour.
struct ElementColors {
  ElementColoring by = ElementColoring::kPlain;
  /// |strain| or energy density drawn in full colour (larger values saturate); 0: the default,
  /// kDefaultStrainScale for strain and the picture's largest density for energy.
  double scale = 0.0;
};

inline constexpr Color kPlainTriangleColor{0.62, 0.78, 0.93};
inline constexpr Color kPlainHingeColor{0.30, 0.30, 0.38};
/// A strain of ±0.1 (10% stretch or compression, or 0.1 rad of bending) is drawn in full colour
/// unless a scale is given.
inline constexpr double kDefaultStrainScale = 0.1;

/// The value elements are drawn in full colour at: colors.scale when positive, else
/// kDefaultStrainScale for strain and the largest finite energy density of `elements` for energy
/// (1 when they are all at rest). The same rule in 2D and 3D pictures.
double element_color_scale(const std::vector<ForceElement>& elements, const ElementColors& colors);
/// The colour of `element` as `colors` asks at `scale` (element_color_scale): strain_color,
/// energy_color, or `plain` for ElementColoring::kPlain.
Color element_color(const ForceElement& element, const ElementColors& colors, double scale,
                    const Color& plain);
/// The legend line of a colouring that is not plain: "strain: red +0.1, blue -0.1" or
/// "energy density: dark red 1.06".
std::string element_legend(ElementColoring by, double scale);

/// The colour of a signed strain s at `scale`: a diverging map from blue (s ≤ -scale) through
/// light grey (0) to red (s ≥ scale), linear in between; NaN is black.
Color strain_color(double strain, double scale);
/// The colour of an energy density e ≥ 0 at `scale`: pale yellow at 0 through orange to dark
/// red at e ≥ scale, linear in sqrt(e / scale) (small densities stay visible); NaN is black.
Color energy_color(double density, double scale);

/// What a viewer adds to a scene's own appearance.
struct Overlay {
  bool show_time = true;            ///< "t = 1.23" as the first text line
  std::vector<std::string> status;  ///< more text lines below the time
  std::vector<ParticleMark> marks;
  std::optional<DragGuide> drag;
  /// How elastic triangles and hinges (2D) and membranes (3D) are coloured; a line of text
  /// says what the colours mean when they are not plain.
  ElementColors elements;
};

/// The drawing of `state` seen through `camera` on a width × height picture: trails from
/// `paths`, the elastic bodies' triangles filled and hinges as two capsules (coloured as
/// overlay.elements says), edges as capsules and particles as discs with the scene's radii and
/// colours, then the overlay. 3D scenes are projected onto the x-y plane.
Drawing compose_drawing(const Scene& scene, const State& state, const PathHistory& paths,
                        const Camera& camera, int width, int height, const Overlay& overlay = {});

/// The overlay's text lines: the time (if shown) and the status lines.
std::vector<std::string> overlay_text(const Overlay& overlay, double time, double dt);

/// The drag guide of the overlay between two pixels: a thin line in `color` and a small ring
/// at the target, added to the drawing's guides and marks.
void add_drag_guide(Drawing& drawing, const Point2& particle, const Point2& target,
                    const Color& color);

/// "t = 1.230": the time with as many decimals as the time step needs (at least 2, at most 6).
std::string format_time(double time, double dt);

/// Black or white, whichever reads better on `background`.
Color text_color_for(const Color& background);

}  // namespace fosssim
