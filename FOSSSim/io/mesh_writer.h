#pragma once
// Writes meshes as OBJ and MEDIT files, the formats the readers take.

#include <string>

#include "mesh/mesh.h"

namespace fosssim {

/// Writes the mesh's vertices, faces ("f", 1-based) and segments ("l a b") as OBJ; tets
/// cannot be written in OBJ and are left out. Numbers are written in their shortest exact form,
/// so reading the file back gives the same mesh. The file appears only when complete (written
/// to a temporary file beside it, then renamed; io/output_file.h). Throws Error (kCannotWrite) when
/// it cannot be written.
void write_obj_file(const std::string& path, const Mesh& mesh);

/// Writes the mesh's vertices and tets as an ASCII MEDIT file (MeshVersionFormatted 2,
/// Dimension 3, reference numbers 0), likewise exact and complete-or-absent.
void write_medit_file(const std::string& path, const Mesh& mesh);

}  // namespace fosssim
