#include "render/drawing_3d.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

#include "render/shading.h"

namespace fosssim {

namespace {

/// Outlines of coarse surfaces: the face colour darkened to this fraction, this wide.
constexpr double kOutlineShade = 0.7;
constexpr double kOutlineWidth = 0.75;
/// Capsules are at least this many pixels in radius, so that distant edges stay visible.
constexpr double kMinCapsulePixels = 0.75;
/// Trails: segments of this radius in pixels (the 2D trails are 1.5 pixels wide).
constexpr double kTrailRadius = 0.75;
constexpr double kPinRingWidth = 1.5;
/// Hinges: capsules of this radius in pixels, a disc of twice it on the hinge (as in 2D).
constexpr double kHingePixels = 1.5;

/// Shapes with their sort depths, handed over farthest first. Equal depths keep the order in
/// which the shapes were added.
class DepthSortedShapes {
 public:
  void add(double depth, Shape shape) {
    keys_.emplace_back(depth, shapes_.size());
    shapes_.push_back(std::move(shape));
  }
  std::vector<Shape> farthest_first() {
    std::stable_sort(keys_.begin(), keys_.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<Shape> sorted;
    sorted.reserve(shapes_.size());
    for (const auto& key : keys_) sorted.push_back(std::move(shapes_[key.second]));
    return sorted;
  }

 private:
  std::vector<std::pair<double, std::size_t>> keys_;
  std::vector<Shape> shapes_;
};

Color mean_color(const Color& a, const Color& b, const Color& c) {
  return {(a.r + b.r + c.r) / 3.0, (a.g + b.g + c.g) / 3.0, (a.b + b.b + c.b) / 3.0};
}

Color darker(const Color& c, double factor) { return {c.r * factor, c.g * factor, c.b * factor}; }

double distance(const Point2& a, const Point2& b) { return std::hypot(a.x - b.x, a.y - b.y); }

/// Everything the shape builders share: the state's positions and their projections.
struct Scene3DView {
  const Scene& scene;
  const State& state;
  const OrbitCamera& camera;
  OrbitProjection projection;
  std::vector<ProjectedPoint> seen;  ///< per particle

  Eigen::Vector3d position(int p) const { return state.q.segment<3>(3 * p); }
  /// From the eye toward `point`: the view ray there (perspective) or the view direction.
  Eigen::Vector3d view_toward(const Eigen::Vector3d& point) const {
    if (camera.projection == Projection::kOrthographic) return projection.forward();
    return point - projection.eye();
  }
};

/// The mean projected side length of a set of triangles, pixels (0 without any visible).
class SideLengths {
 public:
  void add(const Scene3DView& view, const std::array<int, 3>& t) {
    const ProjectedPoint &a = view.seen[t[0]], &b = view.seen[t[1]], &c = view.seen[t[2]];
    if (!a.visible || !b.visible || !c.visible) return;
    sum_ += distance(a.pixel, b.pixel) + distance(b.pixel, c.pixel) + distance(c.pixel, a.pixel);
    sides_ += 3;
  }
  double mean() const { return sides_ == 0 ? 0.0 : sum_ / static_cast<double>(sides_); }

 private:
  double sum_ = 0.0;
  std::size_t sides_ = 0;
};

/// Triangle t filled with `base` shaded as seen, with its depth; nothing when a corner is
/// behind the near plane.
void add_shaded_triangle(const Scene3DView& view, const std::array<int, 3>& t, const Color& base,
                         BackSide back, bool outline, const Lighting& light,
                         DepthSortedShapes& shapes) {
  const ProjectedPoint &a = view.seen[t[0]], &b = view.seen[t[1]], &c = view.seen[t[2]];
  if (!a.visible || !b.visible || !c.visible) return;
  const Eigen::Vector3d pa = view.position(t[0]), pb = view.position(t[1]),
                        pc = view.position(t[2]);
  Triangle triangle;
  triangle.corners = {a.pixel, b.pixel, c.pixel};
  triangle.color =
      shade_triangle(base, pa, pb, pc, view.view_toward((pa + pb + pc) / 3.0), light, back);
  if (outline) {
    triangle.outline_width = kOutlineWidth;
    triangle.outline_color = darker(triangle.color, kOutlineShade);
  }
  shapes.add((a.depth + b.depth + c.depth) / 3.0, triangle);
}

Lighting view_lighting(const Scene3DView& view) {
  const OrbitProjection& projection = view.projection;
  return camera_lighting(projection.right(), projection.up(), projection.forward());
}

/// The mesh faces, in the mean colour of their corners' particles.
void add_faces(const Scene3DView& view, const SceneParts3D& parts, DepthSortedShapes& shapes) {
  const Appearance& look = view.scene.appearance;
  SideLengths sides;
  for (int f : parts.faces) sides.add(view, look.triangles[f]);
  const bool outline = sides.mean() >= kOutlineMinPixels;
  const Lighting light = view_lighting(view);
  for (int f : parts.faces) {
    const auto& t = look.triangles[f];
    const Color base =
        mean_color(look.particle_color[t[0]], look.particle_color[t[1]], look.particle_color[t[2]]);
    add_shaded_triangle(view, t, base, BackSide::kTinted, outline, light, shapes);
  }
}

/// The elements the forces show at the view's state: membrane triangles shaded like faces,
/// hinges as capsules. Returns the colour scale, 0 without elements.
double add_elements(const Scene3DView& view, const SceneParts3D& parts, const ElementColors& colors,
                    DepthSortedShapes& shapes) {
  std::vector<ForceElement> elements;
  for (int f : parts.element_forces) {
    view.scene.model.forces[f]->append_elements(view.state.q, elements);
  }
  if (elements.empty()) return 0.0;
  const double scale = element_color_scale(elements, colors);
  SideLengths sides;
  for (const ForceElement& e : elements) {
    if (e.kind == ForceElement::Kind::kTriangle) sides.add(view, e.particles);
  }
  const bool outline = sides.mean() >= kOutlineMinPixels;
  const Lighting light = view_lighting(view);
  const BackSide back = colors.by == ElementColoring::kPlain ? BackSide::kTinted : BackSide::kSame;
  for (const ForceElement& e : elements) {
    if (e.kind == ForceElement::Kind::kTriangle) {
      const Color base = element_color(e, colors, scale, kPlainTriangleColor);
      add_shaded_triangle(view, e.particles, base, back, outline, light, shapes);
      continue;
    }
    const ProjectedPoint &a = view.seen[e.particles[0]], &b = view.seen[e.particles[1]],
                         &c = view.seen[e.particles[2]];
    if (!a.visible || !b.visible || !c.visible) continue;
    const Color line = element_color(e, colors, scale, kPlainHingeColor);
    shapes.add(0.5 * (a.depth + b.depth), Capsule{a.pixel, b.pixel, kHingePixels, line});
    shapes.add(0.5 * (b.depth + c.depth), Capsule{b.pixel, c.pixel, kHingePixels, line});
    shapes.add(b.depth, Disc{b.pixel, 2.0 * kHingePixels, line});
  }
  return scale;
}

void add_edges(const Scene3DView& view, const SceneParts3D& parts, DepthSortedShapes& shapes) {
  const Appearance& look = view.scene.appearance;
  const auto& edges = view.scene.model.edges;
  for (int e : parts.edges) {
    const ProjectedPoint &a = view.seen[edges[e].i], &b = view.seen[edges[e].j];
    if (!a.visible || !b.visible) continue;
    const double depth = 0.5 * (a.depth + b.depth);
    const double radius = view.scene.model.edge_radius[e];
    const double pixels =
        std::max(radius * view.projection.pixels_per_unit(depth), kMinCapsulePixels);
    shapes.add(depth - radius, Capsule{a.pixel, b.pixel, pixels, look.edge_color[e]});
  }
}

void add_particles(const Scene3DView& view, const SceneParts3D& parts, const Color& pin_color,
                   DepthSortedShapes& shapes) {
  const Appearance& look = view.scene.appearance;
  auto add = [&](int p, bool pin) {
    const ProjectedPoint& seen = view.seen[p];
    if (!seen.visible) return;
    const double radius = view.scene.model.particle_radius[p];
    const double pixels = radius * view.projection.pixels_per_unit(seen.depth);
    const double depth = seen.depth - radius;
    if (pin) {
      shapes.add(depth, Disc{seen.pixel, std::max(0.5 * pixels, kPinMinPixels), pin_color});
    } else if (view.scene.model.fixed[p]) {
      const double shown = std::max(pixels, kPinMinPixels);
      shapes.add(depth, Disc{seen.pixel, shown, look.particle_color[p]});
      shapes.add(depth, Ring{seen.pixel, shown, kPinRingWidth, pin_color});
    } else {
      shapes.add(depth, Disc{seen.pixel, pixels, look.particle_color[p]});
    }
  };
  for (int p : parts.particles) add(p, false);
  for (int p : parts.pins) add(p, true);
}

void add_trails(const Scene3DView& view, const PathHistory& paths, DepthSortedShapes& shapes) {
  for (const Trail& trail : paths.trails()) {
    for (std::size_t k = 1; k < trail.points.size(); ++k) {
      const Point3 &p0 = trail.points[k - 1], &p1 = trail.points[k];
      const ProjectedPoint a = view.projection.project({p0.x, p0.y, p0.z});
      const ProjectedPoint b = view.projection.project({p1.x, p1.y, p1.z});
      if (!a.visible || !b.visible) continue;
      shapes.add(0.5 * (a.depth + b.depth), Capsule{a.pixel, b.pixel, kTrailRadius, trail.color});
    }
  }
}

void add_overlay(const Scene3DView& view, const Overlay& overlay, Drawing& drawing) {
  for (const ParticleMark& mark : overlay.marks) {
    const ProjectedPoint& seen = view.seen.at(mark.particle);
    if (!seen.visible) continue;
    const double pixels = view.scene.model.particle_radius[mark.particle] *
                          view.projection.pixels_per_unit(seen.depth);
    drawing.marks.push_back({seen.pixel, pixels + kMarkGap, kMarkWidth, mark.color});
  }
  if (overlay.drag) {
    const ProjectedPoint& from = view.seen.at(overlay.drag->particle);
    const ProjectedPoint to = view.projection.project(overlay.drag->target);
    if (from.visible && to.visible) {
      add_drag_guide(drawing, from.pixel, to.pixel, drawing.text_color);
    }
  }
}

}  // namespace

SceneParts3D compute_scene_parts_3d(const Scene& scene) {
  const int n = scene.model.num_particles();
  const Appearance& look = scene.appearance;
  SceneParts3D parts;
  std::vector<bool> on_surface(n, false), inside(n, false);
  // Membranes: the triangles the forces show, with their corners sorted to find faces that are
  // membranes too.
  std::vector<std::array<int, 3>> membranes;
  const auto& forces = scene.model.forces;
  for (std::size_t f = 0; f < forces.size(); ++f) {
    std::vector<ForceElement> elements;
    forces[f]->append_elements(scene.initial.q, elements);
    if (elements.empty()) continue;
    parts.element_forces.push_back(static_cast<int>(f));
    for (const ForceElement& e : elements) {
      if (e.kind != ForceElement::Kind::kTriangle) continue;
      for (int p : e.particles) on_surface[p] = true;
      std::array<int, 3> sorted = e.particles;
      std::sort(sorted.begin(), sorted.end());
      membranes.push_back(sorted);
    }
  }
  std::sort(membranes.begin(), membranes.end());
  for (std::size_t t = 0; t < look.triangles.size(); ++t) {
    std::array<int, 3> sorted = look.triangles[t];
    for (int p : sorted) on_surface[p] = true;
    std::sort(sorted.begin(), sorted.end());
    if (!std::binary_search(membranes.begin(), membranes.end(), sorted)) {
      parts.faces.push_back(static_cast<int>(t));
    }
  }
  for (int p : look.interior_particles) inside[p] = true;
  auto stood_for = [&](int p) { return on_surface[p] || inside[p]; };
  for (int p = 0; p < n; ++p) {
    if (!stood_for(p)) {
      parts.particles.push_back(p);
    } else if (scene.model.fixed[p] && on_surface[p]) {
      parts.pins.push_back(p);
    }
  }
  const auto& edges = scene.model.edges;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!stood_for(edges[e].i) || !stood_for(edges[e].j))
      parts.edges.push_back(static_cast<int>(e));
  }
  parts.obstacles = compute_obstacle_frame(scene);
  return parts;
}

Drawing compose_drawing_3d(const Scene& scene, const SceneParts3D& parts, const State& state,
                           const PathHistory& paths, const OrbitCamera& camera, int width,
                           int height, const Overlay& overlay) {
  Scene3DView view{scene, state, camera, OrbitProjection(camera, width, height), {}};
  const int n = scene.model.num_particles();
  view.seen.reserve(n);
  for (int p = 0; p < n; ++p) view.seen.push_back(view.projection.project(view.position(p)));

  Drawing drawing;
  drawing.width = width;
  drawing.height = height;
  drawing.background = scene.appearance.background;
  drawing.text_color = text_color_for(scene.appearance.background);
  DepthSortedShapes shapes;
  add_trails(view, paths, shapes);
  add_faces(view, parts, shapes);
  const double element_scale = add_elements(view, parts, overlay.elements, shapes);
  add_edges(view, parts, shapes);
  add_particles(view, parts, drawing.text_color, shapes);
  for (DepthShape& facet : sphere_triangles(scene, camera, view.projection)) {
    shapes.add(facet.depth, std::move(facet.triangle));
  }
  add_half_space_regions(scene, parts.obstacles, camera, view.projection, drawing.regions);
  drawing.shapes = shapes.farthest_first();
  add_overlay(view, overlay, drawing);
  drawing.text = overlay_text(overlay, state.time, scene.model.integrator.dt);
  if (element_scale > 0.0 && overlay.elements.by != ElementColoring::kPlain) {
    drawing.text.push_back(element_legend(overlay.elements.by, element_scale));
  }
  return drawing;
}

}  // namespace fosssim
