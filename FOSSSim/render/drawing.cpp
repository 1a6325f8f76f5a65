#include "render/drawing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

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

  for (const Trail& trail : paths.trails()) {
    if (trail.points.size() < 2) continue;
    Polyline line;
    line.width = kTrailWidth;
    line.color = trail.color;
    line.points.reserve(trail.points.size());
    for (const Point3& p : trail.points) line.points.push_back(mapping.to_pixel(p.x, p.y));
    drawing.paths.push_back(std::move(line));
  }
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
