#include "io/mesh_elements.h"

#include "io/xml_tree.h"

#include <algorithm>
#include <array>
#include <map>

#include "io/element_reader.h"
#include "io/medit_reader.h"
#include "io/mesh_reference.h"
#include "io/obj_reader.h"
#include "io/scene_error.h"
#include "io/text_lines.h"
#include "mesh/generators.h"
#include "mesh/mesh_scene.h"

namespace fosssim {

namespace {


constexpr std::array<std::string_view, 3> kMeshElements = {"clothmesh", "tetmesh", "generate"};

/// A mesh element being read: the mesh, its pinned vertices and its label.
struct MeshDeclaration {
  Mesh mesh;
  std::vector<int> pinned;
  std::string label;
};

/// A required integer of at least `minimum`.
int integer_at_least(ElementReader& r, const char* name, int minimum) {
  const int value = r.integer(name);
  if (value < minimum)
    r.fail(name,
           "must be at least " + std::to_string(minimum) + ", found " + std::to_string(value));
  return value;
}

/// An optional positive number.
double positive_or(ElementReader& r, const char* name, double fallback) {
  return r.has(name) ? r.positive(name) : fallback;
}

/// An optional 0 or 1.
bool flag_or(ElementReader& r, const char* name, bool fallback) {
  return r.has(name) ? r.flag(name) : fallback;
}

GeneratedMesh generate_mesh(ElementReader& r, std::int64_t max_vertices) {
  const std::string type = r.text("type");
  if (type == "cloth") {
    const std::string plane = r.has("plane") ? r.text("plane") : "xy";
    if (plane != "xy" && plane != "xz")
      r.fail("plane", "must be \"xy\" (hanging) or \"xz\" (flat), found \"" + plane + "\"");
    return generate_cloth(integer_at_least(r, "nx", 2), integer_at_least(r, "ny", 2),
                          positive_or(r, "width", 1.0), positive_or(r, "height", 1.0),
                          plane == "xz", flag_or(r, "bend", true), max_vertices);
  }
  if (type == "chain")
    return generate_chain(integer_at_least(r, "links", 1), positive_or(r, "length", 1.0),
                          max_vertices);
  if (type == "net") {
    return generate_net(integer_at_least(r, "nx", 2), integer_at_least(r, "ny", 2),
                        positive_or(r, "width", 1.0), positive_or(r, "depth", 1.0), max_vertices);
  }
  if (type == "skirt") {
    const double top = positive_or(r, "top-radius", 0.25);
    return generate_skirt(integer_at_least(r, "segments", 3), integer_at_least(r, "rings", 2), top,
                          positive_or(r, "bottom-radius", 2.0 * top),
                          r.non_negative_or("height", 1.0), flag_or(r, "bend", true), max_vertices);
  }
  if (type == "tetbox") {
    return generate_tet_box(integer_at_least(r, "nx", 1), integer_at_least(r, "ny", 1),
                            integer_at_least(r, "nz", 1), positive_or(r, "sx", 1.0),
                            positive_or(r, "sy", 1.0), positive_or(r, "sz", 1.0), max_vertices);
  }
  if (type == "tetball")
    return generate_tet_ball(integer_at_least(r, "cells", 2), positive_or(r, "radius", 1.0),
                             max_vertices);
  r.fail("type", "names an unknown generator \"" + type +
                     "\" (expected cloth, chain, net, skirt, tetbox or tetball)");
}

/// The generated mesh of a <generate>, refused before it is generated when it would have more
/// than `max_vertices` vertices.
GeneratedMesh generate(ElementReader& r, std::int64_t max_vertices) {
  try {
    return generate_mesh(r, max_vertices);
  } catch (const SceneError&) {
    throw;
  } catch (const Error& error) {
    r.fail(error.what());
  }
}

/// Reads a mesh file, re-throwing its error with the element that asked for it.
template <typename ParseText>
Mesh read_mesh_file(ElementReader& r, const std::string& file, InputFiles& files,
                    ParseText parse_text) {
  const std::string name = r.text("file");
  return read_referenced_mesh(files, file, name, parse_text,
                              "the mesh of " + file + ":" + std::to_string(r.line()));
}

MassRule read_mass_rule(ElementReader& r) {
  const std::string kind = r.has("mass") ? r.text("mass") : "uniform";
  if (kind == "uniform") return {MassRule::kUniform, r.positive("m")};
  if (kind == "total") return {MassRule::kTotal, r.positive("total")};
  // "area" is the older name of "barycentric".
  if (kind == "barycentric" || kind == "area") return {MassRule::kArea, r.positive("density")};
  if (kind == "voronoi") return {MassRule::kVoronoi, r.positive("density")};
  if (kind == "volume") return {MassRule::kVolume, r.positive("density")};
  r.fail("mass",
         "must be \"uniform\" (with m), \"total\" (with total), \"barycentric\" (or \"area\"), "
         "\"voronoi\" or \"volume\" (with density), found \"" +
             kind + "\"");
}

/// Scales then translates the mesh: x ← scale·x + (tx, ty, tz).
void read_transform(ElementReader& r, Mesh& mesh) {
  const double scale = positive_or(r, "scale", 1.0);
  const Eigen::Vector3d shift(r.number_or("tx", 0.0), r.number_or("ty", 0.0),
                              r.number_or("tz", 0.0));
  for (auto& x : mesh.vertices) x = scale * x + shift;
}

/// Adds the vertices a <pin> child selects to `pinned`.
void read_pin(ElementReader& r, const Mesh& mesh, std::vector<int>& pinned) {
  if (r.has("vertices")) {
    const std::string list = r.text("vertices");
    std::string spaced = list;
    std::replace(spaced.begin(), spaced.end(), ',', ' ');
    for (std::string_view word : split_line(spaced)) {
      int v = 0;
      if (!parse_int(word, v)) r.fail("vertices", "must be vertex indices, found " + quote(word));
      if (v < 0 || v >= mesh.num_vertices()) {
        r.fail("vertices", "refers to vertex " + std::to_string(v) + ", but the mesh has " +
                               std::to_string(mesh.num_vertices()) + " (0-based)");
      }
      pinned.push_back(v);
    }
    return;
  }
  const std::string axis = r.text("axis");
  if (axis != "x" && axis != "y" && axis != "z")
    r.fail("axis", "must be x, y or z, found \"" + axis + "\"");
  const std::string side = r.text("side");
  if (side != "lowest" && side != "highest")
    r.fail("side", "must be \"lowest\" or \"highest\", found \"" + side + "\"");
  const auto selected =
      select_extreme_vertices(mesh, axis[0] - 'x', side == "highest", r.non_negative("within"));
  pinned.insert(pinned.end(), selected.begin(), selected.end());
}

}  // namespace

bool is_mesh_element(std::string_view name) {
  return std::find(kMeshElements.begin(), kMeshElements.end(), name) != kMeshElements.end();
}

std::span<const std::string_view> mesh_element_names() { return kMeshElements; }

std::vector<std::unique_ptr<Force>> read_mesh_elements(const XmlElement& root, Scene& scene,
                                                       const std::string& file, InputFiles& files,
                                                       SceneErrorList& errors) {
  const std::int64_t max_particles = files.limits().max_particles;
  std::vector<std::unique_ptr<Force>> forces;
  std::map<std::string, int> count;
  for (const XmlElement& element : root.children()) {
    const XmlElement* e = &element;
    const std::string kind = e->name();
    if (!is_mesh_element(kind)) continue;
    const int index = count[kind]++;
    errors.attempt([&] {
      ElementReader r(*e, file, index, scene.model.num_particles(),
                      static_cast<int>(scene.model.edges.size()));
      MeshDeclaration mesh;
      mesh.label = kind + " " + std::to_string(index);
      if (kind == "clothmesh") {
        const std::int64_t corners = files.limits().max_face_corners;
        mesh.mesh = read_mesh_file(r, file, files,
                                   [corners](std::string_view text, const std::string& name) {
                                     return read_obj_text(text, name, corners);
                                   });
      } else if (kind == "tetmesh") {
        mesh.mesh = read_mesh_file(r, file, files, read_medit_text);
      } else {
        GeneratedMesh generated = generate(r, max_particles);
        const std::string pins = r.has("pin") ? r.text("pin") : generated.default_pins;
        const std::vector<int>* set = generated.find_pins(pins);
        if (!set)
          r.fail("pin", "names no pin set of this generator: \"" + pins + "\" (expected " +
                            generated.pin_set_names() + ")");
        mesh.pinned = *set;
        mesh.mesh = std::move(generated.mesh);
        mesh.label += " (" + r.text("type") + ")";
      }
      read_transform(r, mesh.mesh);
      MeshMaterial material;
      material.k = r.non_negative("k");
      material.b = r.non_negative_or("b", 0.0);
      material.mass = read_mass_rule(r);
      material.velocity =
          Eigen::Vector3d(r.number_or("vx", 0.0), r.number_or("vy", 0.0), r.number_or("vz", 0.0));
      for (const XmlElement& pin_element : e->children()) {
        const XmlElement* child = &pin_element;
        if (std::string_view(child->name()) != "pin") {
          throw SceneError(file, child->line(), std::string("<") + child->name() + ">",
                           "unknown element inside <" + kind + "> (only <pin> may appear there)");
        }
        ElementReader pin(*child, file, -1, 0, 0);
        read_pin(pin, mesh.mesh, mesh.pinned);
        for (auto& warning : pin.finish()) scene.warnings.push_back(warning);
      }
      std::sort(mesh.pinned.begin(), mesh.pinned.end());
      mesh.pinned.erase(std::unique(mesh.pinned.begin(), mesh.pinned.end()), mesh.pinned.end());
      const std::int64_t particles =
          std::int64_t{scene.model.num_particles()} + mesh.mesh.num_vertices();
      if (particles > max_particles) {
        r.fail("its " + std::to_string(mesh.mesh.num_vertices()) + " vertices bring the scene to " +
               std::to_string(particles) + " particles, " +
               over_limit(max_particles, "particles", "--max-particles"));
      }
      std::vector<std::string> warnings = r.finish();  // before the scene changes
      std::unique_ptr<Force> force;
      try {
        force = append_mesh(scene, mesh.mesh, material, mesh.pinned, mesh.label);
      } catch (const Error& error) {
        r.fail(error.what());
      }
      forces.push_back(std::move(force));
      for (auto& warning : warnings) scene.warnings.push_back(warning);
    });
  }
  return forces;
}

}  // namespace fosssim
