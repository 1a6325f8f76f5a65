#pragma once
// A mesh file named by a scene file (an XML <mesh file="…"> or a JSON "obj").

#include <filesystem>
#include <string>

#include "io/scene_error.h"
#include "mesh/mesh.h"

namespace fosssim {

/// Reads the mesh file `name` with `reader` (read_obj_file or read_medit_file); a relative name
/// is taken from the folder of `scene_file`. The reader's error is thrown again with
/// " (<context>)" added to its problem, so the message names both files.
template <typename Reader>
Mesh read_referenced_mesh(const std::string& scene_file, const std::string& name, Reader reader,
                          const std::string& context) {
  std::filesystem::path path(name);
  if (path.is_relative()) path = std::filesystem::path(scene_file).parent_path() / path;
  try {
    return reader(path.string());
  } catch (const SceneError& e) {
    throw SceneError(e.file(), e.line(), e.element(), e.problem() + " (" + context + ")");
  }
}

}  // namespace fosssim
