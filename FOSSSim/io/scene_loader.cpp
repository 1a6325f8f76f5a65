#include "io/scene_loader.h"

#include "io/xml_tree.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <filesystem>
#include <map>
#include <utility>
#include <vector>

#include "core/force_registry.h"
#include "core/integrators/integrator_registry.h"
#include "io/collision_elements.h"
#include "io/elastic_body_element.h"
#include "io/element_reader.h"
#include "io/json_scene_reader.h"
#include "io/mesh_elements.h"
#include "io/scene_error.h"
#include "io/rigid_body_elements.h"
#include "io/text_lines.h"

namespace fosssim {

namespace {


constexpr std::array<const char*, 3> kPositionNames = {"px", "py", "pz"};
constexpr std::array<const char*, 3> kVelocityNames = {"vx", "vy", "vz"};

/// Elements that are not forces, in the order they are read.
constexpr std::array<const char*, 13> kOtherElements = {
    "duration",     "integrator", "maxsimfreq",    "description", "scenetag",
    "particle",     "edge",       "particlecolor", "edgecolor",   "backgroundcolor",
    "particlepath", "viewport",   "camera3d"};

bool is_known_element(std::string_view name) {
  for (const char* known : kOtherElements) {
    if (name == known) return true;
  }
  return find_force_kind(name) != nullptr || is_mesh_element(name) || is_collision_element(name) ||
         is_rigid_body_element(name) || name == kElasticBodyElement;
}

/// " (did you mean <springforce>?)" for an unknown element name within two edits of a known
/// one (the first in reading order), or nothing.
std::string element_suggestion(std::string_view unknown) {
  std::vector<std::string_view> names(kOtherElements.begin(), kOtherElements.end());
  for (const ForceKind& kind : force_kinds()) names.push_back(kind.tag);
  for (std::string_view name : mesh_element_names()) names.push_back(name);
  for (std::string_view name : collision_element_names()) names.push_back(name);
  for (std::string_view name : rigid_body_element_names()) names.push_back(name);
  names.push_back(kElasticBodyElement);
  for (std::string_view name : names) {
    if (looks_like_misspelling(unknown, name)) {
      return " (did you mean <" + std::string(name) + ">?)";
    }
  }
  return "";
}

/// Turns a parsed document into a Scene. Every element is read in errors_.attempt(), so that
/// one run reports the problems of every element (at most SceneErrorList::kMaxReported of
/// them); the problems that leave nothing sensible to go on with (the root, the dimension, a
/// count over a limit) end reading at once. An element that refers to a particle or edge whose
/// own element failed is skipped without a report (BrokenElements).
class SceneParser {
 public:
  SceneParser(const std::string& file, InputFiles& files, std::vector<std::string> warnings)
      : file_(file), files_(files) {
    scene_.warnings = std::move(warnings);
  }

  Scene parse(const XmlElement& root) {
    scene_.source = file_;
    read_root(root);
    group_children(root);
    if (is_rigid_body_scene(elements_, file_)) {
      if (scene_.model.dim != 2) {
        throw SceneError(file_, root.line(), "<scene>",
                         "rigid bodies are planar: a rigid-body scene cannot be dim=\"3\"");
      }
      if (const auto& bodies = all(std::string(kElasticBodyElement)); !bodies.empty()) {
        throw SceneError(file_, bodies[0]->line(), "<elasticbody>",
                         "an elastic body is made of particles: a rigid-body scene cannot hold "
                         "one");
      }
      read_rigid_body_scene(elements_, scene_, file_, files_.limits());
      return std::move(scene_);
    }
    for (const char* tag : {"rigidbodyvertex", "rigidbody", "rigidbodyintegrator"}) {
      if (!all(tag).empty()) {
        throw SceneError(file_, all(tag)[0]->line(), std::string("<") + tag + ">",
                         "belongs to rigid-body scenes, which start with <simtype "
                         "type=\"rigid-body\"/>");
      }
    }
    read_settings(root);
    read_particles();
    read_edges();
    mesh_forces_ = read_mesh_elements(root, scene_, file_, files_, errors_);
    elastic_forces_ = read_elastic_bodies(root, scene_, file_, files_, errors_);
    read_collision_elements(root, scene_, file_, files_.limits(), errors_);
    read_forces();
    read_appearance();
    errors_.throw_if_any();
    return std::move(scene_);
  }

 private:
  ElementReader reader(const XmlElement& element, int index) {
    ElementReader r(element, file_, index, scene_.model.num_particles(),
                    static_cast<int>(scene_.model.edges.size()));
    r.skip_broken(&broken_);
    return r;
  }

  /// Ends reading now: the problems found so far with `fatal` last.
  [[noreturn]] void stop(const SceneError& fatal) {
    errors_.add(fatal);
    errors_.throw_if_any();
    throw fatal;  // not reached: throw_if_any() throws
  }

  void keep_warnings(const ElementReader& r) {
    for (auto& warning : r.finish()) scene_.warnings.push_back(warning);
  }

  void read_root(const XmlElement& root) {
    if (std::string_view(root.name()) != "scene") {
      throw SceneError(file_, root.line(), std::string("<") + root.name() + ">",
                       "the root element must be <scene>");
    }
    ElementReader r = reader(root, -1);
    try {  // every other element depends on the dimension
      if (r.has("dim")) {
        const int dim = r.integer("dim");
        if (dim != 2 && dim != 3) r.fail("dim", "must be 2 or 3, found " + std::to_string(dim));
        scene_.model.dim = dim;
      }
      keep_warnings(r);
    } catch (const SceneError& error) {
      stop(error);
    }
  }

  void group_children(const XmlElement& root) {
    for (const XmlElement& element : root.children()) {
      const XmlElement* e = &element;
      if (!is_known_element(e->name())) {
        errors_.add(SceneError(file_, e->line(), std::string("<") + e->name() + ">",
                               "unknown element" + element_suggestion(e->name())));
        continue;
      }
      // Only the mesh elements hold elements (<pin>, read with them); anything inside another
      // element would otherwise be dropped without a word.
      const XmlElement* child = e->children().empty() ? nullptr : &e->children().front();
      if (child != nullptr && !is_mesh_element(e->name())) {
        errors_.add(SceneError(file_, child->line(), std::string("<") + child->name() + ">",
                               std::string("inside <") + e->name() +
                                   ">, which holds no elements: close <" + e->name() +
                                   " .../> before it"));
      }
      elements_[e->name()].push_back(e);
    }
  }

  const std::vector<const XmlElement*>& all(const std::string& name) { return elements_[name]; }

  /// The element that may appear at most once, or nullptr; required ones must appear.
  const XmlElement* single(const XmlElement& root, const char* name, bool required) {
    const auto& found = all(name);
    if (found.empty()) {
      if (required) {
        errors_.add(SceneError(file_, root.line(), "<scene>",
                               std::string("the required element <") + name + "> is missing"));
      }
      return nullptr;
    }
    if (found.size() > 1) {
      errors_.add(SceneError(
          file_, found[1]->line(), std::string("<") + name + ">",
          "may appear only once (first at line " + std::to_string(found[0]->line()) + ")"));
    }
    return found[0];
  }

  /// Reads the element `name` (at most one; `required` ones must appear) with `read`.
  template <class Read>
  void read_single(const XmlElement& root, const char* name, bool required, Read&& read) {
    if (const XmlElement* e = single(root, name, required)) {
      errors_.attempt([&] {
        ElementReader r = reader(*e, -1);
        read(r);
        keep_warnings(r);
      });
    }
  }

  void read_settings(const XmlElement& root) {
    SceneModel& model = scene_.model;
    read_single(root, "integrator", true, [&](ElementReader& r) {
      const std::string type = r.text("type");
      const IntegratorMethod* method = find_integrator_method(type);
      if (method == nullptr) {
        r.fail("type", "names an unknown integrator \"" + type + "\" (expected one of " +
                           describe_integrator_names() + ")");
      }
      const IntegratorProperties& runs = method->properties;
      if ((model.dim == 2 && !runs.runs_2d) || (model.dim == 3 && !runs.runs_3d)) {
        r.fail("type", "\"" + type + "\" does not run " + std::to_string(model.dim) + "D scenes");
      }
      model.integrator.use(*method);
      model.integrator.dt = r.positive("dt");
      AttributeOptions options(r);
      model.integrator.options.read(options);
    });
    read_single(root, "duration", true,
                [&](ElementReader& r) { model.duration = r.non_negative("time"); });
    read_single(root, "maxsimfreq", false,
                [&](ElementReader& r) { scene_.max_sim_frequency = r.positive("max"); });
    read_single(root, "description", false,
                [&](ElementReader& r) { scene_.description = r.text("text"); });
    read_single(root, "scenetag", false, [&](ElementReader& r) { scene_.tag = r.text("tag"); });
    read_single(root, "backgroundcolor", false,
                [&](ElementReader& r) { scene_.appearance.background = r.color(); });
    read_single(root, "viewport", false, [&](ElementReader& r) {
      scene_.appearance.viewport = Viewport{r.number("cx"), r.number("cy"), r.positive("size")};
    });
    if (const XmlElement* e = single(root, "camera3d", false)) {
      errors_.attempt([&] { read_camera3d(*e); });
    }
  }

  /// <camera3d yaw pitch distance tx ty tz fov projection>, every attribute optional.
  void read_camera3d(const XmlElement& e) {
    ElementReader r = reader(e, -1);
    if (scene_.model.dim != 3) r.fail("applies to 3D scenes only (<scene dim=\"3\">)");
    OrbitViewSettings view;
    if (r.has("yaw")) view.yaw = r.number("yaw");
    if (r.has("pitch")) view.pitch = r.number("pitch");
    if (r.has("distance")) view.distance = r.positive("distance");
    if (r.has("tx") || r.has("ty") || r.has("tz")) {
      view.target = std::array<double, 3>{r.number("tx"), r.number("ty"), r.number("tz")};
    }
    if (r.has("fov")) {
      const double fov = r.number("fov");
      if (!(fov > 0.0 && fov < 180.0)) {
        r.fail("fov", "must be between 0 and 180 degrees, found " + std::to_string(fov));
      }
      view.fov = fov;
    }
    const std::string projection = r.text_or_empty("projection");
    if (projection == "orthographic") {
      view.orthographic = true;
    } else if (!projection.empty() && projection != "perspective") {
      r.fail("projection", "must be perspective or orthographic, found \"" + projection + "\"");
    }
    scene_.appearance.camera3d = view;
    keep_warnings(r);
  }

  void read_particles() {
    SceneModel& model = scene_.model;
    const auto& particles = all("particle");
    if (static_cast<std::int64_t>(particles.size()) > files_.limits().max_particles) {
      stop(SceneError(
          file_, particles.front()->line(), "<particle>",
          "the scene declares " + std::to_string(particles.size()) + " particles, " +
              over_limit(files_.limits().max_particles, "particles", "--max-particles")));
    }
    const int n = static_cast<int>(particles.size());
    const int dim = model.dim;
    model.mass.setOnes(dim * n);  // a particle whose element fails keeps these values
    model.fixed.assign(n, false);
    scene_.initial.q.setZero(dim * n);
    scene_.initial.v.setZero(dim * n);
    broken_.particles.assign(n, 0);
    model.particle_radius.assign(n, SceneModel::kDefaultParticleRadius);
    scene_.appearance.particle_color.assign(n, Appearance::kDefaultParticleColor);
    scene_.particle_tags.assign(n, "");
    for (int p = 0; p < n; ++p) {
      broken_.particles[p] = !errors_.attempt([&] {
        ElementReader r = reader(*particles[p], p);
        model.mass.segment(dim * p, dim).setConstant(r.positive("m"));
        for (int c = 0; c < dim; ++c) {
          scene_.initial.q[dim * p + c] = r.number(kPositionNames[c]);
          scene_.initial.v[dim * p + c] = r.number(kVelocityNames[c]);
        }
        model.fixed[p] = r.flag("fixed");
        model.particle_radius[p] = r.non_negative_or("radius", SceneModel::kDefaultParticleRadius);
        scene_.particle_tags[p] = r.text_or_empty("tag");
        keep_warnings(r);
      });
    }
  }

  void read_edges() {
    const auto& edges = all("edge");
    // An edge whose element fails keeps its place (so that later edges keep their indices) as
    // the edge 0-0, marked broken: no element that refers to it is read.
    for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
      int i = 0, j = 0;
      double radius = SceneModel::kDefaultEdgeRadius;
      const bool read = errors_.attempt([&] {
        ElementReader r = reader(*edges[e], e);
        i = r.particle_index("i");
        j = r.particle_index("j");
        if (i == j) r.fail("j", "must differ from i (both are " + std::to_string(i) + ")");
        radius = r.non_negative_or("radius", SceneModel::kDefaultEdgeRadius);
        keep_warnings(r);
      });
      if (!read) i = j = 0;
      scene_.model.edges.push_back({i, j});
      scene_.model.edge_radius.push_back(radius);
      scene_.appearance.edge_color.push_back(Appearance::kDefaultEdgeColor);
      broken_.edges.push_back(read ? 0 : 1);
    }
  }

  void read_forces() {
    const ForceContext context{scene_.model, scene_.initial.q};
    for (const ForceKind& kind : force_kinds()) {
      const auto& declarations = all(std::string(kind.tag));
      for (int k = 0; k < static_cast<int>(declarations.size()); ++k) {
        errors_.attempt([&] {
          ElementReader r = reader(*declarations[k], k);
          std::unique_ptr<Force> force = kind.create(r, context);
          keep_warnings(r);
          scene_.model.forces.push_back(std::move(force));
        });
      }
      if (!declarations.empty()) {
        scene_.grading_theme = std::max(scene_.grading_theme, kind.course_theme);
      }
      if (kind.tag == "springforce") {  // mesh springs sum right after the <springforce> group
        for (auto& force : mesh_forces_) scene_.model.forces.push_back(std::move(force));
      }
      // An <elasticbody>'s forces sum right after the scene's own elements of their kind.
      if (const auto body = elastic_forces_.find(kind.tag); body != elastic_forces_.end()) {
        for (auto& force : body->second) scene_.model.forces.push_back(std::move(force));
      }
    }
  }

  void read_appearance() {
    Appearance& look = scene_.appearance;
    const auto& particle_colors = all("particlecolor");
    for (int k = 0; k < static_cast<int>(particle_colors.size()); ++k) {
      errors_.attempt([&] {
        ElementReader r = reader(*particle_colors[k], k);
        const int i = r.particle_index("i");
        look.particle_color[i] = r.color();
        keep_warnings(r);
      });
    }
    const auto& edge_colors = all("edgecolor");
    for (int k = 0; k < static_cast<int>(edge_colors.size()); ++k) {
      errors_.attempt([&] {
        ElementReader r = reader(*edge_colors[k], k);
        const int i = r.edge_index("i");
        look.edge_color[i] = r.color();
        keep_warnings(r);
      });
    }
    const auto& paths = all("particlepath");
    for (int k = 0; k < static_cast<int>(paths.size()); ++k) {
      errors_.attempt([&] {
        ElementReader r = reader(*paths[k], k);
        ParticlePath path;
        path.particle = r.particle_index("i");
        path.duration = r.non_negative("duration");
        path.color = r.color();
        keep_warnings(r);
        look.paths.push_back(path);
      });
    }
  }

  const std::string& file_;
  InputFiles& files_;
  Scene scene_;
  ElementGroups elements_;
  std::vector<std::unique_ptr<Force>> mesh_forces_;
  ForcesByTag elastic_forces_;
  SceneErrorList errors_;
  BrokenElements broken_;
};

/// Refuses, before the XML parser reads it, an element of more than `limit` attributes (counted
/// as the '=' signs outside quotes within its tag), in one linear pass: the check for repeated
/// attributes (io/xml_tree) takes quadratic time in them.
void check_attribute_counts(std::string_view text, const std::string& name, std::int64_t limit) {
  int line = 1, tag_line = 1;
  bool in_tag = false;
  char quote_char = 0;
  std::int64_t count = 0;
  for (std::size_t k = 0; k < text.size(); ++k) {
    const char c = text[k];
    if (c == '\n') ++line;
    if (quote_char != 0) {
      if (c == quote_char) quote_char = 0;
    } else if (in_tag) {
      if (c == '"' || c == '\'') quote_char = c;
      if (c == '>') in_tag = false;
      if (c == '=' && ++count > limit) {
        throw SceneError(name, tag_line, "",
                         "an element with " + over_limit(limit, "attributes", "--max-attributes"));
      }
    } else if (c == '<') {
      if (text.substr(k, 4) == "<!--") {  // a comment: skip it whole
        const std::size_t end = text.find("-->", k + 4);
        const std::size_t stop = end == std::string_view::npos ? text.size() : end + 3;
        line +=
            static_cast<int>(std::count(text.begin() + static_cast<std::ptrdiff_t>(k),
                                        text.begin() + static_cast<std::ptrdiff_t>(stop), '\n'));
        k = stop - 1;
        continue;
      }
      in_tag = true;
      tag_line = line;
      count = 0;
    }
  }
}

/// Loads a scene from its XML text, which it takes over: a file's text is read once into
/// memory and parsed where it lies, not copied (the contest timing scene is 2.6 MB).
Scene load_scene_from_text(std::string text, const std::string& name, InputFiles& files) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    throw SceneError(name, 0, "", "the file is empty (expected a <scene> element)");
  }
  if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos) {
    // The parser reads up to a NUL and would ignore the rest of the file.
    const auto line =
        1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(nul), '\n');
    throw SceneError(name, static_cast<int>(line), "",
                     "a NUL byte (at byte " + std::to_string(nul) +
                         "): a scene file is text, and nothing after it would be read");
  }
  check_attribute_counts(text, name, files.limits().max_attributes);
  std::vector<std::string> warnings;
  text = separate_run_together_attributes(std::move(text), name, warnings);
  // Only rigid bodies have hull attributes to number: elsewhere the pass would copy the whole
  // text unchanged (54 MB more at the peak of reading the 316x316 cloth, and 6% of its time).
  if (text.find("<rigidbody") != std::string::npos) {
    text = number_repeated_hull_attributes(text);
  }
  const XmlDocument top = parse_xml_text(std::move(text), name);
  if (top.empty()) throw SceneError(name, 0, "", "the file holds no XML element");
  if (top.size() > 1) {
    const XmlElement& second = top[1];
    throw SceneError(name, second.line(), std::string("<") + second.name() + ">",
                     "a second top-level element; a scene file holds one <scene>");
  }
  Scene scene = SceneParser(name, files, std::move(warnings)).parse(top.front());
  scene.files = files.paths();
  return scene;
}

}  // namespace

Scene load_scene_text(std::string_view text, const std::string& name, InputFiles& files) {
  return load_scene_from_text(std::string(text), name, files);
}

Scene load_scene_text(std::string_view text, const std::string& name) {
  InputFiles files;
  return load_scene_text(text, name, files);
}

Scene load_scene_file(const std::string& path, InputFiles& files) {
  if (std::filesystem::path(path).extension() == ".json") return load_json_scene_file(path, files);
  return load_scene_from_text(files.read(path), path, files);
}

Scene load_scene_file(const std::string& path) {
  InputFiles files;
  return load_scene_file(path, files);
}

}  // namespace fosssim
