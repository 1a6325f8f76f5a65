#include "io/collision_elements.h"

#include "io/xml_tree.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>

#include "core/collisions/contact_registry.h"
#include "core/text.h"
#include "io/element_reader.h"
#include "io/scene_error.h"
#include "io/text_lines.h"

namespace fosssim {

namespace {


constexpr std::array<std::string_view, 6> kElements = {
    "halfplane", "halfplanecolor", "sphere", "spherecolor", "collision", "collisiondetection"};

/// A contact method's options as attributes of its <collision> element. Every option of the
/// method is asked for, given or not, so that a misspelt one is named ("thicknes": did you mean
/// "thickness"?). A choice given as "" is read as not given (penalty-jacobian="" is the
/// course's "none"); an empty number is an error.
class CollisionAttributes final : public AttributeOptions {
 public:
  CollisionAttributes(ElementReader& reader, const ContactMethod& method)
      : AttributeOptions(reader), method_(method) {}
  bool has(std::string_view name) override {
    const std::string attribute(name);
    const std::string value = reader_.text_or_empty(attribute.c_str());  // asked for, given or not
    if (value.empty() && is_choice(name)) return false;
    return reader_.has(attribute.c_str());
  }

 private:
  bool is_choice(std::string_view name) const {
    for (const OptionSpec& option : method_.options) {
      if (option.name == name) return option.type == OptionSpec::Type::kChoice;
    }
    return false;
  }

  const ContactMethod& method_;
};

std::vector<const XmlElement*> children(const XmlElement& root, const char* name) {
  return root.children_named(name);
}

class CollisionReader {
 public:
  CollisionReader(Scene& scene, const std::string& file, const Limits& limits,
                  SceneErrorList& errors)
      : scene_(scene), file_(file), limits_(limits), errors_(errors) {}

  /// Reads every element, each in errors_.attempt(). The colours of half-planes (spheres) are
  /// read only when every half-plane (sphere) could be: the numbering of the others depends on
  /// it.
  void read(const XmlElement& root) {
    const auto half_planes = children(root, "halfplane");
    bool planes_read = true;
    for (int k = 0; k < static_cast<int>(half_planes.size()); ++k) {
      planes_read &= errors_.attempt([&] { read_half_plane(*half_planes[k], k); });
    }
    scene_.appearance.half_plane_color.assign(scene_.model.half_planes.size(),
                                              Appearance::kDefaultHalfPlaneColor);
    const auto colors = children(root, "halfplanecolor");
    for (int k = 0; planes_read && k < static_cast<int>(colors.size()); ++k) {
      errors_.attempt([&] { read_color(*colors[k], k); });
    }
    const auto spheres = children(root, "sphere");
    bool spheres_read = true;
    for (int k = 0; k < static_cast<int>(spheres.size()); ++k) {
      spheres_read &= errors_.attempt([&] { read_sphere(*spheres[k], k); });
    }
    scene_.appearance.sphere_color.assign(scene_.model.spheres.size(),
                                          Appearance::kDefaultSphereColor);
    const auto sphere_colors = children(root, "spherecolor");
    for (int k = 0; spheres_read && k < static_cast<int>(sphere_colors.size()); ++k) {
      errors_.attempt([&] { read_sphere_color(*sphere_colors[k], k); });
    }
    const auto collisions = children(root, "collision");
    if (!collisions.empty()) errors_.attempt([&] { read_collision(*collisions[0]); });
    for (std::size_t k = 1; k < collisions.size(); ++k) {
      ElementReader r = reader(*collisions[k], static_cast<int>(k));
      warn(r,
           "a second <collision> element is ignored, as the course ignores it (the first, "
           "at line " +
               std::to_string(collisions[0]->line()) + ", applies)");
      r.text_or_empty("type");  // its attributes are not reported one by one
      for (const ContactMethod* method : contact_methods()) {
        if (!method->scope.particles) continue;
        for (const OptionSpec& option : method->options) {
          r.text_or_empty(std::string(option.name).c_str());
        }
      }
    }
    const auto detections = children(root, "collisiondetection");
    if (detections.size() > 1) {
      errors_.add(SceneError(file_, detections[1]->line(), "<collisiondetection>",
                             "may appear only once (first at line " +
                                 std::to_string(detections[0]->line()) + ")"));
    }
    if (!detections.empty()) errors_.attempt([&] { read_detection(*detections[0]); });
  }

 private:
  ElementReader reader(const XmlElement& e, int index) {
    return ElementReader(e, file_, index, scene_.model.num_particles(),
                         static_cast<int>(scene_.model.edges.size()));
  }
  void warn(const ElementReader& r, const std::string& text) {
    scene_.warnings.push_back(r.warning(text));
  }
  void keep_warnings(const ElementReader& r) {
    for (auto& warning : r.finish()) scene_.warnings.push_back(warning);
  }

  void read_half_plane(const XmlElement& e, int index) {
    ElementReader r = reader(e, index);
    const int dim = scene_.model.dim;
    HalfPlane plane;
    plane.point.resize(dim);
    plane.normal.resize(dim);
    const std::array<const char*, 3> p = {"px", "py", "pz"}, n = {"nx", "ny", "nz"};
    for (int c = 0; c < dim; ++c) plane.point[c] = r.number(p[c]);
    for (int c = 0; c < dim; ++c) plane.normal[c] = r.number(n[c]);
    if (plane.normal.isZero(0.0)) {
      warn(r,
           "the normal is zero, so this half-plane never collides and exerts no force (the "
           "course accepts it silently)");
    }
    scene_.model.half_planes.push_back(std::move(plane));
    keep_warnings(r);
  }

  void read_color(const XmlElement& e, int index) {
    read_obstacle_color(e, index, "half-plane", scene_.appearance.half_plane_color);
  }

  /// <halfplanecolor> and <spherecolor>: i names an obstacle of `colors`, one per obstacle.
  void read_obstacle_color(const XmlElement& e, int index, const std::string& what,
                           std::vector<Color>& colors) {
    ElementReader r = reader(e, index);
    const int count = static_cast<int>(colors.size());
    const int i = r.integer("i");
    if (i < 0 || i >= count) {
      r.fail("i",
             "refers to " + what + " " + std::to_string(i) + ", but the scene has " +
                 (count == 0 ? "no " + what + "s"
                             : std::to_string(count) + " " + what + (count == 1 ? "" : "s") +
                                   " (valid indices are 0 to " + std::to_string(count - 1) + ")"));
    }
    colors[i] = r.color();
    keep_warnings(r);
  }

  void read_sphere(const XmlElement& e, int index) {
    ElementReader r = reader(e, index);
    if (scene_.model.dim != 3) {
      r.fail("spheres are obstacles of 3D scenes only (<scene dim=\"3\">)");
    }
    Sphere sphere;
    sphere.center = Vector(3);
    const std::array<const char*, 3> p = {"px", "py", "pz"};
    for (int c = 0; c < 3; ++c) sphere.center[c] = r.number(p[c]);
    sphere.radius = r.number("radius");
    if (!(sphere.radius > 0.0)) {
      r.fail("radius", "must be positive, found " + to_text(sphere.radius));
    }
    scene_.model.spheres.push_back(std::move(sphere));
    keep_warnings(r);
  }

  void read_sphere_color(const XmlElement& e, int index) {
    read_obstacle_color(e, index, "sphere", scene_.appearance.sphere_color);
  }

  /// <collision>: the method, its options (ContactMethod::options, read in their order), and
  /// the particle methods' settings taken from them, with warnings where the course accepts a
  /// value that is probably a mistake.
  void read_collision(const XmlElement& e) {
    ElementReader r = reader(e, -1);
    CollisionSettings& s = scene_.model.collisions;
    const std::string type = r.text("type");
    const ContactMethod* method = find_contact_method(type);
    if (method == nullptr) {
      const std::string_view meant = suggest_contact_method(type, BodyKind::kParticles);
      r.fail("type", "names an unknown collision handling " + quote(type.c_str()) + " (" +
                         (meant.empty() ? "" : "did you mean \"" + std::string(meant) + "\"? ") +
                         "expected one of " +
                         describe_contact_method_names(BodyKind::kParticles) +
                         "; exact spelling, lower case)");
    }
    if (!method->scope.handles(BodyKind::kParticles)) {  // before its options: none are ours
      r.fail("type", contact_method_refusal(*method, scene_.model));
    }
    s.use(*method);
    CollisionAttributes attributes(r, *method);
    s.options.read(attributes);
    take_particle_settings(r, s);
    if (const std::string refusal = contact_method_refusal(*method, scene_.model);
        !refusal.empty()) {
      r.fail("type", refusal);
    }
    keep_warnings(r);
  }

  /// Copies the options the particle methods share into their fields of `s`, warning about
  /// values the course accepts but that are probably mistakes.
  void take_particle_settings(ElementReader& r, CollisionSettings& s) {
    const OptionValues& o = s.options;
    if (o.has("COR")) {
      s.cor = o.number("COR");
      if (s.cor < 0.0 || s.cor > 1.0) {
        warn(r, "COR = " + to_text(s.cor) + " is outside [0, 1]: collisions will " +
                    (s.cor > 1.0 ? "add energy" : "not separate the objects") +
                    " (the course accepts it)");
      }
    }
    if (o.has("k")) {
      s.stiffness = o.number("k");
      if (s.stiffness < 0.0) {
        warn(r, "k = " + to_text(s.stiffness) +
                    " is negative: the penalty force pulls objects "
                    "together (the course accepts it)");
      }
    }
    if (o.has("thickness")) {
      s.thickness = o.number("thickness");
      if (s.thickness < 0.0) {
        warn(r, "thickness = " + to_text(s.thickness) +
                    " is negative: objects may overlap before the penalty force acts (the "
                    "course accepts it)");
      }
    }
    if (o.has("penalty-jacobian")) {
      s.penalty_jacobian = o.choice("penalty-jacobian") == "exact" ? PenaltyJacobian::kExact
                                                                   : PenaltyJacobian::kNone;
    }
    if (o.has("maxiters")) {
      const double iterations = o.number("maxiters");
      const double whole = std::trunc(iterations);
      if (whole != iterations || iterations < 0.0) {
        warn(r, "maxiters = " + to_text(iterations) + " is read as " +
                    to_text(std::max(whole, 0.0)) +
                    (iterations < 1.0 ? " impulse passes (straight to the geometric stage)"
                                      : " impulse passes") +
                    ", as the course reads it");
      }
      double passes = whole;
      // Each pass tests (and logs the polynomials of) every pair, so a huge maxiters on a
      // jammed scene would loop and grow the step's log for hours (docs/limits-and-failures.md).
      const double most = static_cast<double>(limits_.max_hybrid_passes);
      if (!(whole <= most)) {  // a NaN too
        const std::string limit = std::to_string(limits_.max_hybrid_passes);
        warn(r, "maxiters = " + to_text(iterations) + " is more than the limit of " + limit +
                    " impulse passes a step; " + limit +
                    " are made (raise it with --max-hybrid-passes N; "
                    "docs/limits-and-failures.md, \"Hybrid passes\")");
        passes = most;
      }
      s.max_iterations = static_cast<int>(std::max(passes, -1.0));
    }
  }

  void read_detection(const XmlElement& e) {
    ElementReader r = reader(e, -1);
    const std::string type = r.text("type");
    CollisionSettings& s = scene_.model.collisions;
    if (type == "allpairs") {
      s.detection = PairDetection::kAllPairs;
    } else if (type == "contest") {
      s.detection = PairDetection::kContest;
      // The course's contest detection makes no polynomials, so its program refuses the methods
      // that record them.
      if (s.method->records == StepRecordLayout::kCollisionsAndPolynomials) {
        warn(r, "the course's program refuses \"contest\" detection with " +
                    std::string(s.method->name) +
                    " handling; FOSSSim runs it (its pair detection serves every method)");
      }
    } else {
      r.fail("type", "must be \"allpairs\" or \"contest\", found " + quote(type.c_str()));
    }
    keep_warnings(r);
  }

  Scene& scene_;
  const std::string& file_;
  const Limits& limits_;
  SceneErrorList& errors_;
};

bool is_name_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_' || c == ':';
}

}  // namespace

bool is_collision_element(std::string_view name) {
  for (std::string_view known : kElements) {
    if (name == known) return true;
  }
  return false;
}

std::span<const std::string_view> collision_element_names() { return kElements; }

void read_collision_elements(const XmlElement& root, Scene& scene, const std::string& file,
                             const Limits& limits, SceneErrorList& errors) {
  CollisionReader(scene, file, limits, errors).read(root);
}

std::string separate_run_together_attributes(std::string text, const std::string& file,
                                             std::vector<std::string>& warnings) {
  // One pass finds where a blank is missing; the text is copied once, with the blanks added.
  std::vector<std::size_t> missing;  // offsets after which a blank goes
  int line = 1;
  bool in_tag = false;
  char quote_char = 0;  // the quote of the attribute value we are in, or 0
  for (std::size_t k = 0; k < text.size(); ++k) {
    const char c = text[k];
    if (c == '\n') {
      ++line;
    } else if (quote_char != 0) {
      if (c == quote_char) {
        quote_char = 0;
        if (k + 1 < text.size() && is_name_start(text[k + 1])) {
          missing.push_back(k + 1);
          warnings.push_back(file + ":" + std::to_string(line) +
                             ": warning: two attributes without a blank between them (such as "
                             "vx=\"0\"vy=\"0\"), read as if separated, as the course reads them");
        }
      }
    } else if (in_tag) {
      if (c == '"' || c == '\'') quote_char = c;
      if (c == '>') in_tag = false;
    } else if (c == '<') {
      if (text.compare(k, 4, "<!--") == 0) {  // a comment: skip it whole
        const std::size_t end = text.find("-->", k + 4);
        const std::size_t stop = end == std::string_view::npos ? text.size() : end + 3;
        line += static_cast<int>(std::count(text.begin() + k, text.begin() + stop, '\n'));
        k = stop - 1;
        continue;
      }
      in_tag = true;
    }
  }
  if (missing.empty()) return text;
  const std::string_view whole = text;
  std::string out;
  out.reserve(text.size() + missing.size());
  std::size_t from = 0;
  for (const std::size_t at : missing) {
    out.append(whole.substr(from, at - from));
    out.push_back(' ');
    from = at;
  }
  out.append(whole.substr(from));
  return out;
}

}  // namespace fosssim
