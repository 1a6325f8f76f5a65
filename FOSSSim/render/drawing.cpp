#include "render/drawing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/forces/rigid_body_spring_force.h"
#include "core/rigid/rigid_bodies.h"
#include "core/rigid/rigid_contact_detection.h"

namespace fosssim {

namespace {

/// Width of trails in pixels; the course drew one-pixel GL lines, a little more reads better
/// once anti-aliased.
constexpr double kTrailWidth = 1.5;
/// The mouse's drag line and the ring at its end.
constexpr double kGuideWidth = 1.5;
constexpr double kGuideRingRadius = 4.0;

Point2 position(const State& state, int dim, const PixelMapping& mapping, int p) {
  return mapping.to_pixel(state.q[dim * p], state.q[dim * p + 1]);
}

}  // namespace

std::string format_time(double time, double dt) {
  // Enough decimals to tell consecutive steps apart: 0.01 needs 2, 0.005 needs 3.
  const int decimals =
      dt > 0.0 ? std::clamp(static_cast<int>(std::ceil(-std::log10(dt) - 1e-9)), 2, 6) : 2;
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "t = %.*f", decimals, time);
  return buffer;
}

Color text_color_for(const Color& background) {
  // Relative luminance with the sRGB weights (ITU-R BT.709).
  const double luminance = 0.2126 * background.r + 0.7152 * background.g + 0.0722 * background.b;
  return luminance > 0.5 ? Color{0.0, 0.0, 0.0} : Color{1.0, 1.0, 1.0};
}

namespace {

/// The part of the picture [0, width] × [0, height] on the solid side of each half-plane, in its
/// colour. The mapping is a similarity, so the side of a pixel follows from the pixel images of
/// the half-plane's point and normal.
void add_half_planes(const Scene& scene, const PixelMapping& mapping, Drawing& drawing) {
  const auto& planes = scene.model.half_planes;
  for (std::size_t h = 0; h < planes.size(); ++h) {
    const HalfPlane& plane = planes[h];
    const Point2 p = mapping.to_pixel(plane.point[0], plane.point[1]);
    const Point2 q =
        mapping.to_pixel(plane.point[0] + plane.normal[0], plane.point[1] + plane.normal[1]);
    const double nx = q.x - p.x, ny = q.y - p.y;
    if (nx == 0.0 && ny == 0.0) continue;
    const auto side = [&](const Point2& u) { return (u.x - p.x) * nx + (u.y - p.y) * ny; };
    const double w = drawing.width, hgt = drawing.height;
    const Point2 rectangle[4] = {{0.0, 0.0}, {w, 0.0}, {w, hgt}, {0.0, hgt}};
    Region region;
    region.color = h < scene.appearance.half_plane_color.size()
                       ? scene.appearance.half_plane_color[h]
                       : Appearance::kDefaultHalfPlaneColor;
    for (int k = 0; k < 4; ++k) {  // clip the picture's rectangle to side ≤ 0
      const Point2& a = rectangle[k];
      const Point2& b = rectangle[(k + 1) % 4];
      const double sa = side(a), sb = side(b);
      if (sa <= 0.0) region.corners.push_back(a);
      if ((sa < 0.0 && sb > 0.0) || (sa > 0.0 && sb < 0.0)) {
        const double t = sa / (sa - sb);
        region.corners.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
      }
    }
    if (region.corners.size() >= 3) drawing.regions.push_back(std::move(region));
  }
}

/// Rigid bodies (docs/rigid-bodies.md): each hull filled in its body's colour, its edges as
/// capsules of the body's radius (the shape contact sees), and the springs as thin capsules in
/// their colours.
/// The contacts rigid-body contact sees in `state` (a scene with <rigidbodycollisionhandling>):
/// each contact's point on both bodies as a dot of kContactDotRadius pixels, and its normal,
/// from body i0 towards body i1, as a line of kContactNormalLength pixels from between them.
void add_rigid_contacts(const RigidBodies& bodies, const State& state, const PixelMapping& mapping,
                        Drawing& drawing) {
  constexpr Color kContactColor{0.75, 0.05, 0.1};
  constexpr double kContactDotRadius = 2.0, kContactNormalLength = 10.0;
  for (const RigidContact& c : detect_rigid_contacts(bodies, state.q)) {
    if (!has_finite_normal(c)) continue;
    const Vec2 q0 = rotate(body_angle(state.q, c.i0), c.arm0) + body_center(state.q, c.i0);
    const Vec2 q1 = rotate(body_angle(state.q, c.i1), c.arm1) + body_center(state.q, c.i1);
    const Point2 a = mapping.to_pixel(q0.x(), q0.y()), b = mapping.to_pixel(q1.x(), q1.y());
    drawing.particles.push_back({a, kContactDotRadius, kContactColor});
    drawing.particles.push_back({b, kContactDotRadius, kContactColor});
    const Vec2 mid = 0.5 * (q0 + q1);
    const Point2 m = mapping.to_pixel(mid.x(), mid.y());
    // Pixels grow downwards: the world's normal (x, y) is (x, −y) on the picture.
    const Point2 tip{m.x + kContactNormalLength * c.normal.x(),
                     m.y - kContactNormalLength * c.normal.y()};
    drawing.edges.push_back({m, tip, 0.5 * kContactDotRadius, kContactColor});
  }
}

void add_rigid_bodies(const Scene& scene, const State& state, const PixelMapping& mapping,
                      Drawing& drawing) {
  const RigidBodies& bodies = *scene.model.rigid_bodies;
  const Appearance& look = scene.appearance;
  const double ppu = mapping.pixels_per_unit();
  for (int b = 0; b < bodies.size(); ++b) {
    const RigidBody& body = bodies.bodies[b];
    Region region;
    region.color = look.particle_color[b];
    for (int k = 0; k < body.num_vertices(); ++k) {
      const Vec2 p = world_vertex(body, state.q, b, k);
      region.corners.push_back(mapping.to_pixel(p.x(), p.y()));
    }
    for (int k = 0; k < body.num_vertices(); ++k) {
      drawing.edges.push_back({region.corners[k],
                               region.corners[(k + 1) % region.corners.size()],
                               body.radius * ppu, look.particle_color[b]});
    }
    drawing.regions.push_back(std::move(region));
  }
  int spring = 0;
  for (const auto& force : scene.model.forces) {
    const auto* rigid_spring = dynamic_cast<const RigidBodySpringForce*>(force.get());
    if (rigid_spring == nullptr) continue;
    const auto ends = rigid_spring->world_ends(state.q);
    const Color color = spring < static_cast<int>(look.edge_color.size())
                            ? look.edge_color[spring]
                            : Appearance::kDefaultEdgeColor;
    drawing.edges.push_back({mapping.to_pixel(ends[0].x(), ends[0].y()),
                             mapping.to_pixel(ends[1].x(), ends[1].y()),
                             SceneModel::kDefaultEdgeRadius * ppu, color});
    ++spring;
  }
  if (scene.model.collisions.method->make_stage != nullptr) {  // <rigidbodycollisionhandling>
    add_rigid_contacts(bodies, state, mapping, drawing);
  }
}

/// Hinges are drawn as capsules of this radius (pixels), their middle particle as a disc of
/// twice it.
constexpr double kHingeRadius = 1.5;

/// (1 - t) a + t b: exactly a at t = 0 and b at t = 1.
Color mix(const Color& a, const Color& b, double t) {
  const double s = 1.0 - t;
  return {s * a.r + t * b.r, s * a.g + t * b.g, s * a.b + t * b.b};
}

Color darker(const Color& c) { return {0.55 * c.r, 0.55 * c.g, 0.55 * c.b}; }

/// The elastic bodies' triangles and hinges of the model's forces at `state`, as 2D shapes.
/// Returns the scale used (for the legend).
double add_elastic_elements(const Scene& scene, const State& state, const PixelMapping& mapping,
                            const ElementColors& colors, Drawing& drawing) {
  std::vector<ForceElement> elements;
  for (const auto& force : scene.model.forces) force->append_elements(state.q, elements);
  if (elements.empty()) return 0.0;
  const double scale = element_color_scale(elements, colors);
  const int dim = scene.model.dim;
  for (const ForceElement& e : elements) {
    const Point2 a = position(state, dim, mapping, e.particles[0]);
    const Point2 b = position(state, dim, mapping, e.particles[1]);
    const Point2 c = position(state, dim, mapping, e.particles[2]);
    if (e.kind == ForceElement::Kind::kTriangle) {
      const Color fill = element_color(e, colors, scale, kPlainTriangleColor);
      drawing.shapes.push_back(Triangle{std::array<Point2, 3>{a, b, c}, fill, 1.0, darker(fill)});
    } else {
      const Color line = element_color(e, colors, scale, kPlainHingeColor);
      drawing.shapes.push_back(Capsule{a, b, kHingeRadius, line});
      drawing.shapes.push_back(Capsule{b, c, kHingeRadius, line});
      drawing.shapes.push_back(Disc{b, 2.0 * kHingeRadius, line});
    }
  }
  return scale;
}

}  // namespace

double element_color_scale(const std::vector<ForceElement>& elements, const ElementColors& colors) {
  if (colors.scale > 0.0) return colors.scale;
  if (colors.by != ElementColoring::kEnergy) return kDefaultStrainScale;
  double scale = 0.0;
  for (const ForceElement& e : elements) {
    if (std::isfinite(e.energy_density)) scale = std::max(scale, e.energy_density);
  }
  return scale > 0.0 ? scale : 1.0;  // everything at rest: any scale draws it pale
}

Color element_color(const ForceElement& element, const ElementColors& colors, double scale,
                    const Color& plain) {
  switch (colors.by) {
    case ElementColoring::kStrain:
      return strain_color(element.strain, scale);
    case ElementColoring::kEnergy:
      return energy_color(element.energy_density, scale);
    case ElementColoring::kPlain:
      break;
  }
  return plain;
}

std::string element_legend(ElementColoring by, double scale) {
  char buffer[128];
  if (by == ElementColoring::kStrain) {
    std::snprintf(buffer, sizeof buffer, "strain: red +%.3g, blue -%.3g", scale, scale);
  } else {
    std::snprintf(buffer, sizeof buffer, "energy density: dark red %.3g", scale);
  }
  return buffer;
}

Color strain_color(double strain, double scale) {
  if (std::isnan(strain)) return {0.0, 0.0, 0.0};
  constexpr Color kCompressed{0.23, 0.30, 0.75};
  constexpr Color kRest{0.86, 0.86, 0.86};
  constexpr Color kStretched{0.71, 0.02, 0.15};
  const double t = std::clamp(strain / scale, -1.0, 1.0);
  return t < 0.0 ? mix(kRest, kCompressed, -t) : mix(kRest, kStretched, t);
}

Color energy_color(double density, double scale) {
  if (std::isnan(density)) return {0.0, 0.0, 0.0};
  constexpr Color kZero{1.0, 0.97, 0.78};
  constexpr Color kMiddle{0.99, 0.55, 0.24};
  constexpr Color kFull{0.50, 0.0, 0.15};
  const double t = std::sqrt(std::clamp(density / scale, 0.0, 1.0));
  return t < 0.5 ? mix(kZero, kMiddle, 2.0 * t) : mix(kMiddle, kFull, 2.0 * t - 1.0);
}

Drawing compose_drawing(const Scene& scene, const State& state, const PathHistory& paths,
                        const Camera& camera, int width, int height, const Overlay& overlay) {
  const Appearance& look = scene.appearance;
  const int dim = scene.model.dim;
  const PixelMapping mapping(camera, width, height);
  const double ppu = mapping.pixels_per_unit();

  Drawing drawing;
  drawing.width = width;
  drawing.height = height;
  drawing.background = look.background;
  drawing.text_color = text_color_for(look.background);

  add_half_planes(scene, mapping, drawing);
  for (const Trail& trail : paths.trails()) {
    if (trail.points.size() < 2) continue;
    Polyline line;
    line.width = kTrailWidth;
    line.color = trail.color;
    line.points.reserve(trail.points.size());
    for (const Point3& p : trail.points) line.points.push_back(mapping.to_pixel(p.x, p.y));
    drawing.paths.push_back(std::move(line));
  }
  if (scene.model.rigid_bodies) {
    add_rigid_bodies(scene, state, mapping, drawing);
    if (overlay.drag && overlay.drag->body_point) {  // the mouse pulls a body's point
      const int b = overlay.drag->particle;
      const Vec<2> from = rotate(body_angle(state.q, b), *overlay.drag->body_point) +
                          body_center(state.q, b);
      add_drag_guide(drawing, mapping.to_pixel(from.x(), from.y()),
                     mapping.to_pixel(overlay.drag->target.x(), overlay.drag->target.y()),
                     drawing.text_color);
    }
    drawing.text = overlay_text(overlay, state.time, scene.model.integrator.dt);
    return drawing;
  }
  const double element_scale =
      add_elastic_elements(scene, state, mapping, overlay.elements, drawing);
  const auto& edges = scene.model.edges;
  drawing.edges.reserve(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    drawing.edges.push_back({position(state, dim, mapping, edges[e].i),
                             position(state, dim, mapping, edges[e].j),
                             scene.model.edge_radius[e] * ppu, look.edge_color[e]});
  }
  const int n = scene.model.num_particles();
  drawing.particles.reserve(n);
  for (int p = 0; p < n; ++p) {
    drawing.particles.push_back({position(state, dim, mapping, p),
                                 scene.model.particle_radius[p] * ppu, look.particle_color[p]});
  }
  for (const ParticleMark& mark : overlay.marks) {
    const Disc& disc = drawing.particles.at(mark.particle);
    drawing.marks.push_back({disc.center, disc.radius + kMarkGap, kMarkWidth, mark.color});
  }
  if (overlay.drag) {
    add_drag_guide(drawing, drawing.particles.at(overlay.drag->particle).center,
                   mapping.to_pixel(overlay.drag->target.x(), overlay.drag->target.y()),
                   drawing.text_color);
  }
  drawing.text = overlay_text(overlay, state.time, scene.model.integrator.dt);
  if (element_scale > 0.0 && overlay.elements.by != ElementColoring::kPlain) {
    drawing.text.push_back(element_legend(overlay.elements.by, element_scale));
  }
  return drawing;
}

std::vector<std::string> overlay_text(const Overlay& overlay, double time, double dt) {
  std::vector<std::string> text;
  if (overlay.show_time) text.push_back(format_time(time, dt));
  text.insert(text.end(), overlay.status.begin(), overlay.status.end());
  return text;
}

void add_drag_guide(Drawing& drawing, const Point2& particle, const Point2& target,
                    const Color& color) {
  drawing.guides.push_back({{particle, target}, kGuideWidth, color});
  drawing.marks.push_back({target, kGuideRingRadius, kGuideWidth, color});
}

}  // namespace fosssim
