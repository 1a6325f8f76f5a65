// FOSSSim-generate: writes procedural meshes (mesh/generators.h) as OBJ or MEDIT files, and
// optionally a JSON scene of the fast mass-springs format around an OBJ, so that demos and
// benchmarks need no outside data; and elastic bodies (sheet, rod, ring, polygon, obj) as plain
// XML scenes (app/generate_elastic.h). Exit status: 0 written, 2 bad command line, 4 I/O error.

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <vector>

#include "app/generate_elastic.h"
#include "cli/exit_codes.h"
#include "cli/parse_command_line.h"
#include "core/limits.h"
#include "core/text.h"
#include "io/file_identity.h"
#include "io/json_scene_reader.h"
#include "io/mesh_writer.h"
#include "io/output_file.h"
#include "mesh/generators.h"
#include "mesh/load_check.h"

namespace {

using namespace fosssim;

struct GenerateOptions {
  int nx = 21, ny = 21, nz = 4, links = 20, segments = 32, rings = 12, cells = 8;
  double width = 1.0, height = 1.0, depth = 1.0, length = 1.0;
  double top_radius = 0.25, bottom_radius = 0.5, sx = 1.0, sy = 1.0, sz = 1.0, radius = 1.0;
  std::string plane = "xy";
  bool no_bend = false;
  std::string output;
  std::string json;
  double k = 1000.0;
  std::string pins;
  std::int64_t max_vertices = Limits{}.max_particles;
};

/// The largest size (metres) and stiffness FOSSSim-generate writes: far beyond any scene, and
/// small enough that every coordinate and spring length it leads to stays finite.
constexpr double kMaxSize = 1e6;
constexpr double kMaxStiffness = 1e12;

/// `text` as a JSON string, quotes and escapes included.
std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

/// Writes {"obj": <mesh file relative to the JSON>, "k": k, "b": [pins, 1-based]}.
void write_json_scene(const std::string& path, const std::string& mesh_path, double k,
                      const std::vector<int>& pinned) {
  const auto relative = std::filesystem::path(mesh_path).lexically_relative(
      std::filesystem::absolute(path).parent_path());
  write_output_file(path, [&](std::ostream& out) {
    out << "{\n  \"obj\": " << json_string(relative.generic_string())
        << ",\n  \"k\": " << to_text(k) << ",\n  \"b\": [";
    for (std::size_t p = 0; p < pinned.size(); ++p) out << (p ? ", " : "") << pinned[p] + 1;
    out << "]\n}\n";
  });
}

/// Warns when the JSON scene's load, a force of |g| = 9.8 N on every vertex (not m·g), is far
/// beyond what springs of stiffness k hold: a column of the mesh's springs hanging from a pin
/// would stretch by more than the mesh's size (mesh/load_check.h, docs/scenes-3d.md).
void warn_if_overloaded(const Mesh& mesh, double k) {
  const HangingStretch column = hanging_stretch(mesh, k, -JsonSceneDefaults::kGravity);
  if (!column.overloaded()) return;
  std::cerr << "FOSSSim-generate: warning: the JSON scene puts "
            << to_text(-JsonSceneDefaults::kGravity)
            << " N on every vertex, and springs of k = " << to_text(k)
            << " N/m do not hold it: a column of " << column.springs
            << " springs across this mesh, hanging from a pin, would stretch by about "
            << to_text(std::round(column.stretch * 100.0) / 100.0) << " m, against a mesh of "
            << to_text(std::round(column.size * 100.0) / 100.0) << " m (give --k "
            << to_text(std::ceil(column.stiffness_needed))
            << " or more, or fewer vertices; docs/scenes-3d.md)\n";
}

}  // namespace

int main(int argc, char** argv) {
  GenerateOptions o;
  CLI::App app{
      "Writes a procedural mass-spring mesh: cloth, chain, net and skirt as OBJ,\n"
      "tetbox and tetball as MEDIT .mesh (docs/scenes-3d.md); or an elastic body\n"
      "(sheet, rod, ring, polygon, obj) as an XML scene (docs/scene-format.md).",
      "FOSSSim-generate"};
  app.require_subcommand(1);
  app.add_option("-o,--output", o.output, "File to write: .obj or .mesh for a mesh, .xml for an elastic body")->required();
  app.add_option("--json", o.json,
                 "Also write a JSON scene (fast mass-springs format) around the OBJ");
  app.add_option("--k", o.k, "Spring stiffness for --json (N/m)")->capture_default_str();
  app.add_option("--pins", o.pins, "Pin set for --json (default: the generator's)");
  app.add_option("--max-particles", o.max_vertices,
                 "Refuse to generate more vertices than this (docs/limits-and-failures.md)")
      ->check(CLI::Range(std::int64_t{1}, kMaxParticlesLimit))
      ->capture_default_str();
  auto* cloth = app.add_subcommand("cloth", "nx × ny cloth, hanging (plane xy) or flat (xz)");
  cloth->add_option("--nx", o.nx, "Vertices along the width (at least 2)")->capture_default_str();
  cloth->add_option("--ny", o.ny, "Vertices along the height (at least 2)")->capture_default_str();
  cloth->add_option("--width", o.width, "Size along x (m)")->capture_default_str();
  cloth->add_option("--height", o.height, "Size along y (plane xy) or z (plane xz) (m)")
      ->capture_default_str();
  cloth->add_option("--plane", o.plane, "xy: hanging, facing +z; xz: lying flat, facing +y")
      ->check(CLI::IsMember({"xy", "xz"}))
      ->capture_default_str();
  cloth->add_flag("--no-bend", o.no_bend, "No bending springs");
  auto* chain = app.add_subcommand("chain", "a chain of springs along +x");
  chain->add_option("--links", o.links, "Springs in the chain (at least 1)")->capture_default_str();
  chain->add_option("--length", o.length, "Length of the whole chain (m)")->capture_default_str();
  auto* net = app.add_subcommand("net", "a flat net of springs along grid lines");
  net->add_option("--nx", o.nx, "Vertices along x (at least 2)")->capture_default_str();
  net->add_option("--ny", o.ny, "Vertices along z (at least 2)")->capture_default_str();
  net->add_option("--width", o.width, "Size along x (m)")->capture_default_str();
  net->add_option("--depth", o.depth, "Size along z (m)")->capture_default_str();
  auto* skirt = app.add_subcommand("skirt", "rings of cloth around the y axis");
  skirt->add_option("--segments", o.segments, "Vertices around each ring (at least 3)")
      ->capture_default_str();
  skirt->add_option("--rings", o.rings, "Rings from top to bottom (at least 2)")
      ->capture_default_str();
  skirt->add_option("--top-radius", o.top_radius, "Radius of the top ring (m)")
      ->capture_default_str();
  skirt->add_option("--bottom-radius", o.bottom_radius, "Radius of the bottom ring (m)")
      ->capture_default_str();
  skirt->add_option("--height", o.height, "Height from the bottom ring to the top one (m)")
      ->capture_default_str();
  skirt->add_flag("--no-bend", o.no_bend, "No bending springs");
  auto* box = app.add_subcommand("tetbox", "a box of nx × ny × nz cubes, six tets each");
  box->add_option("--nx", o.nx, "Cubes along x (at least 1)")->capture_default_str();
  box->add_option("--ny", o.ny, "Cubes along y (at least 1)")->capture_default_str();
  box->add_option("--nz", o.nz, "Cubes along z (at least 1)")->capture_default_str();
  box->add_option("--sx", o.sx, "Size along x (m)")->capture_default_str();
  box->add_option("--sy", o.sy, "Size along y (m)")->capture_default_str();
  box->add_option("--sz", o.sz, "Size along z (m)")->capture_default_str();
  auto* ball = app.add_subcommand("tetball", "a ball of tetrahedralized cubes");
  ball->add_option("--cells", o.cells, "Cubes along the diameter")->capture_default_str();
  ball->add_option("--radius", o.radius, "Radius of the ball (m)")->capture_default_str();
  // Every number decimal and finite, as FOSSSim reads them; no empty file names.
  for (CLI::App* command : std::vector<CLI::App*>{&app, cloth, chain, net, skirt, box, ball}) {
    for (CLI::Option* option : command->get_options()) {
      const std::string name = option->get_name();
      if (option->get_type_size_max() == 0 || name == "--help") continue;  // a flag
      if (name == "--output" || name == "--json" || name == "--pins" || name == "--plane") {
        option->check(nonempty_name());
      } else {
        option->check(decimal_number());
      }
    }
  }
  ElasticSubcommands elastic;
  add_elastic_subcommands(app, elastic);
  if (auto status = parse_command_line(app, argc, argv)) return *status;
  if (std::any_of(elastic.commands.begin(), elastic.commands.end(),
                  [](const CLI::App* command) { return command->parsed(); }) &&
      (!o.json.empty() || !o.pins.empty())) {
    std::cerr << "FOSSSim-generate: error: --json and --pins apply to meshes, not to elastic "
                 "bodies\n";
    return kExitBadInput;
  }
  if (auto status = run_elastic_subcommand(elastic, o.output, o.max_vertices)) return *status;
  if (!(o.k >= 0.0 && o.k <= kMaxStiffness)) {
    std::cerr << "FOSSSim-generate: error: --k must be between 0 and " << to_text(kMaxStiffness)
              << " N/m, found " << to_text(o.k) << "\n";
    return kExitBadInput;
  }
  for (const double size : {o.width, o.height, o.depth, o.length, o.top_radius, o.bottom_radius,
                            o.sx, o.sy, o.sz, o.radius}) {
    if (size > kMaxSize || size < -kMaxSize) {
      std::cerr << "FOSSSim-generate: error: sizes must be at most " << to_text(kMaxSize)
                << " m, found " << to_text(size) << "\n";
      return kExitBadInput;
    }
  }
  if (!o.json.empty()) {
    const auto same_name = std::filesystem::absolute(o.json).lexically_normal() ==
                           std::filesystem::absolute(o.output).lexically_normal();
    const auto json_file = file_identity(o.json);
    if (same_name || (json_file && json_file == file_identity(o.output))) {
      std::cerr << "FOSSSim-generate: error: --json " << o.json << " and -o " << o.output
                << " name the same file: one would replace the other\n";
      return kExitBadInput;
    }
    // FOSSSim reads a scene as JSON by its extension; another name would be read as XML.
    if (std::filesystem::path(o.json).extension() != ".json") {
      std::cerr << "FOSSSim-generate: error: --json " << o.json
                << " must end in .json (FOSSSim tells scene formats by their extension)\n";
      return kExitBadInput;
    }
  }

  const auto positive = [](double x) { return x > 0.0; };
  const std::int64_t m = o.max_vertices;
  GeneratedMesh generated;
  bool valid = true;
  try {
    if (cloth->parsed()) {
      valid = o.nx >= 2 && o.ny >= 2 && positive(o.width) && positive(o.height);
      if (valid)
        generated = generate_cloth(o.nx, o.ny, o.width, o.height, o.plane == "xz", !o.no_bend, m);
    } else if (chain->parsed()) {
      valid = o.links >= 1 && positive(o.length);
      if (valid) generated = generate_chain(o.links, o.length, m);
    } else if (net->parsed()) {
      valid = o.nx >= 2 && o.ny >= 2 && positive(o.width) && positive(o.depth);
      if (valid) generated = generate_net(o.nx, o.ny, o.width, o.depth, m);
    } else if (skirt->parsed()) {
      valid = o.segments >= 3 && o.rings >= 2 && positive(o.top_radius) &&
              positive(o.bottom_radius) && o.height >= 0.0;
      if (valid)
        generated = generate_skirt(o.segments, o.rings, o.top_radius, o.bottom_radius, o.height,
                                   !o.no_bend, m);
    } else if (box->parsed()) {
      valid =
          o.nx >= 1 && o.ny >= 1 && o.nz >= 1 && positive(o.sx) && positive(o.sy) && positive(o.sz);
      if (valid) generated = generate_tet_box(o.nx, o.ny, o.nz, o.sx, o.sy, o.sz, m);
    } else {
      valid = o.cells >= 2 && positive(o.radius);
      if (valid) generated = generate_tet_ball(o.cells, o.radius, m);
    }
  } catch (const Error& error) {
    std::cerr << "FOSSSim-generate: error: " << error.what() << "\n";
    return exit_status(error.kind());
  }
  if (!valid) {
    std::cerr << "FOSSSim-generate: error: counts must be at least 2 (cubes, links: 1; skirt "
                 "segments: 3) and sizes positive\n";
    return kExitBadInput;
  }
  for (const auto& vertex : generated.mesh.vertices) {
    if (!vertex.allFinite()) {  // cannot happen within the limits above; never written anyway
      std::cerr << "FOSSSim-generate: error: the sizes give vertices beyond the range of a "
                   "double\n";
      return kExitBadInput;
    }
  }
  const bool tets = !generated.mesh.tets.empty();
  const std::string extension = std::filesystem::path(o.output).extension().string();
  if (extension != (tets ? ".mesh" : ".obj")) {
    std::cerr << "FOSSSim-generate: error: this mesh is written as "
              << (tets ? "MEDIT (.mesh)" : "OBJ (.obj)") << ", but the output is " << o.output
              << "\n";
    return kExitBadInput;
  }
  const std::vector<int>* pinned =
      generated.find_pins(o.pins.empty() ? generated.default_pins : o.pins);
  if (!pinned) {
    std::cerr << "FOSSSim-generate: error: --pins must be " << generated.pin_set_names() << "\n";
    return kExitBadInput;
  }
  if (!o.json.empty() && tets) {
    std::cerr << "FOSSSim-generate: error: --json scenes hold OBJ meshes, not tets\n";
    return kExitBadInput;
  }
  try {
    if (tets) {
      write_medit_file(o.output, generated.mesh);
    } else {
      write_obj_file(o.output, generated.mesh);
    }
    if (!o.json.empty()) {
      write_json_scene(o.json, std::filesystem::absolute(o.output).string(), o.k, *pinned);
    }
  } catch (const Error& error) {
    std::cerr << "FOSSSim-generate: error: " << error.what() << "\n";
    return exit_status(error.kind());
  }
  if (!o.json.empty()) warn_if_overloaded(generated.mesh, o.k);
  std::cout << "wrote " << o.output << ": " << generated.mesh.num_vertices() << " vertices, "
            << compute_spring_pairs(generated.mesh).size() << " springs";
  if (tets) std::cout << ", " << generated.mesh.tets.size() << " tets";
  std::cout << "\n";
  return kExitOk;
}
