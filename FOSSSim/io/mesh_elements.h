#pragma once
// The scene-file elements that bring meshes in: <clothmesh>, <tetmesh> and <generate>.

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/force.h"
#include "core/scene.h"
#include "io/input_files.h"
#include "io/xml_tree.h"


namespace fosssim {

class SceneErrorList;

/// True for the root elements read by read_mesh_elements.
bool is_mesh_element(std::string_view name);
/// Their names.
std::span<const std::string_view> mesh_element_names();

/// Reads the root's mesh elements in document order (docs/scenes-3d.md): each appends its
/// vertices as particles (after those of <particle> elements), its springs as edges (after
/// those of <edge> elements) and its surface to the appearance, and yields one spring force.
/// The forces are returned for the caller to sum right after the <springforce> group.
/// Mesh files are found relative to the directory of `file` and read through `files`; a
/// generator is refused before it takes the scene past files.limits().max_particles. Each
/// element's problem (a SceneError naming the scene file, line and element, or the mesh file and
/// its line) goes into `errors`, and reading goes on with the next element.
std::vector<std::unique_ptr<Force>> read_mesh_elements(const XmlElement& root,
                                                       Scene& scene, const std::string& file,
                                                       InputFiles& files, SceneErrorList& errors);

}  // namespace fosssim
