#include "io/rigid_body_elements.h"

#include "io/xml_tree.h"

#include <array>
#include <cmath>

#include "core/collisions/contact_registry.h"
#include "core/force_registry.h"
#include "core/integrators/integrator_registry.h"
#include "core/rigid/rigid_bodies.h"
#include "core/rigid/rigid_contact_stage.h"
#include "io/element_reader.h"
#include "io/scene_error.h"

namespace fosssim {

namespace {


constexpr std::array<std::string_view, 8> kRigidBodyElements = {"simtype",
                                                                "rigidbodyintegrator",
                                                                "rigidbodyvertex",
                                                                "rigidbody",
                                                                "rigidbodycolor",
                                                                "rigidbodyspringcolor",
                                                                "rigidbodycollisionhandling",
                                                                "rigidbodyforce"};

/// Elements of particle scenes that the course ignores in a rigid-body scene.
constexpr std::array<std::string_view, 9> kParticleElements = {
    "integrator",   "particle", "edge",      "particlecolor", "edgecolor",
    "particlepath", "scenetag", "halfplane", "collision"};

/// The methods of Theme 3, by their exact names (the course accepts no alias).
constexpr std::array<std::string_view, 2> kRigidBodyIntegrators = {"explicit-euler",
                                                                   "symplectic-euler"};

const std::vector<const XmlElement*>& all(const ElementGroups& groups, std::string_view name) {
  static const std::vector<const XmlElement*> none;
  const auto found = groups.find(name);
  return found == groups.end() ? none : found->second;
}

class RigidBodySceneReader {
 public:
  RigidBodySceneReader(const ElementGroups& groups, Scene& scene, const std::string& file,
                       const Limits& limits)
      : groups_(groups), scene_(scene), file_(file), limits_(limits) {}

  void read() {
    scene_.model.dim = kRigidBodyCoordinates;
    scene_.grading_theme = 3;
    warn_ignored_elements();
    read_settings();
    read_vertices();
    read_bodies();
    read_forces();
    read_colors();
  }

 private:
  ElementReader reader(const XmlElement& element, int index) {
    ElementReader r(element, file_, index, scene_.model.num_particles(), 0);
    r.read_numbers_as_course();
    r.warn_about_misspellings();  // course files may hold them: warned, never refused
    return r;
  }
  void keep_warnings(const ElementReader& r) {
    for (auto& warning : r.finish()) scene_.warnings.push_back(warning);
  }
  std::string warning_at(const XmlElement& e, const std::string& text) const {
    return file_ + ":" + std::to_string(e.line()) + ": warning: <" + e.name() + ">: " + text;
  }

  /// The first element `name`; a later one is ignored with a warning, as the course reads only
  /// the first. Throws when a required one is missing.
  const XmlElement* first(std::string_view name, bool required) {
    const auto& found = all(groups_, name);
    if (found.empty()) {
      if (!required) return nullptr;
      throw SceneError(file_, 0, "<scene>",
                       "the required element <" + std::string(name) + "> is missing");
    }
    for (std::size_t k = 1; k < found.size(); ++k) {
      scene_.warnings.push_back(warning_at(
          *found[k], "a second <" + std::string(name) + "> is ignored (the first one counts)"));
    }
    return found[0];
  }

  void warn_ignored_elements() {
    for (std::string_view name : kParticleElements) {
      for (const XmlElement* e : all(groups_, name)) {
        scene_.warnings.push_back(
            warning_at(*e, "ignored: a rigid-body scene reads no particle elements"));
      }
    }
    for (const ForceKind& kind : force_kinds()) {
      if (kind.course_theme == 3) continue;
      for (const XmlElement* e : all(groups_, kind.tag)) {
        scene_.warnings.push_back(
            warning_at(*e, "ignored: a particle force in a rigid-body scene"));
      }
    }
  }

  void read_settings() {
    SceneModel& model = scene_.model;
    {
      ElementReader r = reader(*first("rigidbodyintegrator", true), -1);
      const std::string type = r.text("type");
      const IntegratorMethod* method = nullptr;
      for (std::string_view name : kRigidBodyIntegrators) {
        if (type == name) method = find_integrator_method(name);
      }
      if (method == nullptr) {
        r.fail("type", "names \"" + type +
                           "\", but rigid bodies step with explicit-euler or symplectic-euler");
      }
      model.integrator.use(*method);
      model.integrator.dt = r.positive("dt");
      keep_warnings(r);
    }
    {
      ElementReader r = reader(*first("duration", true), -1);
      model.duration = r.non_negative("time");
      keep_warnings(r);
    }
    if (const XmlElement* e = first("maxsimfreq", false)) {
      ElementReader r = reader(*e, -1);
      scene_.max_sim_frequency = r.positive("max");
      keep_warnings(r);
    }
    if (const XmlElement* e = first("description", false)) {
      ElementReader r = reader(*e, -1);
      scene_.description = r.text("text");
      keep_warnings(r);
    }
    if (const XmlElement* e = first("backgroundcolor", false)) {
      ElementReader r = reader(*e, -1);
      scene_.appearance.background = r.color();
      keep_warnings(r);
    }
    if (const XmlElement* e = first("viewport", false)) {
      ElementReader r = reader(*e, -1);
      scene_.appearance.viewport = Viewport{r.number("cx"), r.number("cy"), r.positive("size")};
      keep_warnings(r);
    }
  }

  void check_count(const std::vector<const XmlElement*>& elements, const char* what) {
    if (static_cast<std::int64_t>(elements.size()) > limits_.max_particles) {
      throw SceneError(file_, elements.front()->line(),
                       std::string("<") + elements.front()->name() + ">",
                       "the scene declares " + std::to_string(elements.size()) + " " + what + ", " +
                           over_limit(limits_.max_particles, what, "--max-particles"));
    }
  }

  void read_vertices() {
    const auto& vertices = all(groups_, "rigidbodyvertex");
    check_count(vertices, "rigid-body vertices");
    for (int k = 0; k < static_cast<int>(vertices.size()); ++k) {
      ElementReader r = reader(*vertices[k], k);
      positions_.emplace_back(r.number("x"), r.number("y"));
      masses_.push_back(r.number("m"));
      if (!(masses_.back() > 0.0)) {
        r.warn("mass " + to_text(masses_.back()) +
               " is not positive (accepted, as the course does; a body's mass or inertia may "
               "then be zero or negative)");
      }
      keep_warnings(r);
    }
  }

  /// The hull's vertex indices: "p", then "p.2", "p.3", ... (number_repeated_hull_attributes).
  std::vector<int> read_hull(ElementReader& r) {
    std::vector<int> hull;
    const int vertices = static_cast<int>(positions_.size());
    for (int k = 1;; ++k) {
      const std::string name = k == 1 ? "p" : "p." + std::to_string(k);
      if (!r.has(name.c_str())) break;
      const int index = r.integer(name.c_str());
      if (index < 0 || index >= vertices) {
        r.fail("p",
               "number " + std::to_string(k) + " refers to vertex " + std::to_string(index) +
                   ", but the scene has " + std::to_string(vertices) +
                   " <rigidbodyvertex> elements" +
                   (vertices > 0 ? " (valid: 0 to " + std::to_string(vertices - 1) + ")" : ""));
      }
      hull.push_back(index);
    }
    if (hull.size() < 2) {
      r.fail("needs at least 2 hull vertices (p=\"...\" attributes), found " +
             std::to_string(hull.size()));
    }
    return hull;
  }

  void read_bodies() {
    SceneModel& model = scene_.model;
    const auto& elements = all(groups_, "rigidbody");
    check_count(elements, "rigid bodies");
    auto bodies = std::make_shared<RigidBodies>();
    const int n = static_cast<int>(elements.size());
    model.mass.resize(3 * n);
    model.fixed.assign(n, false);
    model.particle_radius.assign(n, 0.0);
    scene_.initial.q.resize(3 * n);
    scene_.initial.v.resize(3 * n);
    scene_.appearance.particle_color.assign(n, Appearance::kDefaultParticleColor);
    scene_.particle_tags.assign(n, "");
    for (int b = 0; b < n; ++b) {
      ElementReader r = reader(*elements[b], b);
      RigidBody body;
      body.hull = read_hull(r);
      std::vector<Vec2> points;
      std::vector<double> masses;
      for (int index : body.hull) {
        points.push_back(positions_[index]);
        masses.push_back(masses_[index]);
      }
      const MassProperties properties = compute_mass_properties(points, masses);
      body.mass = properties.mass;
      body.inertia = properties.inertia;
      body.initial_center = properties.center;
      for (const Vec2& p : points) {
        body.body_points.emplace_back(p.x() - properties.center.x(), p.y() - properties.center.y());
      }
      if (!(body.mass > 0.0) || !(body.inertia > 0.0)) {
        r.warn("mass " + to_text(body.mass) + " and moment of inertia " + to_text(body.inertia) +
               ": the body cannot be stepped (division by zero or a negative mass)");
      }
      if (signed_area(points) > 0.0) {
        r.warn(
            "the hull runs counter-clockwise; the course asks for clockwise hulls (no result "
            "depends on it)");
      }
      const Vec2 velocity(r.number("vx"), r.number("vy"));
      const double omega = r.number("omega");
      body.radius = r.positive("r");
      body.fixed = r.has("fixed") && r.flag("fixed");
      if (body.fixed) {
        body.reported_velocity = velocity;
        body.reported_omega = omega;
        if (velocity != Vec2::Zero() || omega != 0.0) {
          r.warn(
              "a fixed body with a velocity: it never moves, but its trajectory reports that "
              "velocity, as the course does");
        }
      }
      model.mass.segment<3>(3 * b) << body.mass, body.mass, body.inertia;
      model.fixed[b] = body.fixed;
      model.particle_radius[b] = body.radius;
      scene_.initial.q.segment<3>(3 * b) << properties.center.x(), properties.center.y(), 0.0;
      if (body.fixed) {
        scene_.initial.v.segment<3>(3 * b).setZero();
      } else {
        scene_.initial.v.segment<3>(3 * b) << velocity.x(), velocity.y(), omega;
      }
      bodies->bodies.push_back(std::move(body));
      keep_warnings(r);
    }
    if (n == 0) scene_.warnings.push_back(file_ + ": warning: the scene has no rigid bodies");
    RigidBodies& built = *bodies;
    model.rigid_bodies = std::move(bodies);
    built.contact = read_contact(built);  // after: the registry's refusal reads the model
  }

  /// <rigidbodycollisionhandling detection="all-pairs" response="..."/>, with the course's
  /// messages: the response is a contact method of planar rigid bodies (contact_registry.h),
  /// which becomes model.collisions.method; FOSSSim's own optional maxreflections="..." and
  /// maxgroupcontacts="..." (its limits) go to model.rigid_bodies->contact.
  RigidContactSettings read_contact(const RigidBodies& bodies) {
    RigidContactSettings settings;
    const XmlElement* e = first("rigidbodycollisionhandling", false);
    if (e == nullptr) return settings;  // no contact: model.collisions keeps "none"
    ElementReader r = reader(*e, -1);
    if (!r.has("detection")) {
      r.fail("No rigidbodycollisionhandling 'detection' attribute specified. Exiting.");
    }
    const std::string detection = r.text("detection");
    if (detection != "all-pairs") {
      r.fail("Invalid rigidbodycollisionhandling 'detection' attribute specified. Valid option "
             "is all-pairs. Exiting. (found \"" + detection + "\")");
    }
    if (!r.has("response")) {
      r.fail("No rigidbodycollisionhandling 'response' attribute specified. Exiting.");
    }
    const std::string response = r.text("response");
    const ContactMethod* method = find_contact_method(response);
    const std::string refusal =
        method == nullptr ? "" : contact_method_refusal(*method, scene_.model);
    if (method == nullptr || !refusal.empty()) {
      r.fail("Invalid rigidbodycollisionhandling 'response' attribute specified. Valid options "
             "are lcp and velocity-projection. Exiting. (found \"" + response + "\"" +
             (refusal.empty() ? "" : ": " + refusal) + "; " + other_rigid_responses() +
             " are valid too)");
    }
    scene_.model.collisions.use(*method);
    const RigidResponse& chosen = *method->rigid_response;
    // The method's options (FOSSSim's limits; the registry entry lists them, --help shows them).
    AttributeOptions attributes(r);
    OptionValues& options = scene_.model.collisions.options;
    options.read(attributes);
    if (options.has("maxreflections")) settings.max_reflections = options.integer("maxreflections");
    if (options.has("maxgroupcontacts")) {
      settings.max_group_contacts = options.integer("maxgroupcontacts");
    }
    for (int b = 0; b < bodies.size(); ++b) {
      const RigidBody& body = bodies.bodies[b];
      if (!body.fixed || (body.reported_velocity == Vec2::Zero() && body.reported_omega == 0.0)) {
        continue;
      }
      r.warn("fixed body " + std::to_string(b) + " declares a velocity: " +
             (chosen.solver == ContactSolver::kLcp
                  ? "the LCP counts it in contacts' normal velocities (velocity projection "
                    "ignores it)"
                  : "velocity projection ignores it (the LCP would count it)") +
             (chosen.generalized_reflections && chosen.solver == ContactSolver::kLcp
                  ? "; with gr-lcp a body resting on it never stops reflecting (the course's "
                    "program loops forever, FOSSSim stops at maxreflections)"
                  : ""));
      break;
    }
    keep_warnings(r);
    return settings;
  }

  /// The registry's rigid-body responses beyond the two the course's message names:
  /// "gr-lcp and gr-velocity-projection".
  /// The rigid-body methods the course's message leaves out: "gr-lcp and gr-velocity-projection".
  static std::string other_rigid_responses() {
    std::vector<std::string_view> names;
    for (const ContactMethod* method : contact_methods()) {
      if (method->scope.planar_rigid_bodies && !method->in_course_messages) {
        names.push_back(method->name);
      }
    }
    std::string out;
    for (std::size_t k = 0; k < names.size(); ++k) {
      if (k > 0) out += k + 1 == names.size() ? " and " : ", ";
      out += names[k];
    }
    return out;
  }

  static double signed_area(const std::vector<Vec2>& points) {
    double twice = 0.0;
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Vec2& a = points[k];
      const Vec2& b = points[(k + 1) % points.size()];
      twice += a.x() * b.y() - a.y() * b.x();
    }
    return 0.5 * twice;
  }

  void read_forces() {
    const ForceContext context{scene_.model, scene_.initial.q};
    for (const ForceKind& kind : force_kinds()) {
      if (kind.course_theme != 3) continue;
      const auto& declarations = all(groups_, kind.tag);
      for (int k = 0; k < static_cast<int>(declarations.size()); ++k) {
        ElementReader r = reader(*declarations[k], k);
        scene_.model.forces.push_back(kind.create(r, context));
        if (kind.tag == "rigidbodyspringforce")
          springs_.push_back(scene_.model.forces.back().get());
        keep_warnings(r);
      }
    }
    scene_.appearance.edge_color.assign(springs_.size(), Appearance::kDefaultEdgeColor);
  }

  void read_colors() {
    const auto& body_colors = all(groups_, "rigidbodycolor");
    for (int k = 0; k < static_cast<int>(body_colors.size()); ++k) {
      ElementReader r = reader(*body_colors[k], k);
      const int body = r.integer("body");
      if (body < 0 || body >= scene_.model.num_particles()) {
        r.fail("body", "refers to body " + std::to_string(body) + ", but the scene has " +
                           std::to_string(scene_.model.num_particles()) + " bodies");
      }
      scene_.appearance.particle_color[body] = r.color();
      keep_warnings(r);
    }
    const auto& spring_colors = all(groups_, "rigidbodyspringcolor");
    for (int k = 0; k < static_cast<int>(spring_colors.size()); ++k) {
      ElementReader r = reader(*spring_colors[k], k);
      const int spring = r.integer("spring");
      if (spring < 0 || spring >= static_cast<int>(springs_.size())) {
        r.fail("spring", "refers to spring " + std::to_string(spring) + ", but the scene has " +
                             std::to_string(springs_.size()) + " <rigidbodyspringforce> elements");
      }
      scene_.appearance.edge_color[spring] = r.color();
      keep_warnings(r);
    }
  }

  const ElementGroups& groups_;
  Scene& scene_;
  const std::string& file_;
  const Limits& limits_;
  std::vector<Vec2> positions_;
  std::vector<double> masses_;
  std::vector<const Force*> springs_;
};

}  // namespace

std::span<const std::string_view> rigid_body_element_names() { return kRigidBodyElements; }

bool is_rigid_body_element(std::string_view name) {
  for (std::string_view known : kRigidBodyElements) {
    if (name == known) return true;
  }
  return false;
}

bool is_rigid_body_scene(const ElementGroups& groups, const std::string& file) {
  const auto& simtypes = all(groups, "simtype");
  if (simtypes.empty()) return false;
  if (simtypes.size() > 1) {
    throw SceneError(file, simtypes[1]->line(), "<simtype>", "may appear only once");
  }
  ElementReader r(*simtypes[0], file, -1, 0, 0);
  const std::string type = r.text("type");
  if (type != "rigid-body" && type != "particle-system") {
    r.fail("type", "must be \"particle-system\" or \"rigid-body\", found \"" + type + "\"");
  }
  return type == "rigid-body";
}

void read_rigid_body_scene(const ElementGroups& groups, Scene& scene, const std::string& file,
                           const Limits& limits) {
  RigidBodySceneReader(groups, scene, file, limits).read();
}

std::string number_repeated_hull_attributes(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 64);
  std::size_t k = 0;
  while (k < text.size()) {
    const std::size_t open = text.find("<rigidbody", k);
    if (open == std::string_view::npos) break;
    const std::size_t after = open + 10;
    out.append(text.substr(k, after - k));
    k = after;
    if (after < text.size() && is_xml_name_char(text[after])) continue;  // <rigidbodyvertex ...
    // Inside the tag: count the attributes named "p" outside quotes.
    int count = 0;
    char quote = 0;
    while (k < text.size()) {
      const char c = text[k];
      if (quote != 0) {
        if (c == quote) quote = 0;
        out.push_back(c);
        ++k;
        continue;
      }
      if (c == '>') break;
      if (c == '"' || c == '\'') {
        quote = c;
        out.push_back(c);
        ++k;
        continue;
      }
      if (is_xml_name_char(c)) {
        std::size_t end = k;
        while (end < text.size() && is_xml_name_char(text[end])) ++end;
        std::size_t eq = end;
        while (eq < text.size() && std::isspace(static_cast<unsigned char>(text[eq]))) ++eq;
        const std::string_view name = text.substr(k, end - k);
        if (name == "p" && eq < text.size() && text[eq] == '=' && ++count > 1) {
          out += "p." + std::to_string(count);
        } else {
          out.append(name);
        }
        k = end;
        continue;
      }
      out.push_back(c);
      ++k;
    }
  }
  out.append(text.substr(k));
  return out;
}

}  // namespace fosssim
