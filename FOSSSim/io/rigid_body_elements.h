#pragma once
// The scene-file elements of Theme 3, planar rigid bodies (docs/scene-format.md, 'Rigid
// bodies'; docs/rigid-bodies.md).

#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/limits.h"
#include "core/scene.h"
#include "io/xml_tree.h"


namespace fosssim {

/// The root's elements grouped by name, in document order.
using ElementGroups = std::map<std::string, std::vector<const XmlElement*>, std::less<>>;

/// True for the elements that only rigid-body scenes hold (and <simtype>).
bool is_rigid_body_element(std::string_view name);
/// Those elements' names, for "did you mean" suggestions.
std::span<const std::string_view> rigid_body_element_names();

/// True when the root's <simtype> selects rigid bodies; throws SceneError for a simtype other
/// than "rigid-body" or "particle-system", or a second <simtype>.
bool is_rigid_body_scene(const ElementGroups& groups, const std::string& file);

/// Reads a rigid-body scene into `scene`: duration, <rigidbodyintegrator>, vertices, bodies
/// (mass properties from their vertices), the rigid-body forces in the registry's order,
/// colours, and the settings it shares with particle scenes (description, maxsimfreq, viewport,
/// backgroundcolor). Particle elements are ignored with a warning, as the course ignores them.
/// Numbers are read as the course reads them (trailing junk ignored, with a warning). Throws
/// SceneError naming file, line and element on bad input: fewer than two hull vertices, a
/// vertex or body index out of range, a non-positive radius, a bad integrator, more bodies or
/// vertices than limits.max_particles.
void read_rigid_body_scene(const ElementGroups& groups, Scene& scene, const std::string& file,
                           const Limits& limits);

/// The course writes a body's hull as repeated attributes, <rigidbody p="0" p="1" p="2" .../>,
/// which XML forbids. Renames the second and later `p` of every <rigidbody> tag to "p.2",
/// "p.3", ... (1-based occurrence), in place, so that an XML parser reads them in order; no
/// line changes, so messages keep their line numbers.
std::string number_repeated_hull_attributes(std::string_view text);

}  // namespace fosssim
