#include "io/json_scene_reader.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/forces/constant_force.h"
#include "core/integrators/integrator_registry.h"
#include "core/text.h"
#include "io/mesh_reference.h"
#include "io/obj_reader.h"
#include "io/text_lines.h"
#include "mesh/load_check.h"
#include "mesh/mesh_scene.h"

namespace fosssim {

namespace {

using nlohmann::json;

/// The 1-based line of byte `offset` of `text`.
int line_of(std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  return 1 +
         static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(offset), '\n'));
}

class JsonSceneParser;

/// The integrator options a JSON scene may set, as its top-level keys: "iterations" and
/// "start"; the others are fixed by the format (JsonSceneDefaults).
class KeyOptions final : public OptionSource {
 public:
  KeyOptions(JsonSceneParser& parser, const json& root) : parser_(parser), root_(root) {}
  bool has(std::string_view name) override {
    return (name == "iterations" || name == "start") && root_.contains(std::string(name));
  }
  double number(std::string_view name) override;
  std::string text(std::string_view name) override {
    const json& value = root_.at(std::string(name));
    return value.is_string() ? value.get<std::string>() : value.dump();
  }
  [[noreturn]] void fail(std::string_view name, const std::string& problem) override;

 private:
  JsonSceneParser& parser_;
  const json& root_;
};

class JsonSceneParser {
 public:
  JsonSceneParser(const std::string& name, InputFiles& files) : name_(name), files_(files) {}

  Scene parse(const json& root) {
    if (!root.is_object())
      fail("the file must hold a JSON object such as {\"obj\": \"cloth.obj\", \"k\": 1000}");
    for (const auto& [key, value] : root.items()) {
      if (key != "obj" && key != "k" && key != "b" && key != "m" && key != "h" &&
          key != "iterations" && key != "start" && key != "duration") {
        scene_.warnings.push_back(name_ + ": warning: unknown key \"" + key + "\" ignored");
      }
    }
    SceneModel& model = scene_.model;
    scene_.source = name_;
    model.dim = 3;
    model.mass.resize(0);
    scene_.initial.q.resize(0);
    scene_.initial.v.resize(0);
    model.integrator.use(integrator_method("local-global"));
    model.integrator.dt = positive(root, "h", JsonSceneDefaults::kTimeStep);
    model.integrator.options.set("iterations", JsonSceneDefaults::kIterations);
    model.integrator.options.set("start", JsonSceneDefaults::kStart);
    model.integrator.options.set("pins", "penalty");
    model.integrator.options.set("penalty", JsonSceneDefaults::kPenalty);
    KeyOptions options(*this, root);
    model.integrator.options.read(options);
    model.duration = non_negative(root, "duration", JsonSceneDefaults::kDuration);

    const Mesh mesh = read_mesh(root);
    MeshMaterial material;
    material.k = non_negative(root, "k", -1.0);
    material.mass = root.contains("m")
                        ? MassRule{MassRule::kUniform, positive(root, "m", 0.0)}
                        : MassRule{MassRule::kVoronoi, JsonSceneDefaults::kAreaDensity};
    std::unique_ptr<Force> springs;
    try {
      springs = append_mesh(scene_, mesh, material, pinned(root, mesh.num_vertices()), "obj mesh");
    } catch (const Error& error) {
      fail(error.what());
    }
    model.forces.push_back(std::move(springs));
    model.forces.push_back(
        std::make_unique<ConstantForce<3>>(Vec<3>(0.0, JsonSceneDefaults::kGravity, 0.0)));
    warn_if_overloaded(mesh, material.k);
    return std::move(scene_);
  }

 private:
  friend class KeyOptions;

  /// A warning when the load on every vertex is far beyond what the springs hold: a column of
  /// them hanging from a pin would stretch by more than the mesh's size (mesh/load_check.h).
  void warn_if_overloaded(const Mesh& mesh, double k) {
    const HangingStretch column = hanging_stretch(mesh, k, -JsonSceneDefaults::kGravity);
    if (!column.overloaded()) return;
    scene_.warnings.push_back(
        name_ + ": warning: \"k\": springs of " + to_text(k) + " N/m do not hold the load of " +
        to_text(-JsonSceneDefaults::kGravity) + " N on every vertex: a column of " +
        std::to_string(column.springs) + " springs across the mesh, hanging from a pin, would " +
        "stretch by about " + to_text(std::round(column.stretch * 100.0) / 100.0) +
        " m, against a mesh of " + to_text(std::round(column.size * 100.0) / 100.0) + " m (k of " +
        to_text(std::ceil(column.stiffness_needed)) + " N/m or more holds it; docs/scenes-3d.md)");
  }

  [[noreturn]] void fail(const std::string& problem) const {
    throw SceneError(name_, 0, "", problem);
  }

  /// A number under `key`; fallback < 0 marks it required.
  double number(const json& root, const char* key, double fallback) {
    if (!root.contains(key)) {
      if (fallback < 0.0) fail(std::string("the required key \"") + key + "\" is missing");
      return fallback;
    }
    const json& value = root.at(key);
    if (!value.is_number())
      fail(std::string("\"") + key + "\" must be a number, found " + value.dump());
    const double x = value.get<double>();
    if (!std::isfinite(x))
      fail(std::string("\"") + key + "\" must be finite, found " + value.dump());
    return x;
  }

  double non_negative(const json& root, const char* key, double fallback) {
    const double x = number(root, key, fallback);
    if (x < 0.0) fail(std::string("\"") + key + "\" must not be negative, found " + to_text(x));
    return x;
  }

  double positive(const json& root, const char* key, double fallback) {
    const double x = number(root, key, fallback);
    if (!(x > 0.0)) fail(std::string("\"") + key + "\" must be positive, found " + to_text(x));
    return x;
  }

  Mesh read_mesh(const json& root) {
    if (!root.contains("obj")) fail("the required key \"obj\" (the OBJ mesh file) is missing");
    if (!root.at("obj").is_string())
      fail("\"obj\" must be a file name, found " + root.at("obj").dump());
    const std::string obj = root.at("obj").get<std::string>();
    // A "\u0000" in the name would cut it short where the system reads it.
    if (obj.find('\0') != std::string::npos)
      fail("\"obj\" must be a file name, found one holding a NUL character: " +
           root.at("obj").dump());
    const std::int64_t corners = files_.limits().max_face_corners;
    Mesh mesh = read_referenced_mesh(
        files_, name_, obj,
        [corners](std::string_view text, const std::string& name) {
          return read_obj_text(text, name, corners);
        },
        "the \"obj\" of " + name_);
    if (mesh.num_vertices() > files_.limits().max_particles) {
      fail("the \"obj\" mesh has " + std::to_string(mesh.num_vertices()) + " vertices, " +
           over_limit(files_.limits().max_particles, "particles", "--max-particles"));
    }
    return mesh;
  }

  /// The 0-based vertices of the 1-based list "b".
  std::vector<int> pinned(const json& root, int num_vertices) {
    std::vector<int> out;
    if (!root.contains("b")) return out;
    const json& list = root.at("b");
    if (!list.is_array())
      fail("\"b\" must be a list of 1-based vertex numbers, found " + list.dump());
    for (std::size_t k = 0; k < list.size(); ++k) {
      const json& entry = list[k];
      const bool valid = entry.is_number_integer() && entry.get<long long>() >= 1 &&
                         entry.get<long long>() <= num_vertices;
      if (!valid) {
        fail("\"b\"[" + std::to_string(k) + "] must be a vertex number from 1 to " +
             std::to_string(num_vertices) + " (1-based), found " + entry.dump());
      }
      out.push_back(entry.get<int>() - 1);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  const std::string& name_;
  InputFiles& files_;
  Scene scene_;
};

double KeyOptions::number(std::string_view name) {
  const json& value = root_.at(std::string(name));
  if (!value.is_number()) fail(name, "must be a number, found " + value.dump());
  const double x = value.get<double>();
  if (!std::isfinite(x)) fail(name, "must be finite, found " + value.dump());
  return x;
}

void KeyOptions::fail(std::string_view name, const std::string& problem) {
  parser_.fail("\"" + std::string(name) + "\" " + problem);
}

}  // namespace

Scene load_json_scene_text(std::string_view text, const std::string& name, InputFiles& files) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    throw SceneError(name, 0, "", "the file is empty (expected a JSON object)");
  }
  json root;
  try {
    root = json::parse(text.begin(), text.end());
  } catch (const json::parse_error& error) {
    std::string what = error.what();
    if (const auto colon = what.find("syntax error"); colon != std::string::npos)
      what = what.substr(colon);
    throw SceneError(name, line_of(text, error.byte == 0 ? 0 : error.byte - 1), "",
                     "not valid JSON: " + what);
  } catch (const json::exception& error) {
    // A number beyond the range of a double ("number overflow parsing '1e400'"), or any other
    // reason nlohmann::json gives; it names the offending text, not its line.
    std::string what = error.what();
    if (const auto bracket = what.find("] "); bracket != std::string::npos)
      what = what.substr(bracket + 2);
    throw SceneError(name, 0, "", "not valid JSON: " + what);
  }
  Scene scene = JsonSceneParser(name, files).parse(root);
  scene.files = files.paths();
  return scene;
}

Scene load_json_scene_text(std::string_view text, const std::string& name) {
  InputFiles files;
  return load_json_scene_text(text, name, files);
}

Scene load_json_scene_file(const std::string& path, InputFiles& files) {
  return load_json_scene_text(files.read(path), path, files);
}

Scene load_json_scene_file(const std::string& path) {
  InputFiles files;
  return load_json_scene_file(path, files);
}

}  // namespace fosssim
