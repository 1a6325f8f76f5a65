#pragma once
// A mesh file named by a scene file (an XML <mesh file="…"> or a JSON "obj").

#include <filesystem>
#include <string>

#include "io/input_files.h"
#include "io/scene_error.h"
#include "mesh/mesh.h"

namespace fosssim {

/// Reads the mesh file `name` through `files` and parses it with `parse_text` (read_obj_text or
/// read_medit_text); a relative name is taken from the folder of `scene_file`. The error is
/// thrown again with " (<context>)" added to its problem, so the message names both files.
template <typename ParseText>
Mesh read_referenced_mesh(InputFiles& files, const std::string& scene_file, const std::string& name,
                          ParseText parse_text, const std::string& context) {
  std::filesystem::path path(name);
  if (path.is_relative()) path = std::filesystem::path(scene_file).parent_path() / path;
  try {
    return parse_text(files.read(path.string()), path.string());
  } catch (const SceneError& e) {
    throw SceneError(e.file(), e.line(), e.element(), e.problem() + " (" + context + ")");
  }
}

}  // namespace fosssim
