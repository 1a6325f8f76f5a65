#pragma once
// Reads scenes in the course's XML format (docs/scene-format.md).

#include <string>
#include <string_view>

#include "core/scene.h"
#include "io/input_files.h"
#include "io/scene_error.h"

namespace fosssim {

/// Loads a scene file. Every malformed input (missing file, empty file, not XML, unknown
/// element, missing or non-numeric attribute, index out of range, non-positive mass, ...) is
/// thrown as a SceneError naming file, line, element and problem; nothing is defaulted
/// silently. Attributes nobody reads become warnings in Scene::warnings. A path ending in
/// ".json" is read as a fast mass-springs JSON scene instead (load_json_scene_file). The scene
/// file and its mesh files are read through `files` (regular files only, within its limits;
/// io/input_files.h), and Scene::files lists them. A scene of more particles than
/// files.limits().max_particles is refused.
Scene load_scene_file(const std::string& path, InputFiles& files);
/// The same with the default limits.
Scene load_scene_file(const std::string& path);

/// Loads a scene from XML text; `name` stands for the file in messages, and the mesh files it
/// names are read through `files`.
Scene load_scene_text(std::string_view text, const std::string& name, InputFiles& files);
/// The same with the default limits, mesh files read from the file system.
Scene load_scene_text(std::string_view text, const std::string& name);

}  // namespace fosssim
