#pragma once
// Triangulation of a simple polygon with interior points: ear clipping, then Lawson's edge flips
// to the constrained Delaunay triangulation, then points inserted one by one (docs/forces.md,
// 'Authoring elastic bodies', says why this is written here rather than taken from a library).

#include <Eigen/Core>
#include <array>
#include <vector>

namespace fosssim {

/// Triangles over `points`, counter-clockwise and of positive area, covering the polygon whose
/// outline is points[0 .. corners) in counter-clockwise order (simple: the caller checks), with
/// every later point a vertex. After the corners come cut points on the sides: cuts_per_side[k]
/// (k < corners) points on the side from corner k to corner k + 1, in order from corner k; the
/// rest are interior points, strictly inside and off every side.
///
/// 1. Ear clipping (Meisters 1975): repeatedly cut off the first strictly convex corner whose
///    triangle holds no other outline vertex, inside or on its sides.
/// 2. Lawson flips: an edge between two triangles is flipped while the far corner of one lies
///    inside the other's circumcircle (by more than round-off) and their quadrilateral is
///    strictly convex; sides of the outline are never flipped. (Before this, each cut point
///    splits the triangle on its side in two.) This ends in the constrained
///    Delaunay triangulation of the outline (Lee and Lin 1986), which maximizes the smallest
///    angle among the triangulations that keep the outline.
/// 3. Each interior point, in order, is located by walking across triangles from the last
///    inserted one, splits its triangle in three (or, exactly on an edge, the two beside it in
///    four), and the edges opposite it are flipped as in 2 (incremental Delaunay insertion).
/// Deterministic: the result depends only on the input order. Time O(n²) in the outline's
/// vertices in the worst case of ear clipping, about linear in interior points given in rows.
/// Throws Error (kBadInput) if no ear is found (a polygon that is not simple).
std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<Eigen::Vector2d>& points,
                                                    int corners,
                                                    const std::vector<int>& cuts_per_side);

}  // namespace fosssim
