#pragma once
// The scene-file elements of contact: <halfplane>, <halfplanecolor>, <sphere>, <spherecolor>,
// <collision> and <collisiondetection> (docs/scene-format.md, docs/collisions.md).

#include <span>
#include <string>
#include <string_view>

#include "core/limits.h"
#include "core/scene.h"
#include "io/xml_tree.h"


namespace fosssim {

class SceneErrorList;

/// True for the root elements read by read_collision_elements.
bool is_collision_element(std::string_view name);
/// Their names.
std::span<const std::string_view> collision_element_names();

/// Reads the root's contact elements into `scene` (its particles and edges already read):
/// half-planes into model.half_planes and spheres (3D only) into model.spheres, their colours
/// into the appearance, the first
/// <collision> element into model.collisions (a second one is ignored with a warning, as the
/// course ignores it) and <collisiondetection>. Values the course accepts but that are probably
/// mistakes (a restitution outside [0, 1], a negative stiffness or thickness, a zero normal, a
/// fractional or negative maxiters) become warnings. Each element's problem (a SceneError
/// naming file, line and element) goes into `errors`, and reading goes on with the next one.
/// A `maxiters` above limits.max_hybrid_passes is read as that many, with a warning.
void read_collision_elements(const XmlElement& root, Scene& scene,
                             const std::string& file, const Limits& limits, SceneErrorList& errors);

/// Inserts the blank that is missing between two attributes written one after the other,
/// `vx="0"vy="0"`, which XML forbids and the course's parser reads as two attributes (an
/// official course scene has it). Nothing else changes: only a quote that closes an attribute
/// value inside a tag and is directly followed by a letter gets a blank after it. Appends a
/// warning naming the line of each place fixed. A text with no such place is returned as it
/// came, not copied.
std::string separate_run_together_attributes(std::string text, const std::string& file,
                                             std::vector<std::string>& warnings);

}  // namespace fosssim
