#include "io/elastic_body_element.h"

#include <algorithm>
#include <filesystem>
#include <set>
#include <vector>

#include "core/force_registry.h"
#include "core/text.h"
#include "io/element_reader.h"
#include "io/obj_reader.h"
#include "io/scene_error.h"
#include "io/text_lines.h"
#include "io/xml_tree.h"
#include "mesh/elastic_body.h"

namespace fosssim {

namespace {

/// A required integer of at least `minimum`.
int integer_at_least(ElementReader& r, const char* name, int minimum) {
  const int value = r.integer(name);
  if (value < minimum)
    r.fail(name,
           "must be at least " + std::to_string(minimum) + ", found " + std::to_string(value));
  return value;
}

/// True when the element has the optional attribute `name`, which is remembered as one this
/// element may have (so that a misspelling of it is reported).
bool present(ElementReader& r, const char* name) {
  r.text_or_empty(name);
  return r.has(name);
}

/// An optional positive number.
double positive_or(ElementReader& r, const char* name, double fallback) {
  return present(r, name) ? r.positive(name) : fallback;
}

/// The numbers of `text`, separated by blanks or commas; `fail` gets a word that is not one.
template <typename Fail>
std::vector<double> numbers_of(std::string spaced, Fail&& fail) {
  std::replace(spaced.begin(), spaced.end(), ',', ' ');
  std::vector<double> values;
  for (std::string_view word : split_line(spaced)) {
    double value = 0.0;
    if (!parse_finite(word, value)) fail("must be numbers, found " + quote(word));
    values.push_back(value);
  }
  return values;
}

/// The numbers of a list attribute, separated by blanks or commas.
std::vector<double> number_list(ElementReader& r, const char* name) {
  return numbers_of(r.text(name), [&](const std::string& problem) { r.fail(name, problem); });
}

/// The words of `text` (separated by blanks or commas), counted in one pass that allocates
/// nothing.
std::int64_t count_words(std::string_view text) {
  std::int64_t words = 0;
  bool in_word = false;
  for (const char c : text) {
    const bool separator = c == ',' || c == ' ' || c == '\t' || c == '\n' || c == '\r';
    if (!separator && !in_word) ++words;
    in_word = !separator;
  }
  return words;
}

/// x y pairs as points; `fail` gets an odd count.
template <typename Fail>
std::vector<Eigen::Vector2d> pairs_of(const std::vector<double>& values, Fail&& fail) {
  if (values.size() % 2 != 0)
    fail("must hold x y pairs, found " + std::to_string(values.size()) + " numbers");
  std::vector<Eigen::Vector2d> corners;
  for (std::size_t k = 0; k + 1 < values.size(); k += 2)
    corners.emplace_back(values[k], values[k + 1]);
  return corners;
}

/// The polygon's corners from points="x0 y0 x1 y1 ...".
std::vector<Eigen::Vector2d> read_corners(ElementReader& r, std::int64_t max_corners) {
  // Count the words before converting them.
  const std::int64_t corners = (count_words(r.text("points")) + 1) / 2;
  if (corners > max_corners) {
    r.fail("points", "holds " + std::to_string(corners) + " corners, " +
                         over_limit(max_corners, "corners", "--max-polygon-corners"));
  }
  return pairs_of(number_list(r, "points"),
                  [&](const std::string& problem) { r.fail("points", problem); });
}

/// The polygon's holes from holes="x0 y0 x1 y1 ...; x0 y0 ...": one list of corners per hole,
/// separated by ';'. `outline_corners` counts towards max_corners.
std::vector<std::vector<Eigen::Vector2d>> read_holes(ElementReader& r, std::size_t outline_corners,
                                                     std::int64_t max_corners) {
  const std::string text = r.text("holes");
  std::vector<std::string_view> parts;
  for (std::size_t start = 0;;) {
    const std::size_t end = text.find(';', start);
    parts.push_back(std::string_view(text).substr(start, end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  auto corners = static_cast<std::int64_t>(outline_corners);
  for (const std::string_view part : parts) corners += (count_words(part) + 1) / 2;
  if (corners > max_corners) {
    r.fail("holes", "brings the polygon to " + std::to_string(corners) + " corners, " +
                        over_limit(max_corners, "corners", "--max-polygon-corners"));
  }
  std::vector<std::vector<Eigen::Vector2d>> holes;
  for (std::size_t h = 0; h < parts.size(); ++h) {
    const auto fail = [&](const std::string& problem) {
      r.fail("holes", "(hole " + std::to_string(h) + ") " + problem);
    };
    if (count_words(parts[h]) == 0) fail("is empty: holes are lists of x y pairs separated by ';'");
    holes.push_back(pairs_of(numbers_of(std::string(parts[h]), fail), fail));
  }
  return holes;
}

/// The body's shape from the attributes of its kind.
ElasticShape read_shape(ElementReader& r, const std::string& shape, const std::string& file,
                        InputFiles& files, std::int64_t max_vertices) {
  try {
    if (shape == "sheet") {
      const std::string pattern = present(r, "diagonals") ? r.text("diagonals") : "alternating";
      if (pattern != "alternating" && pattern != "parallel")
        r.fail("diagonals", "must be \"alternating\" or \"parallel\", found \"" + pattern + "\"");
      return make_sheet(
          integer_at_least(r, "nx", 1), integer_at_least(r, "ny", 1), positive_or(r, "width", 1.0),
          positive_or(r, "height", 1.0),
          pattern == "parallel" ? SheetDiagonals::kParallel : SheetDiagonals::kAlternating,
          max_vertices);
    }
    if (shape == "rod") {
      return make_rod(integer_at_least(r, "segments", 1), positive_or(r, "length", 1.0),
                      max_vertices);
    }
    if (shape == "ring") {
      const int segments = integer_at_least(r, "segments", 3);
      const double radius = positive_or(r, "radius", 1.0);
      if (!present(r, "innerradius")) return make_ring_rod(segments, radius, max_vertices);
      const double inner = r.positive("innerradius");
      if (!(inner < radius)) {
        r.fail("innerradius",
               "must be less than radius (" + to_text(radius) + "), found " + to_text(inner));
      }
      const int layers = present(r, "layers") ? integer_at_least(r, "layers", 1) : 1;
      return make_annulus(segments, layers, inner, radius, max_vertices);
    }
    if (shape == "polygon") {
      const std::int64_t max_corners = files.limits().max_polygon_corners;
      const auto corners = read_corners(r, max_corners);
      const auto holes = present(r, "holes") ? read_holes(r, corners.size(), max_corners)
                                             : std::vector<std::vector<Eigen::Vector2d>>{};
      return make_polygon(corners, holes, positive_or(r, "spacing", 0.0), max_vertices,
                          max_corners);
    }
    if (shape == "obj") {
      std::filesystem::path path(r.text("file"));
      if (path.is_relative()) path = std::filesystem::path(file).parent_path() / path;
      return read_elastic_obj(path.string(), files,
                              "the mesh of " + file + ":" + std::to_string(r.line()));
    }
  } catch (const SceneError&) {
    throw;
  } catch (const Error& error) {
    r.fail(error.what());
  }
  r.fail("shape",
         "names an unknown shape \"" + shape + "\" (expected sheet, rod, ring, polygon or obj)");
}

/// The material, checked against the shape: triangles take youngsmodulus and poissonratio (and
/// stretch, for springs on their edges), rods take stretch and bend.
ElasticMaterial read_material(ElementReader& r, const ElasticShape& shape) {
  ElasticMaterial material;
  if (present(r, "stretch")) material.stretch = r.non_negative("stretch");
  if (shape.is_rod()) {
    for (const char* name : {"youngsmodulus", "poissonratio"}) {
      if (present(r, name))
        r.fail(name, "applies to bodies of triangles, not to a rod or a ring rod");
    }
    if (!material.stretch) r.fail("a rod needs stretch (alpha of the springs along it)");
    if (present(r, "bend")) material.bend = r.non_negative("bend");
    return material;
  }
  if (present(r, "bend")) {
    r.fail("bend",
           "applies to rods and ring rods (a ring without innerradius), not to a body "
           "of triangles");
  }
  material.youngs_modulus = r.number("youngsmodulus");
  material.poisson_ratio = r.number("poissonratio");
  return material;
}

ElasticMass read_mass(ElementReader& r) {
  const bool per_particle = present(r, "m"), total = present(r, "totalmass");
  if (per_particle == total) {
    r.fail(per_particle
               ? "give either m (every particle's mass) or totalmass (the body's), not both"
               : "the mass is missing: give m (every particle's mass) or totalmass "
                 "(the body's, shared by area or length)");
  }
  if (per_particle) return {ElasticMass::kPerParticle, r.positive("m")};
  return {ElasticMass::kTotal, r.positive("totalmass")};
}

ElasticFixing read_fixing(ElementReader& r, const ElasticShape& shape) {
  ElasticFixing fixing;
  const std::string side = present(r, "fix") ? r.text("fix") : "none";
  if (side == "left")
    fixing.side = ShapeSide::kLeft;
  else if (side == "right")
    fixing.side = ShapeSide::kRight;
  else if (side == "bottom")
    fixing.side = ShapeSide::kBottom;
  else if (side == "top")
    fixing.side = ShapeSide::kTop;
  else if (side != "none")
    r.fail("fix", "must be left, right, bottom, top or none, found \"" + side + "\"");
  if (present(r, "fixed")) {
    for (const double value : number_list(r, "fixed")) {
      if (value != std::floor(value) || value < 0.0 || value >= shape.num_vertices()) {
        r.fail("fixed", "refers to vertex " + to_text(value) + ", but the body has " +
                            std::to_string(shape.num_vertices()) + " vertices (0-based)");
      }
      fixing.vertices.push_back(static_cast<int>(value));
    }
  }
  return fixing;
}

/// A generated force declaration as the ForceParameters its factory reads: a problem with a
/// material parameter is reported on the element's attribute that gave it.
class DeclaredParameters final : public ForceParameters {
 public:
  DeclaredParameters(std::string_view tag, std::span<const DeclaredValue> values,
                     ElementReader& element, std::set<std::string>& warned)
      : tag_(tag), values_(values), element_(element), warned_(warned) {}

  double number(const char* name) override {
    for (const DeclaredValue& v : values_) {
      if (std::string_view(v.name) == name) return v.value;
    }
    fail(name, "is missing");  // not reached: the declarations hold what the factories read
  }
  double number_or(const char* name, double fallback) override {
    for (const DeclaredValue& v : values_) {
      if (std::string_view(v.name) == name) return v.value;
    }
    return fallback;
  }
  int particle_index(const char* name) override { return static_cast<int>(number(name)); }
  int edge_index(const char* name) override { fail(name, "is not generated"); }
  [[noreturn]] void fail(const std::string& problem) override {
    element_.fail("its " + std::string(tag_) + " " + describe() + ": " + problem);
  }
  [[noreturn]] void fail(const char* name, const std::string& problem) override {
    const std::string_view n(name);
    if (n == "youngsmodulus" || n == "poissonratio") element_.fail(name, problem);
    if (n == "alpha") element_.fail(tag_ == "elasticbodyspringforce" ? "stretch" : "bend", problem);
    fail(std::string(name) + " " + problem);
  }
  void warn(const std::string& problem) override {
    if (warned_.insert(problem).second) element_.warn(problem);
  }

 private:
  /// "(3, 4, 8)": the particles of the declaration.
  std::string describe() const {
    std::string out;
    for (const DeclaredValue& v : values_) {
      if (v.is_index) out += (out.empty() ? "(" : ", ") + std::to_string(static_cast<int>(v.value));
    }
    return out + ")";
  }

  std::string_view tag_;
  std::span<const DeclaredValue> values_;
  ElementReader& element_;
  std::set<std::string>& warned_;
};

/// The body an <elasticbody> describes, its vertices to become particles first, first + 1, ...
ElasticBodyDescription read_description(ElementReader& r, const std::string& file,
                                        InputFiles& files, int first) {
  const std::int64_t max_particles = files.limits().max_particles;
  ElasticBodyDescription body;
  const std::string shape_name = r.text("shape");
  body.shape = read_shape(r, shape_name, file, files, max_particles);
  const ElasticShape& shape = body.shape;
  if (std::int64_t{first} + shape.num_vertices() > max_particles) {
    r.fail("its " + std::to_string(shape.num_vertices()) + " vertices bring the scene to " +
           std::to_string(std::int64_t{first} + shape.num_vertices()) + " particles, " +
           over_limit(max_particles, "particles", "--max-particles"));
  }
  body.material = read_material(r, shape);
  const ElasticMass mass = read_mass(r);
  const ElasticFixing fixing = read_fixing(r, shape);
  ElasticPlacement placement;
  placement.origin = {r.number_or("x", 0.0), r.number_or("y", 0.0)};
  placement.rotation_degrees = r.number_or("rotation", 0.0);
  placement.velocity = {r.number_or("vx", 0.0), r.number_or("vy", 0.0)};
  body.radius = r.non_negative_or("particleradius", SceneModel::kDefaultParticleRadius);
  body.edge_radius = r.non_negative_or("edgeradius", SceneModel::kDefaultEdgeRadius);
  try {
    body.particles = make_elastic_particles(shape, placement, mass, fixing);
  } catch (const Error& error) {
    r.fail(error.what());
  }
  for (const auto& x : body.particles.positions) {
    if (!x.allFinite()) r.fail("the placed body has a vertex beyond the range of a double");
  }
  return body;
}

/// Reads one <elasticbody> and, when it is sound, adds it to the scene and its forces to
/// `forces`. The scene is left unchanged when the element has a problem.
void read_elastic_body(const XmlElement& e, int index, Scene& scene, const std::string& file,
                       InputFiles& files, ForcesByTag& forces) {
  SceneModel& model = scene.model;
  ElementReader r(e, file, index, model.num_particles(), static_cast<int>(model.edges.size()));
  if (model.dim != 2) r.fail("an elastic body is planar: it belongs to 2D scenes");
  const int first = model.num_particles();
  const ElasticBodyDescription body = read_description(r, file, files, first);
  const ElasticShape& shape = body.shape;
  const ElasticParticles& particles = body.particles;
  const int n = shape.num_vertices();

  // The forces, made by the registry's factories from the body's initial positions.
  Vector q(2 * (first + n));
  q.head(2 * first) = scene.initial.q;
  for (int v = 0; v < n; ++v) q.segment<2>(2 * (first + v)) = particles.positions[v];
  SceneModel extended;  // what a factory may consult: the dimension and the particle count
  extended.dim = 2;
  extended.mass.setOnes(2 * (first + n));
  extended.fixed.assign(first + n, false);
  const ForceContext context{extended, q};
  ForcesByTag made;
  std::set<std::string> warned;
  int theme = scene.grading_theme;
  declare_elastic_forces(shape, particles.positions, body.material, first,
                         [&](std::string_view tag, std::span<const DeclaredValue> values) {
                           DeclaredParameters params(tag, values, r, warned);
                           const ForceKind* kind = find_force_kind(tag);
                           made[std::string(tag)].push_back(kind->create(params, context));
                           theme = std::max(theme, kind->course_theme);
                         });
  std::vector<std::string> warnings = r.finish();

  // Particles, edges, then the forces.
  const int total = first + n;
  model.mass.conservativeResize(2 * total);
  scene.initial.q = q;
  scene.initial.v.conservativeResize(2 * total);
  model.fixed.resize(total, false);
  for (int v = 0; v < n; ++v) {
    const int p = first + v;
    model.mass.segment<2>(2 * p).setConstant(particles.masses[v]);
    model.fixed[p] = particles.fixed[v] != 0;
    scene.initial.v.segment<2>(2 * p) =
        model.fixed[p] ? Eigen::Vector2d::Zero().eval() : particles.velocity;
  }
  model.particle_radius.resize(total, body.radius);
  scene.appearance.particle_color.resize(total, Appearance::kDefaultParticleColor);
  scene.particle_tags.resize(total);
  for (const auto& [a, b] : shape.edges) {
    model.edges.push_back({first + a, first + b});
    model.edge_radius.push_back(body.edge_radius);
    scene.appearance.edge_color.push_back(Appearance::kDefaultEdgeColor);
    if (!model.edge_collides.empty()) model.edge_collides.push_back(true);
  }
  for (auto& [tag, list] : made) {
    auto& group = forces[tag];
    for (auto& force : list) group.push_back(std::move(force));
  }
  scene.grading_theme = theme;
  for (auto& warning : warnings) scene.warnings.push_back(std::move(warning));
}

}  // namespace

ElasticShape read_elastic_obj(const std::string& name, InputFiles& files,
                              const std::string& context) {
  ObjLines lines;
  Mesh mesh;
  try {
    mesh = read_obj_text(files.read(name), name, files.limits().max_face_corners, true, &lines);
  } catch (const SceneError& e) {
    throw SceneError(e.file(), e.line(), e.element(), e.problem() + " (" + context + ")");
  }
  const auto fail = [&](int line, const std::string& problem) {
    throw SceneError(name, line, "", problem + " (" + context + ")");
  };
  const std::int64_t limit = files.limits().max_particles;
  if (mesh.num_vertices() > limit) {
    fail(0, "the file has " + std::to_string(mesh.num_vertices()) + " vertices, " +
                over_limit(limit, "particles", "--max-particles"));
  }
  std::vector<Eigen::Vector2d> vertices;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (mesh.vertices[v].z() != 0.0) {
      fail(lines.vertices[v], "vertex " + std::to_string(v + 1) +
                                  " has z = " + to_text(mesh.vertices[v].z()) +
                                  ": an elastic body is planar (z must be 0 or absent)");
    }
    vertices.push_back(mesh.vertices[v].head<2>());
  }
  if (!mesh.segments.empty()) {
    fail(lines.segments[0],
         "a polyline or a face of 2 corners: an elastic body's mesh holds triangles only");
  }
  if (mesh.faces.empty()) fail(0, "the file has no faces: an elastic body needs triangles");
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> first_use(vertices.size(), -1);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& face = mesh.faces[f];
    if (face.size() != 3) {
      fail(lines.faces[f], "a face of " + std::to_string(face.size()) +
                               " corners: an elastic body's mesh holds triangles only");
    }
    if (orientation(vertices[face[0]], vertices[face[1]], vertices[face[2]]) == 0.0)
      fail(lines.faces[f], "the triangle has zero area (its corners are collinear)");
    triangles.push_back({face[0], face[1], face[2]});
  }
  std::vector<char> used(vertices.size(), 0);
  for (const auto& t : triangles)
    for (const int v : t) used[v] = 1;
  for (std::size_t v = 0; v < used.size(); ++v) {
    if (!used[v]) {
      fail(lines.vertices[v], "vertex " + std::to_string(v + 1) +
                                  " is on no triangle: it would have no mass and no force");
    }
  }
  return make_triangle_shape(std::move(vertices), triangles);
}

ForcesByTag read_elastic_bodies(const XmlElement& root, Scene& scene, const std::string& file,
                                InputFiles& files, SceneErrorList& errors) {
  ForcesByTag forces;
  int index = 0;
  for (const XmlElement* e : root.children_named(kElasticBodyElement)) {
    const int k = index++;
    errors.attempt([&] { read_elastic_body(*e, k, scene, file, files, forces); });
  }
  return forces;
}

ElasticBodyText read_elastic_body_text(std::string_view element, const std::string& name,
                                       InputFiles& files) {
  XmlDocument parsed;
  try {
    parsed = parse_xml(element, name);
  } catch (const SceneError&) {
    parsed = XmlDocument();  // a syntax error: the message below says what is expected
  }
  if (parsed.empty() || parsed.front().name() != kElasticBodyElement) {
    throw SceneError(name, 0, "", "not one <elasticbody .../> element");
  }
  ElementReader r(parsed.front(), name, -1, 0, 0);
  ElasticBodyText out;
  out.body = read_description(r, name, files, 0);
  out.warnings = r.finish();
  return out;
}

}  // namespace fosssim
