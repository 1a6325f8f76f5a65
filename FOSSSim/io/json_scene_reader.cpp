#include "io/json_scene_reader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <nlohmann/json.hpp>

#include "core/forces/constant_force.h"
#include "core/integrators/integrator_registry.h"
#include "core/text.h"
#include "io/element_reader.h"
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

/// The keys a JSON scene knows: the assignment's and our optional ones.
constexpr std::array<std::string_view, 8> kKnownKeys = {"obj", "k",          "b",     "m",
                                                        "h",   "iterations", "start", "duration"};

/// Where the root object, its keys and the entries of its arrays are in the text, as lines, for
/// messages (nlohmann::json keeps no positions). The text is valid JSON (parsed before), so a
/// plain scan suffices: strings are skipped with their escapes, and depth counts brackets.
struct JsonLines {
  int object = 1;                                     ///< the line of the root's '{'
  std::map<std::string, int, std::less<>> keys;       ///< a key's line (the last, if repeated)
  std::map<std::string, std::vector<int>, std::less<>> entries;  ///< an array's entries' lines

  explicit JsonLines(std::string_view text) {
    int depth = 0;
    std::string key;       // the root key whose value is being scanned
    bool expect_key = false;
    bool expect_entry = false;  // at depth 2, inside a root key's array, before an entry
    int line = 1;
    for (std::size_t i = 0; i < text.size(); ++i) {
      const char c = text[i];
      if (c == '\n') {
        ++line;
        continue;
      }
      if (c == ' ' || c == '\t' || c == '\r') continue;
      if (depth == 2 && expect_entry && c != ']') {
        entries[key].push_back(line);
        expect_entry = false;
      }
      if (c == '"') {
        const std::size_t begin = i + 1;
        for (++i; i < text.size() && text[i] != '"'; ++i) {
          if (text[i] == '\\') ++i;
        }
        if (depth == 1 && expect_key) {
          key.assign(text.substr(begin, i - begin));
          keys[key] = line;
          expect_key = false;
        }
      } else if (c == '{' || c == '[') {
        if (depth == 0) object = line;
        ++depth;
        if (depth == 1 && c == '{') expect_key = true;
        if (depth == 2 && c == '[') {
          entries[key].clear();
          expect_entry = true;
        }
      } else if (c == '}' || c == ']') {
        --depth;
      } else if (c == ',') {
        if (depth == 1) expect_key = true;
        if (depth == 2) expect_entry = true;
      }
    }
  }

  /// The line of `key`, or of the object when it is absent.
  int of(std::string_view key) const {
    const auto at = keys.find(key);
    return at == keys.end() ? object : at->second;
  }
  /// The line of entry `k` of the array under `key`, or of the key.
  int of_entry(std::string_view key, std::size_t k) const {
    const auto at = entries.find(key);
    return at == entries.end() || k >= at->second.size() ? of(key) : at->second[k];
  }
};

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

/// Reads the scene, collecting every problem (SceneErrorList, as the XML reader does): each
/// key is checked on its own, with the line it is on, and the mesh is built only when the keys
/// it needs were read.
class JsonSceneParser {
 public:
  JsonSceneParser(const std::string& name, std::string_view text, InputFiles& files)
      : name_(name), lines_(text), files_(files) {}

  Scene parse(const json& root) {
    if (!root.is_object())
      fail("", "the file must hold a JSON object such as {\"obj\": \"cloth.obj\", \"k\": 1000}");
    for (const auto& [key, value] : root.items()) {
      if (std::find(kKnownKeys.begin(), kKnownKeys.end(), key) != kKnownKeys.end()) continue;
      const auto meant = std::find_if(kKnownKeys.begin(), kKnownKeys.end(), [&key = key](auto known) {
        return looks_like_misspelling(key, known);
      });
      if (meant != kKnownKeys.end()) {
        // A misspelt key would leave its default in silence: an error, as a misspelt XML
        // attribute is.
        errors_.add(SceneError(name_, lines_.of(key), "",
                               "unknown key \"" + key + "\" (did you mean \"" +
                                   std::string(*meant) + "\"?)"));
      } else {
        scene_.warnings.push_back(name_ + ":" + std::to_string(lines_.of(key)) +
                                  ": warning: unknown key \"" + key + "\" ignored");
      }
    }
    SceneModel& model = scene_.model;
    scene_.source = name_;
    model.dim = 3;
    model.mass.resize(0);
    scene_.initial.q.resize(0);
    scene_.initial.v.resize(0);
    model.integrator.use(integrator_method("local-global"));
    model.integrator.options.set("iterations", JsonSceneDefaults::kIterations);
    model.integrator.options.set("start", JsonSceneDefaults::kStart);
    model.integrator.options.set("pins", "penalty");
    model.integrator.options.set("penalty", JsonSceneDefaults::kPenalty);
    errors_.attempt(
        [&] { model.integrator.dt = positive(root, "h", JsonSceneDefaults::kTimeStep); });
    errors_.attempt([&] {
      KeyOptions options(*this, root);
      model.integrator.options.read(options);
    });
    errors_.attempt(
        [&] { model.duration = non_negative(root, "duration", JsonSceneDefaults::kDuration); });

    std::optional<Mesh> mesh;
    MeshMaterial material;
    std::optional<std::vector<int>> pins;
    errors_.attempt([&] { mesh = read_mesh(root); });
    const bool k_read = errors_.attempt([&] { material.k = non_negative(root, "k", -1.0); });
    const bool m_read = errors_.attempt([&] {
      material.mass = root.contains("m")
                          ? MassRule{MassRule::kUniform, positive(root, "m", 0.0)}
                          : MassRule{MassRule::kVoronoi, JsonSceneDefaults::kAreaDensity};
    });
    if (mesh) errors_.attempt([&] { pins = pinned(root, mesh->num_vertices()); });
    if (mesh && pins && k_read && m_read) {
      errors_.attempt([&] {
        std::unique_ptr<Force> springs;
        try {
          springs = append_mesh(scene_, *mesh, material, *pins, "obj mesh");
        } catch (const Error& error) {
          fail("obj", error.what());
        }
        model.forces.push_back(std::move(springs));
        model.forces.push_back(
            std::make_unique<ConstantForce<3>>(Vec<3>(0.0, JsonSceneDefaults::kGravity, 0.0)));
        warn_if_overloaded(*mesh, material.k);
      });
    }
    errors_.throw_if_any();
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

  /// Throws a problem of `key` (of the whole object when empty or absent), on its line.
  [[noreturn]] void fail(std::string_view key, const std::string& problem) const {
    throw SceneError(name_, key.empty() ? lines_.object : lines_.of(key), "", problem);
  }

  /// A number under `key`; fallback < 0 marks it required.
  double number(const json& root, const char* key, double fallback) {
    if (!root.contains(key)) {
      if (fallback < 0.0) fail("", std::string("the required key \"") + key + "\" is missing");
      return fallback;
    }
    const json& value = root.at(key);
    if (!value.is_number())
      fail(key, std::string("\"") + key + "\" must be a number, found " + value.dump());
    const double x = value.get<double>();
    if (!std::isfinite(x))
      fail(key, std::string("\"") + key + "\" must be finite, found " + value.dump());
    return x;
  }

  double non_negative(const json& root, const char* key, double fallback) {
    const double x = number(root, key, fallback);
    if (x < 0.0)
      fail(key, std::string("\"") + key + "\" must not be negative, found " + to_text(x));
    return x;
  }

  double positive(const json& root, const char* key, double fallback) {
    const double x = number(root, key, fallback);
    if (!(x > 0.0)) fail(key, std::string("\"") + key + "\" must be positive, found " + to_text(x));
    return x;
  }

  Mesh read_mesh(const json& root) {
    if (!root.contains("obj"))
      fail("", "the required key \"obj\" (the OBJ mesh file) is missing");
    if (!root.at("obj").is_string())
      fail("obj", "\"obj\" must be a file name, found " + root.at("obj").dump());
    const std::string obj = root.at("obj").get<std::string>();
    // A "\u0000" in the name would cut it short where the system reads it.
    if (obj.find('\0') != std::string::npos)
      fail("obj", "\"obj\" must be a file name, found one holding a NUL character: " +
                      root.at("obj").dump());
    const std::int64_t corners = files_.limits().max_face_corners;
    Mesh mesh = read_referenced_mesh(
        files_, name_, obj,
        [corners](std::string_view text, const std::string& name) {
          return read_obj_text(text, name, corners);
        },
        "the \"obj\" of " + name_ + ":" + std::to_string(lines_.of("obj")));
    if (mesh.num_vertices() > files_.limits().max_particles) {
      fail("obj", "the \"obj\" mesh has " + std::to_string(mesh.num_vertices()) + " vertices, " +
                      over_limit(files_.limits().max_particles, "particles", "--max-particles"));
    }
    return mesh;
  }

  /// The 0-based vertices of the 1-based list "b"; every bad entry is reported, on its line.
  std::vector<int> pinned(const json& root, int num_vertices) {
    std::vector<int> out;
    if (!root.contains("b")) return out;
    const json& list = root.at("b");
    if (!list.is_array())
      fail("b", "\"b\" must be a list of 1-based vertex numbers, found " + list.dump());
    bool bad = false;
    for (std::size_t k = 0; k < list.size(); ++k) {
      const json& entry = list[k];
      const bool valid = entry.is_number_integer() && entry.get<long long>() >= 1 &&
                         entry.get<long long>() <= num_vertices;
      if (!valid) {
        errors_.add(SceneError(name_, lines_.of_entry("b", k), "",
                               "\"b\"[" + std::to_string(k) + "] must be a vertex number from 1 to " +
                                   std::to_string(num_vertices) + " (1-based), found " +
                                   entry.dump()));
        bad = true;
        continue;
      }
      out.push_back(entry.get<int>() - 1);
    }
    if (bad) throw DependsOnBrokenElement{};  // reported above, entry by entry
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  const std::string& name_;
  JsonLines lines_;
  InputFiles& files_;
  SceneErrorList errors_;
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
  parser_.fail(name, "\"" + std::string(name) + "\" " + problem);
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
  Scene scene = JsonSceneParser(name, text, files).parse(root);
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
