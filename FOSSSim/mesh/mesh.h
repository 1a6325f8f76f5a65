#pragma once
// A mass-spring mesh's geometry and topology, whatever file or generator it came from, and
// what the simulator derives from it: springs, lumped masses and surfaces to draw.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <string>
#include <vector>

#include "core/error.h"

namespace fosssim {

/// Vertices and elements, 0-based. Springs are not stored: they follow from the elements
/// (compute_spring_pairs), so a file's faces and a generator's grid give the same springs.
struct Mesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::vector<int>> faces;       ///< polygons of at least 3 corners
  std::vector<std::array<int, 2>> segments;  ///< springs beyond the elements' edges
  std::vector<std::array<int, 4>> tets;      ///< tetrahedra, positively oriented when generated

  int num_vertices() const { return static_cast<int>(vertices.size()); }
};

/// Vertex pairs joined by a spring: every pair of corners of a face (so a quad gets its four
/// sides and both diagonals, a triangle its three sides), every segment, and the six edges of
/// every tet. Each pair appears once, as (min, max), in order of first appearance.
std::vector<std::array<int, 2>> compute_spring_pairs(const Mesh& mesh);

/// Triangles covering the faces, each polygon fanned from its first corner.
std::vector<std::array<int, 3>> compute_face_triangles(const Mesh& mesh);

/// The boundary of the tets: faces that belong to exactly one tet, oriented so that their
/// normals (b - a) × (c - a) point out of it.
std::vector<std::array<int, 3>> compute_tet_boundary(const Mesh& mesh);

/// Signed volume of the tet (a, b, c, d): ((b - a) × (c - a))·(d - a) / 6.
double compute_tet_volume(const Mesh& mesh, const std::array<int, 4>& tet);

/// Area of triangle (a, b, c).
double compute_triangle_area(const Mesh& mesh, const std::array<int, 3>& triangle);

/// How the vertices of a mesh get their masses.
struct MassRule {
  enum Kind {
    kUniform,  ///< value = the mass of every vertex (kg)
    kTotal,    ///< value = the mesh's total mass (kg), shared equally by the vertices
    kArea,     ///< value = areal density (kg/m²); each face triangle gives a third of its mass
               ///< to each corner
    kVolume,   ///< value = density (kg/m³); each tet gives a quarter of its mass to each corner
  };
  Kind kind = kUniform;
  double value = 1.0;
};

/// Lumped vertex masses by the rule. Throws Error (kBadInput), naming the first such vertex,
/// when a vertex would get no mass (a vertex on no face under kArea, on no tet under kVolume),
/// or when the mesh has no face (kArea) or no tet (kVolume).
std::vector<double> compute_vertex_masses(const Mesh& mesh, const MassRule& rule);

/// The vertices whose coordinate along `axis` (0 x, 1 y, 2 z) is within `within` (≥ 0) of
/// the lowest (or, with highest, the highest) value among all vertices: CSC417's "within 3
/// units of the lowest y". In increasing order.
std::vector<int> select_extreme_vertices(const Mesh& mesh, int axis, bool highest, double within);

}  // namespace fosssim
