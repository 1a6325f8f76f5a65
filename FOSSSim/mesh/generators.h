#pragma once
// Procedural meshes, so that demos, tests and benchmarks need no outside data.

#include <string>
#include <utility>
#include <vector>

#include "core/limits.h"
#include "mesh/mesh.h"

namespace fosssim {

// Every generator refuses sizes that would make more than `max_vertices` vertices by throwing
// Error (kBadInput) before it allocates anything ("a tetbox of 2000 × 2000 × 2000 cubes has
// 8012006001 vertices, more than the limit of ..."); counts are computed in 64 bits.

/// A generated mesh with named sets of vertices to pin ("corners", "top-row", ...). Every
/// generator offers "none".
struct GeneratedMesh {
  Mesh mesh;
  std::vector<std::pair<std::string, std::vector<int>>> pin_sets;
  std::string default_pins;  ///< the set a scene pins unless told otherwise

  /// The set with this name, or nullptr.
  const std::vector<int>* find_pins(const std::string& name) const;
  /// "corners, top-row or none": the names, for messages.
  std::string pin_set_names() const;
};

/// A rectangular cloth of nx × ny vertices (nx, ny ≥ 2), width along x, height along the other
/// axis, centred on x = 0 with its top row (row 0) at the origin's level. In the "xy" plane it
/// hangs: row r at y = -r·height/(ny - 1), z = 0. In the "xz" plane it lies flat at y = 0, row
/// r at z = r·height/(ny - 1). Vertex (r, c) is r·nx + c. Faces are the grid's quads (so
/// springs are the structural sides and both shear diagonals); with bend, segments join every
/// vertex to the one two steps along each grid direction. Pin sets: "corners" (the two ends of
/// row 0, the default), "top-row" (all of row 0), "left-column" (all of column 0: a flag on
/// its pole), "none".
GeneratedMesh generate_cloth(int nx, int ny, double width, double height, bool horizontal,
                             bool bend, std::int64_t max_vertices = Limits{}.max_particles);

/// A chain of `links` ≥ 1 springs (links + 1 vertices) along +x from the origin, total length
/// `length`, as segments. Pin sets: "first" (vertex 0, the default), "ends", "none".
GeneratedMesh generate_chain(int links, double length,
                             std::int64_t max_vertices = Limits{}.max_particles);

/// A net: an nx × ny grid (≥ 2 each) lying flat at y = 0, centred on the origin, width along x
/// and depth along z, with springs only along the grid lines (segments, no faces). Pin sets:
/// "corners" (the default), "border", "none".
GeneratedMesh generate_net(int nx, int ny, double width, double depth,
                           std::int64_t max_vertices = Limits{}.max_particles);

/// A skirt: `rings` ≥ 2 circles of `segments` ≥ 3 vertices around the y axis, the top ring of
/// radius top_radius at y = 0, the bottom one of radius bottom_radius at y = -height (≥ 0; 0
/// gives a flat annulus that falls into folds), radii in between linear. Faces are the quads
/// between rings (wrapping around); with bend, segments join every vertex to the one two steps
/// along its ring and two rings down. Pin sets: "top" (the top ring, the default), "none".
GeneratedMesh generate_skirt(int segments, int rings, double top_radius, double bottom_radius,
                             double height, bool bend,
                             std::int64_t max_vertices = Limits{}.max_particles);

/// A box of nx × ny × nz cubes (≥ 1 each) spanning size_x × size_y × size_z, centred on the
/// origin, each cube split into six positively oriented tets around its main diagonal (Kuhn's
/// subdivision, which is conforming across cubes). Pin sets: "none" (the default), "bottom"
/// (the lowest layer, y minimal), "left" (x minimal: a cantilever).
GeneratedMesh generate_tet_box(int nx, int ny, int nz, double size_x, double size_y, double size_z,
                               std::int64_t max_vertices = Limits{}.max_particles);

/// A ball of radius `radius` centred on the origin: the cubes of a grid with `cells` ≥ 2
/// cubes along the diameter whose centres lie inside the sphere, each split as in
/// generate_tet_box. Pin sets: "none" (the default), "bottom" (the lowest layer of vertices).
GeneratedMesh generate_tet_ball(int cells, double radius,
                                std::int64_t max_vertices = Limits{}.max_particles);

}  // namespace fosssim
