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
               ///< to each corner (barycentric lumping)
    kVoronoi,  ///< value = areal density (kg/m²); each face triangle shares its mass by mixed
               ///< Voronoi areas (compute_voronoi_corner_areas)
    kVolume,   ///< value = density (kg/m³); each tet gives a quarter of its mass to each corner
  };
  Kind kind = kUniform;
  double value = 1.0;
};

/// The share of the area of triangle (a, b, c) that belongs to each corner in the mixed Voronoi
/// lumping of Meyer, Desbrun, Schröder and Barr, "Discrete Differential-Geometry Operators for
/// Triangulated 2-Manifolds" (2003), the default mass matrix of libigl for triangles. With A
/// the area, l_c the length of the side opposite corner c and cos_c = (l_{c+1}² + l_{c+2}² -
/// l_c²) / (2 l_{c+1} l_{c+2}) the cosine of its angle (law of cosines, indices mod 3):
/// - if a corner o is obtuse (cos_o < 0), o gets A/2 and the other two A/4 each;
/// - otherwise the circumcentre splits the triangle into three parts P_c = A w_c / (w_0 + w_1 +
///   w_2) with w_c = cos_c l_c (P_c is the part facing side c), and corner c gets the halves of
///   the two parts beside it, (P_{c+1} + P_{c+2}) / 2.
/// A right angle is not obtuse; both cases give A/2, A/4, A/4 there, so the rule is
/// continuous. The three shares sum to A.
std::array<double, 3> compute_voronoi_corner_areas(const Mesh& mesh,
                                                   const std::array<int, 3>& triangle);

/// Lumped vertex masses by the rule. Throws Error (kBadInput), naming the first such vertex,
/// when a vertex would get no mass (a vertex on no face under kArea or kVoronoi, on no tet under
/// kVolume), or when the mesh has no face (kArea, kVoronoi) or no tet (kVolume). Faces are
/// fanned into triangles (compute_face_triangles) for kArea and kVoronoi.
std::vector<double> compute_vertex_masses(const Mesh& mesh, const MassRule& rule);

/// The vertices whose coordinate along `axis` (0 x, 1 y, 2 z) is within `within` (≥ 0) of
/// the lowest (or, with highest, the highest) value among all vertices: CSC417's "within 3
/// units of the lowest y". In increasing order.
std::vector<int> select_extreme_vertices(const Mesh& mesh, int axis, bool highest, double within);

}  // namespace fosssim
