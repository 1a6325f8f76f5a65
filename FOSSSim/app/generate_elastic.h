#pragma once
// FOSSSim-generate's elastic-body subcommands: sheet, rod, ring, polygon and obj write a plain
// course-format XML scene (explicit particles, edges and Theme 4 force elements) of the body an
// <elasticbody> element with the same attributes makes (docs/scene-format.md).

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

namespace fosssim {

/// The subcommands, added to a program's CLI::App.
struct ElasticSubcommands {
  std::vector<CLI::App*> commands;
  /// The scene around the body.
  double duration = 5.0;
  double dt = 0.01;
  std::string integrator = "implicit-euler";
  std::optional<double> gravity;
  std::string description;
};

/// Adds sheet, rod, ring, polygon and obj to `app`. Each option --NAME of a body is the
/// attribute NAME of <elasticbody>, read by the same reader.
void add_elastic_subcommands(CLI::App& app, ElasticSubcommands& elastic);

/// When one of the subcommands was given: writes its scene to `output` (which must end in .xml)
/// and returns the exit status (0 written, 2 bad input, 4 cannot write); otherwise nothing.
/// `max_particles` bounds the body as --max-particles bounds a scene.
std::optional<int> run_elastic_subcommand(const ElasticSubcommands& elastic,
                                          const std::string& output, std::int64_t max_particles);

}  // namespace fosssim
