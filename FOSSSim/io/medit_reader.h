#pragma once
// Reads MEDIT .mesh files (INRIA's ASCII mesh format) as tetrahedral mass-spring meshes.

#include <string>
#include <string_view>

#include "io/scene_error.h"
#include "mesh/mesh.h"

namespace fosssim {

/// Reads an ASCII MEDIT file (docs/scenes-3d.md, 'Mesh files'; every tet edge is a spring):
///   MeshVersionFormatted 1
///   Dimension 3
///   Vertices  N   then N lines "x y z ref"
///   Tetrahedra M  then M lines "a b c d ref" (1-based vertex indices)
///   End
/// Keywords and numbers are whitespace-separated words, so counts may follow on the same or
/// the next line; # starts a comment. Edges, Triangles, Quadrilaterals, Hexahedra, Corners,
/// Ridges, Required*, Normals, NormalAtVertices, Tangents and TangentAtVertices sections are
/// read and ignored (the surface to draw is the tets' boundary). Errors name file, line and
/// problem: an unknown keyword, a dimension other than 3, a missing or malformed count or
/// number, a file that ends inside a section, an index out of range, a tet with a repeated
/// vertex or zero volume, no vertices or no tets (thrown as SceneError).
Mesh read_medit_file(const std::string& path);

/// Reads MEDIT text; `name` stands for the file in messages.
Mesh read_medit_text(std::string_view text, const std::string& name);

}  // namespace fosssim
