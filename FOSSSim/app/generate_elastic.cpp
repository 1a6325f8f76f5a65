#include "app/generate_elastic.h"

#include <filesystem>
#include <iostream>

#include "cli/exit_codes.h"
#include "cli/parse_command_line.h"
#include "core/error.h"
#include "core/limits.h"
#include "core/scene_model.h"
#include "core/text.h"
#include "io/elastic_body_element.h"
#include "io/elastic_scene_writer.h"
#include "io/input_files.h"
#include "io/scene_error.h"

namespace fosssim {

namespace {

/// Options every body takes (the attributes of <elasticbody> besides the shape's own).
constexpr const char* kBodyOptions[][2] = {
    {"m", "Mass of every particle (kg); or --totalmass"},
    {"totalmass", "Mass of the whole body (kg), lumped by area (triangles) or length (rods)"},
    {"youngsmodulus", "Young's modulus E of the CST on every triangle (Pa per unit thickness)"},
    {"poissonratio", "Poisson ratio of the CST on every triangle, in (-1, 1)"},
    {"stretch", "alpha of an elastic spring on every edge (N; stiffness alpha / length)"},
    {"bend", "alpha of a bending force at every hinge of a rod (N m^2)"},
    {"x", "Where the body's origin goes (m)"},
    {"y", "Where the body's origin goes (m)"},
    {"rotation", "Counter-clockwise turn of the body about its origin (degrees)"},
    {"vx", "Initial velocity of every free particle (m/s)"},
    {"vy", "Initial velocity of every free particle (m/s)"},
    {"fix", "Side of the body's own frame to fix: left, right, bottom, top or none"},
    {"fixed", "Vertices to fix (0-based, blank or comma separated)"},
    {"particleradius", "Radius of every particle (m), for drawing and collisions"},
    {"edgeradius", "Radius of every edge (m), for drawing and collisions"},
};

/// The shape options of each subcommand: name, help.
struct ShapeCommand {
  const char* name;
  const char* help;
  std::vector<std::pair<const char*, const char*>> options;
};

const std::vector<ShapeCommand>& shape_commands() {
  static const std::vector<ShapeCommand> commands = {
      {"sheet",
       "a width x height rectangle of nx x ny cells, two CST triangles each",
       {{"nx", "Cells along x (at least 1)"},
        {"ny", "Cells along y (at least 1)"},
        {"width", "Size along x (m, default 1)"},
        {"height", "Size along y (m, default 1)"},
        {"diagonals", "alternating (default) or parallel"}}},
      {"rod",
       "a straight rod of springs with bending hinges",
       {{"segments", "Springs along the rod (at least 1)"}, {"length", "Length (m, default 1)"}}},
      {"ring",
       "a closed rod, or with --innerradius an annulus of CST triangles",
       {{"segments", "Vertices around (at least 3)"},
        {"radius", "(Outer) radius (m, default 1)"},
        {"innerradius", "Inner radius (m): makes an annulus"},
        {"layers", "Cells across the annulus (default 1)"}}},
      {"polygon",
       "a simple polygon, with holes or not, triangulated (constrained Delaunay)",
       {{"points", "Corners: \"x0 y0 x1 y1 ...\""},
        {"holes", "Holes' corners, holes separated by ';': \"x0 y0 x1 y1 ...; x0 y0 ...\""},
        {"spacing", "Target side length of the triangles (m); default: corners only"}}},
      {"obj", "the triangles of a 2D OBJ file (z 0 or absent)", {{"file", "The OBJ file"}}},
  };
  return commands;
}

/// `text` escaped for an XML attribute value in double quotes.
std::string attribute_value(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

}  // namespace

void add_elastic_subcommands(CLI::App& app, ElasticSubcommands& elastic) {
  for (const ShapeCommand& shape : shape_commands()) {
    CLI::App* command = app.add_subcommand(
        shape.name, std::string("elastic body: ") + shape.help + " (writes an XML scene)");
    for (const auto& [name, help] : shape.options)
      command->add_option(std::string("--") + name, help);
    for (const auto& [name, help] : kBodyOptions)
      command->add_option(std::string("--") + name, help);
    command->add_option("--duration", elastic.duration, "Scene duration (s)")
        ->check(decimal_number())
        ->capture_default_str();
    command->add_option("--dt", elastic.dt, "Time step (s)")
        ->check(decimal_number())
        ->capture_default_str();
    command->add_option("--integrator", elastic.integrator, "Integrator type")
        ->check(nonempty_name())
        ->capture_default_str();
    command->add_option("--gravity", elastic.gravity, "Add <simplegravity fx=0 fy=G> (m/s^2)")
        ->check(decimal_number());
    command->add_option("--description", elastic.description, "The scene's <description>");
    elastic.commands.push_back(command);
  }
}

std::optional<int> run_elastic_subcommand(const ElasticSubcommands& elastic,
                                          const std::string& output, std::int64_t max_particles) {
  const CLI::App* command = nullptr;
  for (const CLI::App* c : elastic.commands) {
    if (c->parsed()) command = c;
  }
  if (!command) return std::nullopt;
  if (std::filesystem::path(output).extension() != ".xml") {
    std::cerr << "FOSSSim-generate: error: an elastic body is written as an XML scene, but the "
                 "output is "
              << output << "\n";
    return kExitBadInput;
  }
  if (!(elastic.duration >= 0.0) || !(elastic.dt > 0.0)) {
    std::cerr << "FOSSSim-generate: error: --duration must be at least 0 and --dt positive\n";
    return kExitBadInput;
  }
  // The element an <elasticbody> with the same attributes would be.
  std::string element = "<elasticbody shape=\"" + command->get_name() + "\"";
  for (const CLI::Option* option : command->get_options()) {
    const std::string name = option->get_name();
    if (option->count() == 0 || name == "--help" || name == "--duration" || name == "--dt" ||
        name == "--integrator" || name == "--gravity" || name == "--description")
      continue;
    element += " " + name.substr(2) + "=\"" + attribute_value(option->as<std::string>()) + "\"";
  }
  element += "/>";
  Limits limits;
  limits.max_particles = max_particles;
  InputFiles files(limits);
  try {
    const ElasticBodyText read = read_elastic_body_text(element, "command line", files);
    for (const std::string& warning : read.warnings) std::cerr << warning << "\n";
    ElasticSceneSettings settings;
    settings.comment = "Written by FOSSSim-generate " + command->get_name() + " from " + element;
    settings.description = elastic.description;
    settings.duration = elastic.duration;
    settings.integrator = elastic.integrator;
    settings.dt = elastic.dt;
    if (elastic.gravity) settings.gravity = Eigen::Vector2d(0.0, *elastic.gravity);
    const bool default_radius = read.body.radius == SceneModel::kDefaultParticleRadius;
    if (!default_radius) settings.radius = read.body.radius;
    if (read.body.edge_radius != SceneModel::kDefaultEdgeRadius)
      settings.edge_radius = read.body.edge_radius;
    write_elastic_scene(output, settings, read.body.shape, read.body.particles, read.body.material);
    std::cout << "wrote " << output << ": " << read.body.shape.num_vertices() << " particles, "
              << read.body.shape.triangles.size() << " triangles, " << read.body.shape.hinges.size()
              << " hinges\n";
  } catch (const SceneError& error) {  // already "command line:1: error: ..."
    std::cerr << "FOSSSim-generate: " << error.what() << "\n";
    return exit_status(error.kind());
  } catch (const Error& error) {
    std::cerr << "FOSSSim-generate: error: " << error.what() << "\n";
    return exit_status(error.kind());
  }
  return kExitOk;
}

}  // namespace fosssim
