#include "mesh/elastic_shapes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <unordered_map>

#include "core/error.h"
#include "core/text.h"
#include "mesh/polygon_triangulation.h"

namespace fosssim {

namespace {

[[noreturn]] void bad(const std::string& problem) { throw Error(ErrorKind::kBadInput, problem); }

/// Vertex k of n on the circle of radius r: angle 2πk/n, exactly (r, 0) for k = 0.
Eigen::Vector2d on_circle(int k, int n, double r) {
  const double angle = 2.0 * std::numbers::pi * k / n;
  return {r * std::cos(angle), r * std::sin(angle)};
}

/// Rod segments and hinges over vertices 0 .. n-1 in order, closed or not.
void connect_rod(ElasticShape& shape, bool closed) {
  const int n = shape.num_vertices();
  const int segments = closed ? n : n - 1;
  for (int k = 0; k < segments; ++k) {
    const int a = k, b = (k + 1) % n;
    shape.edges.push_back({std::min(a, b), std::max(a, b)});
  }
  for (int k = closed ? 0 : 1; k < (closed ? n : n - 1); ++k)
    shape.hinges.push_back({(k + n - 1) % n, k, (k + 1) % n});
}

/// Refuses an outline that is not a simple polygon of positive area: fewer than 3 corners, a
/// corner repeated, sides crossing or touching, a side folding back over the previous one.
/// `prefix` goes before each problem ("hole 1: " for a hole). Quadratic in the corners (their
/// number is bounded by the caller).
void check_simple(const std::vector<Eigen::Vector2d>& outline, const std::string& prefix = "") {
  const auto bad = [&](const std::string& problem) { fosssim::bad(prefix + problem); };
  const int n = static_cast<int>(outline.size());
  if (n < 3) bad("a polygon needs at least 3 corners, found " + std::to_string(n));
  for (int i = 0; i < n; ++i) {
    if (!outline[i].allFinite()) bad("corner " + std::to_string(i) + " is not finite");
  }
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      if (outline[i] == outline[j]) {
        bad("corners " + std::to_string(i) + " and " + std::to_string(j) + " are the same point");
      }
    }
  }
  for (int i = 0; i < n; ++i) {
    const auto& a = outline[i];
    const auto& b = outline[(i + 1) % n];
    const auto& c = outline[(i + 2) % n];
    if (orientation(a, b, c) == 0.0 && (b - a).dot(c - b) < 0.0) {
      bad("the sides from corner " + std::to_string(i) + " to " + std::to_string((i + 2) % n) +
          " fold back over each other");
    }
    for (int j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours through corner 0
      if (closed_segments_meet(a, b, outline[j], outline[(j + 1) % n])) {
        bad("side " + std::to_string(i) + " (corners " + std::to_string(i) + "–" +
            std::to_string((i + 1) % n) + ") and side " + std::to_string(j) + " (corners " +
            std::to_string(j) + "–" + std::to_string((j + 1) % n) +
            ") cross or touch: the polygon is not simple");
      }
    }
  }
}

/// "side 2 (corners 2–3)" of a loop of n corners.
std::string side_name(int k, int n) {
  return "side " + std::to_string(k) + " (corners " + std::to_string(k) + "–" +
         std::to_string((k + 1) % n) + ")";
}

/// The first side of `a` and side of `b` that meet, or {-1, -1}. Quadratic.
std::pair<int, int> first_meeting_sides(const std::vector<Eigen::Vector2d>& a,
                                        const std::vector<Eigen::Vector2d>& b) {
  const int na = static_cast<int>(a.size()), nb = static_cast<int>(b.size());
  for (int i = 0; i < na; ++i) {
    for (int j = 0; j < nb; ++j) {
      if (closed_segments_meet(a[i], a[(i + 1) % na], b[j], b[(j + 1) % nb])) return {i, j};
    }
  }
  return {-1, -1};
}

/// x strictly inside the closed polygon `loop` (x on no side of it: the caller knows), by the
/// parity of the sides a ray towards +x crosses.
bool inside_loop(const std::vector<Eigen::Vector2d>& loop, const Eigen::Vector2d& x) {
  bool inside = false;
  const int n = static_cast<int>(loop.size());
  for (int k = 0; k < n; ++k) {
    const auto& a = loop[k];
    const auto& b = loop[(k + 1) % n];
    if ((a.y() > x.y()) != (b.y() > x.y()) &&
        x.x() < a.x() + (x.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
      inside = !inside;
  }
  return inside;
}

/// Refuses holes that are not simple, not strictly inside the outline, or that meet the outline
/// or each other (crossing, touching, or one inside another). Quadratic in all corners.
void check_holes(const std::vector<Eigen::Vector2d>& outline,
                 const std::vector<std::vector<Eigen::Vector2d>>& holes) {
  for (std::size_t h = 0; h < holes.size(); ++h) {
    const std::string name = "hole " + std::to_string(h);
    check_simple(holes[h], name + ": ");
    const auto [side, outline_side] = first_meeting_sides(holes[h], outline);
    if (side >= 0) {
      bad(name + " crosses or touches the outline: its " +
          side_name(side, static_cast<int>(holes[h].size())) + " and the outline's " +
          side_name(outline_side, static_cast<int>(outline.size())));
    }
    if (!inside_loop(outline, holes[h][0])) bad(name + " is outside the outline");
  }
  for (std::size_t h = 0; h < holes.size(); ++h) {
    for (std::size_t g = 0; g < h; ++g) {
      const auto [side, other_side] = first_meeting_sides(holes[h], holes[g]);
      const std::string names = "holes " + std::to_string(g) + " and " + std::to_string(h);
      if (side >= 0) {
        bad(names + " cross or touch: " + side_name(other_side, static_cast<int>(holes[g].size())) +
            " of hole " + std::to_string(g) + " and " +
            side_name(side, static_cast<int>(holes[h].size())) + " of hole " + std::to_string(h));
      }
      if (inside_loop(holes[g], holes[h][0]) || inside_loop(holes[h], holes[g][0]))
        bad(names + " overlap: one lies inside the other");
    }
  }
}

/// The grid points of `spacing` strictly inside the polygon whose outline is loops[0] (its
/// holes the later loops) and at least spacing/2 from each side of every loop, row by row
/// (y increasing), each row by x increasing. The grid is centred on the outline's bounding box.
std::vector<Eigen::Vector2d> interior_grid(const std::vector<std::vector<Eigen::Vector2d>>& loops,
                                           double spacing) {
  const std::vector<Eigen::Vector2d>& outline = loops[0];
  Eigen::Vector2d low = outline[0], high = outline[0];
  for (const auto& x : outline) {
    low = low.cwiseMin(x);
    high = high.cwiseMax(x);
  }
  const Eigen::Vector2d size = high - low;
  const int columns = static_cast<int>(std::floor(size.x() / spacing)) + 1;
  const int rows = static_cast<int>(std::floor(size.y() / spacing)) + 1;
  const Eigen::Vector2d first =
      low + 0.5 * (size - spacing * Eigen::Vector2d(columns - 1, rows - 1));
  const double margin = 0.5 * spacing;
  std::vector<Eigen::Vector2d> points;
  std::vector<std::pair<const Eigen::Vector2d*, const Eigen::Vector2d*>> near;
  std::vector<double> crossings;
  for (int r = 0; r < rows; ++r) {
    const double y = first.y() + r * spacing;
    near.clear();
    crossings.clear();
    for (const auto& loop : loops) {
      const int n = static_cast<int>(loop.size());
      for (int k = 0; k < n; ++k) {
        const auto& a = loop[k];
        const auto& b = loop[(k + 1) % n];
        if (std::min(a.y(), b.y()) <= y + margin && std::max(a.y(), b.y()) >= y - margin)
          near.push_back({&a, &b});
        if ((a.y() > y) != (b.y() > y))
          crossings.push_back(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
      }
    }
    std::sort(crossings.begin(), crossings.end());
    for (int c = 0; c < columns; ++c) {
      const Eigen::Vector2d x(first.x() + c * spacing, y);
      const auto left = std::lower_bound(crossings.begin(), crossings.end(), x.x());
      if ((left - crossings.begin()) % 2 == 0) continue;  // outside, or in a hole
      bool clear = true;
      for (const auto& [a, b] : near) {
        const Eigen::Vector2d side = *b - *a;
        const double t = std::clamp((x - *a).dot(side) / side.squaredNorm(), 0.0, 1.0);
        if ((*a + t * side - x).norm() < margin) {
          clear = false;
          break;
        }
      }
      if (clear) points.push_back(x);
    }
  }
  return points;
}

/// `loop` turned to the orientation `counter_clockwise` from its corner 0 (its corners after
/// corner 0 reversed when it turns the other way).
std::vector<Eigen::Vector2d> oriented(std::vector<Eigen::Vector2d> loop, bool counter_clockwise) {
  double twice_area = 0.0;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const auto& a = loop[k];
    const auto& b = loop[(k + 1) % loop.size()];
    twice_area += a.x() * b.y() - a.y() * b.x();
  }
  if ((twice_area < 0.0) == counter_clockwise) std::reverse(loop.begin() + 1, loop.end());
  return loop;
}

}  // namespace

double orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

std::vector<std::array<int, 2>> compute_triangle_edges(
    const std::vector<std::array<int, 3>>& triangles, int num_vertices) {
  std::unordered_map<std::int64_t, int> seen;
  std::vector<std::array<int, 2>> edges;
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = std::min(t[k], t[(k + 1) % 3]), b = std::max(t[k], t[(k + 1) % 3]);
      const std::int64_t key = std::int64_t{a} * num_vertices + b;
      if (seen.emplace(key, static_cast<int>(edges.size())).second) edges.push_back({a, b});
    }
  }
  return edges;
}

ElasticShape make_sheet(int nx, int ny, double width, double height, SheetDiagonals diagonals,
                        std::int64_t max_vertices) {
  check_vertex_count(saturating_product({nx + std::int64_t{1}, ny + std::int64_t{1}}), max_vertices,
                     "a sheet of " + std::to_string(nx) + " × " + std::to_string(ny) + " cells");
  ElasticShape shape;
  for (int r = 0; r <= ny; ++r) {
    for (int c = 0; c <= nx; ++c) shape.vertices.emplace_back(c * width / nx, r * height / ny);
  }
  for (int r = 0; r < ny; ++r) {
    for (int c = 0; c < nx; ++c) {
      const int a = r * (nx + 1) + c, b = a + 1, e = a + nx + 1, d = e + 1;
      if (diagonals == SheetDiagonals::kParallel || (r + c) % 2 == 0) {
        shape.triangles.push_back({a, b, d});
        shape.triangles.push_back({a, d, e});
      } else {
        shape.triangles.push_back({a, b, e});
        shape.triangles.push_back({b, d, e});
      }
    }
  }
  shape.edges = compute_triangle_edges(shape.triangles, shape.num_vertices());
  return shape;
}

ElasticShape make_rod(int segments, double length, std::int64_t max_vertices) {
  check_vertex_count(segments + std::int64_t{1}, max_vertices,
                     "a rod of " + std::to_string(segments) + " segments");
  ElasticShape shape;
  for (int k = 0; k <= segments; ++k) shape.vertices.emplace_back(k * length / segments, 0.0);
  connect_rod(shape, false);
  return shape;
}

ElasticShape make_ring_rod(int segments, double radius, std::int64_t max_vertices) {
  check_vertex_count(segments, max_vertices, "a ring of " + std::to_string(segments) + " segments");
  ElasticShape shape;
  for (int k = 0; k < segments; ++k) shape.vertices.push_back(on_circle(k, segments, radius));
  connect_rod(shape, true);
  return shape;
}

ElasticShape make_annulus(int segments, int layers, double inner_radius, double outer_radius,
                          std::int64_t max_vertices) {
  check_vertex_count(saturating_product({segments, layers + std::int64_t{1}}), max_vertices,
                     "an annulus of " + std::to_string(segments) + " segments × " +
                         std::to_string(layers) + " layers");
  ElasticShape shape;
  for (int j = 0; j <= layers; ++j) {
    const double r = inner_radius + (outer_radius - inner_radius) * j / layers;
    for (int k = 0; k < segments; ++k) shape.vertices.push_back(on_circle(k, segments, r));
  }
  for (int j = 0; j < layers; ++j) {
    for (int k = 0; k < segments; ++k) {
      // Quad a (inner, k), b (inner, k + 1), c (outer, k + 1), d (outer, k): counter-clockwise
      // it runs a, d, c, b.
      const int kk = (k + 1) % segments;
      const int a = j * segments + k, b = j * segments + kk;
      const int d = a + segments, c = b + segments;
      if ((j + k) % 2 == 0) {
        shape.triangles.push_back({a, d, c});
        shape.triangles.push_back({a, c, b});
      } else {
        shape.triangles.push_back({a, d, b});
        shape.triangles.push_back({b, d, c});
      }
    }
  }
  shape.edges = compute_triangle_edges(shape.triangles, shape.num_vertices());
  return shape;
}

ElasticShape make_polygon(const std::vector<Eigen::Vector2d>& outline, double spacing,
                          std::int64_t max_vertices, std::int64_t max_corners) {
  return make_polygon(outline, {}, spacing, max_vertices, max_corners);
}

ElasticShape make_polygon(const std::vector<Eigen::Vector2d>& given,
                          const std::vector<std::vector<Eigen::Vector2d>>& given_holes,
                          double spacing, std::int64_t max_vertices, std::int64_t max_corners) {
  auto corners = static_cast<std::int64_t>(given.size());
  for (const auto& hole : given_holes) corners += static_cast<std::int64_t>(hole.size());
  if (corners > max_corners) {
    bad((given_holes.empty() ? "a polygon of " : "a polygon with holes of ") +
        std::to_string(corners) + " corners, " +
        over_limit(max_corners, "corners", "--max-polygon-corners"));
  }
  check_vertex_count(corners, max_vertices,
                     given_holes.empty() ? "the polygon's outline" : "the polygon's outlines");
  check_simple(given);
  check_holes(given, given_holes);
  // The outline counter-clockwise, each hole clockwise: the body is on the left of every side.
  std::vector<std::vector<Eigen::Vector2d>> loops = {oriented(given, true)};
  for (const auto& hole : given_holes) loops.push_back(oriented(hole, false));
  std::vector<int> loop_corners;
  ElasticShape shape;
  for (const auto& loop : loops) {
    loop_corners.push_back(static_cast<int>(loop.size()));
    shape.vertices.insert(shape.vertices.end(), loop.begin(), loop.end());
  }
  std::vector<int> cuts(corners, 0);
  if (spacing > 0.0) {
    // Count first: the cut points exactly, the grid points by the outline's bounding box's grid.
    Eigen::Vector2d low = loops[0][0], high = loops[0][0];
    for (const auto& x : loops[0]) {
      low = low.cwiseMin(x);
      high = high.cwiseMax(x);
    }
    double total_cuts = 0.0;
    for (const auto& loop : loops) {
      const int n = static_cast<int>(loop.size());
      for (int k = 0; k < n; ++k)
        total_cuts += std::ceil((loop[(k + 1) % n] - loop[k]).norm() / spacing) - 1.0;
    }
    const Eigen::Vector2d size = high - low;
    const double grid =
        (std::floor(size.x() / spacing) + 1.0) * (std::floor(size.y() / spacing) + 1.0);
    const double bound = static_cast<double>(corners) + total_cuts + grid;
    check_vertex_count(
        bound < 9e18 ? static_cast<std::int64_t>(bound) : std::numeric_limits<std::int64_t>::max(),
        max_vertices,
        "the polygon at spacing " + to_text(spacing) +
            " (its corners, the cuts of its sides and the grid over its box)",
        "may have");
    int side = 0;
    for (const auto& loop : loops) {
      const int n = static_cast<int>(loop.size());
      for (int k = 0; k < n; ++k, ++side) {
        const Eigen::Vector2d a = loop[k], b = loop[(k + 1) % n];
        cuts[side] = static_cast<int>(std::ceil((b - a).norm() / spacing)) - 1;
        for (int s = 1; s <= cuts[side]; ++s)
          shape.vertices.push_back(a + (b - a) * (static_cast<double>(s) / (cuts[side] + 1)));
      }
    }
    for (const auto& x : interior_grid(loops, spacing)) shape.vertices.push_back(x);
  }
  shape.triangles = triangulate_polygon(shape.vertices, loop_corners, cuts);
  shape.edges = compute_triangle_edges(shape.triangles, shape.num_vertices());
  return shape;
}

ElasticShape make_triangle_shape(std::vector<Eigen::Vector2d> vertices,
                                 const std::vector<std::array<int, 3>>& triangles) {
  ElasticShape shape;
  shape.vertices = std::move(vertices);
  std::vector<char> used(shape.vertices.size(), 0);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    auto triangle = triangles[t];
    const double twice_area = orientation(shape.vertices[triangle[0]], shape.vertices[triangle[1]],
                                          shape.vertices[triangle[2]]);
    if (twice_area == 0.0) bad("triangle " + std::to_string(t) + " has zero area");
    if (twice_area < 0.0) std::swap(triangle[1], triangle[2]);
    for (const int v : triangle) used[v] = 1;
    shape.triangles.push_back(triangle);
  }
  for (std::size_t v = 0; v < used.size(); ++v) {
    if (!used[v]) bad("vertex " + std::to_string(v) + " is on no triangle");
  }
  shape.edges = compute_triangle_edges(shape.triangles, shape.num_vertices());
  return shape;
}

std::vector<double> lump_total_mass(const ElasticShape& shape, double total) {
  std::vector<double> weight(shape.vertices.size(), 0.0);
  if (shape.is_rod()) {
    for (const auto& [a, b] : shape.edges) {
      const double half = 0.5 * (shape.vertices[b] - shape.vertices[a]).norm();
      weight[a] += half;
      weight[b] += half;
    }
  } else {
    for (const auto& [a, b, c] : shape.triangles) {
      const double third =
          orientation(shape.vertices[a], shape.vertices[b], shape.vertices[c]) / 6.0;
      weight[a] += third;
      weight[b] += third;
      weight[c] += third;
    }
  }
  double sum = 0.0;
  for (const double w : weight) sum += w;
  std::vector<double> mass(weight.size());
  for (std::size_t v = 0; v < weight.size(); ++v) mass[v] = total * (weight[v] / sum);
  return mass;
}

std::vector<int> select_side(const ElasticShape& shape, ShapeSide side) {
  const int axis = (side == ShapeSide::kLeft || side == ShapeSide::kRight) ? 0 : 1;
  const bool highest = side == ShapeSide::kRight || side == ShapeSide::kTop;
  Eigen::Vector2d low = shape.vertices.front(), high = shape.vertices.front();
  for (const auto& x : shape.vertices) {
    low = low.cwiseMin(x);
    high = high.cwiseMax(x);
  }
  const double tolerance = 1e-9 * (high - low).maxCoeff();
  const double extreme = highest ? high[axis] : low[axis];
  std::vector<int> selected;
  for (int v = 0; v < shape.num_vertices(); ++v) {
    if (std::abs(shape.vertices[v][axis] - extreme) <= tolerance) selected.push_back(v);
  }
  return selected;
}

std::vector<Eigen::Vector2d> place_vertices(const ElasticShape& shape,
                                            const Eigen::Vector2d& origin,
                                            double rotation_degrees) {
  std::vector<Eigen::Vector2d> placed;
  placed.reserve(shape.vertices.size());
  if (rotation_degrees == 0.0) {  // exact: no cos/sin round-off on an unrotated body
    for (const auto& x : shape.vertices) placed.push_back(origin + x);
    return placed;
  }
  const double angle = rotation_degrees * std::numbers::pi / 180.0;
  const double c = std::cos(angle), s = std::sin(angle);
  for (const auto& x : shape.vertices)
    placed.emplace_back(origin.x() + (c * x.x() - s * x.y()), origin.y() + (s * x.x() + c * x.y()));
  return placed;
}

}  // namespace fosssim
