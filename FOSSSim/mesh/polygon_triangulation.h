#pragma once
// Triangulation of a polygon, with or without holes, with interior points: ear clipping (holes
// first joined to the outline by bridges), then Lawson's edge flips to the constrained Delaunay
// triangulation, then points inserted one by one (docs/forces.md, 'Authoring elastic bodies',
// says why this is written here rather than taken from a library).

#include <Eigen/Core>
#include <array>
#include <vector>

namespace fosssim {

/// Triangles over `points`, counter-clockwise and of positive area, covering the polygon whose
/// boundary is given by loops of corners, with every point a vertex. points begins with the
/// corners of every loop, loop after loop: loop_corners[l] corners each. Loop 0 is the outline,
/// counter-clockwise; every later loop is a hole, clockwise (the polygon is on the left of every
/// side). The caller checks that the loops are simple, that each hole is strictly inside the
/// outline and that no two loops meet. After the corners come cut points on the sides, side by
/// side, loop after loop: cuts_per_side[s] points on side s (side k of a loop runs from its
/// corner k to corner k + 1), in order from the side's first corner; the rest are interior
/// points, strictly inside the polygon, off every side and outside every hole.
///
/// 0. Holes (only when there are some; after Eberly 2002, "Triangulation by ear clipping"):
///    taken by decreasing largest x, each is joined to the outline it has grown to by a bridge,
///    from its corner of largest x to the nearest corner that sees it (the segment between them
///    meets no side and no other corner, and leaves both corners on the polygon's side). The
///    outline walks along the bridge, around the hole and back: one closed walk in which the two
///    ends of each bridge appear twice.
/// 1. Ear clipping (Meisters 1975): repeatedly cut off the first strictly convex corner whose
///    triangle holds no other vertex of the walk, inside or on its sides (without holes only
///    corners that are not strictly convex are tested, as only those can lie in an ear of a
///    simple polygon; with holes every vertex is, except the other appearances of the
///    triangle's own corners).
/// 2. Lawson flips: an edge between two triangles is flipped while the far corner of one lies
///    inside the other's circumcircle (by more than round-off) and their quadrilateral is
///    strictly convex; sides of the outline and of the holes are never flipped (bridges are
///    ordinary edges). (Before this, each cut point splits the triangle on its side in two.)
///    This ends in the constrained Delaunay triangulation of the loops (Lee and Lin 1986), which
///    maximizes the smallest angle among the triangulations that keep the sides.
/// 3. Each interior point, in order, is located by walking across triangles from the last
///    inserted one, splits its triangle in three (or, exactly on an edge, the two beside it in
///    four), and the edges opposite it are flipped as in 2 (incremental Delaunay insertion).
/// Deterministic: the result depends only on the input order; without holes it is the same as
/// before holes existed (the same triangles in the same order). Time O(n²) in the loops' corners
/// in the worst case of ear clipping and of each bridge, about linear in interior points given
/// in rows (points near holes may take a search over every triangle).
/// Throws Error (kBadInput) if no ear or no bridge is found (loops that are not as promised).
std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<Eigen::Vector2d>& points,
                                                    const std::vector<int>& loop_corners,
                                                    const std::vector<int>& cuts_per_side);

/// True when the closed segments [a, b] and [c, d] share a point (crossing, touching or
/// overlapping), decided by the signs of orientations (exact for the inputs' doubles up to the
/// round-off of one 2 × 2 determinant each).
bool closed_segments_meet(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                          const Eigen::Vector2d& c, const Eigen::Vector2d& d);

}  // namespace fosssim
