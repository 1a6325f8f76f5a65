#pragma once
// Planar elastic bodies for the Theme 4 forces, generated from a few numbers (docs/scene-format.md,
// 'Elastic bodies from one element'): a sheet, a rod, a ring or annulus, a triangulated polygon,
// or triangles given by the caller (an OBJ file read in io/). No files here.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/limits.h"

namespace fosssim {

/// A planar body as elements over vertices, in the body's own frame, before it has particles.
/// Triangles carry constant strain triangles (CST), edges elastic springs, hinges bending.
struct ElasticShape {
  std::vector<Eigen::Vector2d> vertices;
  /// Counter-clockwise, of positive area.
  std::vector<std::array<int, 3>> triangles;
  /// Each edge once: a rod's segments in order, or the sides of the triangles in order of first
  /// appearance, as (smaller, larger) index.
  std::vector<std::array<int, 2>> edges;
  /// (previous, hinge, next) along a rod or closed rod: one per interior vertex (every vertex
  /// of a closed rod).
  std::vector<std::array<int, 3>> hinges;

  int num_vertices() const { return static_cast<int>(vertices.size()); }
  bool is_rod() const { return triangles.empty(); }
};

/// How a sheet's cells are cut into two triangles. Cell (r, c) has corners a = (r, c) lower
/// left, b = (r, c + 1) lower right, d = (r + 1, c + 1) upper right, e = (r + 1, c) upper left.
enum class SheetDiagonals {
  kAlternating,  ///< a–d where r + c is even, b–e where it is odd (a symmetric pattern)
  kParallel,     ///< a–d in every cell
};

/// A width × height rectangle of nx × ny cells (≥ 1 each), lower left corner at the origin:
/// vertex (r, c) = r (nx + 1) + c at (c·width/nx, r·height/ny); triangles (a, b, d), (a, d, e)
/// for a cell cut a–d, (a, b, e), (b, d, e) for one cut b–e, cells row by row.
ElasticShape make_sheet(int nx, int ny, double width, double height, SheetDiagonals diagonals,
                        std::int64_t max_vertices = Limits{}.max_particles);

/// A straight rod of `segments` ≥ 1 springs along +x from the origin, total `length`; hinges
/// (k − 1, k, k + 1) at the segments − 1 interior vertices.
ElasticShape make_rod(int segments, double length,
                      std::int64_t max_vertices = Limits{}.max_particles);

/// A closed rod: `segments` ≥ 3 vertices on the circle of `radius` around the origin, vertex k
/// at angle 2πk/segments (counter-clockwise), springs (k, k + 1) and a hinge at every vertex.
ElasticShape make_ring_rod(int segments, double radius,
                           std::int64_t max_vertices = Limits{}.max_particles);

/// An annulus between inner_radius and outer_radius (0 < inner < outer) around the origin:
/// layers + 1 circles of `segments` ≥ 3 vertices (circle j, vertex k = j·segments + k at angle
/// 2πk/segments), the quads between neighbouring circles cut into two triangles alternately
/// along either diagonal.
ElasticShape make_annulus(int segments, int layers, double inner_radius, double outer_radius,
                          std::int64_t max_vertices = Limits{}.max_particles);

/// The simple polygon `outline` (vertices in order, either orientation; at least 3; no vertex
/// repeated; no two sides crossing or touching), triangulated (mesh/polygon_triangulation.h).
/// With spacing > 0, sides are first cut into pieces no longer than `spacing` and points of a
/// square grid of that spacing, at least spacing/2 from the outline, are added inside, so that
/// triangles have sides of about `spacing`; with spacing = 0 the triangles use the outline's
/// vertices only. The vertices are the outline's (counter-clockwise from outline[0]), then the
/// cut points, then the grid points row by row. Refused before any work: more than max_corners
/// corners, or more than max_vertices vertices counting the grid over the bounding box.
ElasticShape make_polygon(const std::vector<Eigen::Vector2d>& outline, double spacing,
                          std::int64_t max_vertices = Limits{}.max_particles,
                          std::int64_t max_corners = Limits{}.max_polygon_corners);

/// The same with holes: each hole a simple polygon (as the outline: either orientation, at
/// least 3 corners), strictly inside the outline, meeting neither the outline nor another hole
/// (no sides crossing or touching, no hole inside another). Messages name the hole (0-based) and
/// its sides. The vertices are the outline's corners (counter-clockwise from outline[0]), each
/// hole's corners in turn (clockwise from its corner 0: the body is on the left of every side),
/// then the cut points of the outline's sides and of each hole's, then the grid points outside
/// the holes and at least spacing/2 from every side. max_corners bounds the outline's and the
/// holes' corners together. Without holes it is exactly make_polygon(outline, spacing, ...).
ElasticShape make_polygon(const std::vector<Eigen::Vector2d>& outline,
                          const std::vector<std::vector<Eigen::Vector2d>>& holes, double spacing,
                          std::int64_t max_vertices = Limits{}.max_particles,
                          std::int64_t max_corners = Limits{}.max_polygon_corners);

/// Triangles over given vertices (an OBJ file's, say): each turned counter-clockwise, edges
/// derived. Throws Error (kBadInput) naming the 0-based triangle for a triangle of zero area
/// and the vertex for a vertex on no triangle.
ElasticShape make_triangle_shape(std::vector<Eigen::Vector2d> vertices,
                                 const std::vector<std::array<int, 3>>& triangles);

/// The sides of the triangles, each once as (smaller, larger), in order of first appearance.
std::vector<std::array<int, 2>> compute_triangle_edges(
    const std::vector<std::array<int, 3>>& triangles, int num_vertices);

/// Twice the signed area of (a, b, c): (b − a) × (c − a), positive when counter-clockwise.
double orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c);

/// Masses lumped from a total: a triangle gives a third of its share of `total` (by area) to
/// each corner; a rod's segment half of its share (by length) to each end. They sum to `total`
/// up to round-off.
std::vector<double> lump_total_mass(const ElasticShape& shape, double total);

/// The side of a body's own frame a scene may fix.
enum class ShapeSide { kLeft, kRight, kBottom, kTop };

/// The vertices on that side: those whose x (left, right) or y (bottom, top) is within 1e-9 of
/// the body's size of the extreme value. In increasing order.
std::vector<int> select_side(const ElasticShape& shape, ShapeSide side);

/// Moves the body from its own frame: x ← origin + R(rotation_degrees) x, R turning
/// counter-clockwise.
std::vector<Eigen::Vector2d> place_vertices(const ElasticShape& shape,
                                            const Eigen::Vector2d& origin, double rotation_degrees);

}  // namespace fosssim
