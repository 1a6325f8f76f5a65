#include "io/elastic_scene_writer.h"

#include <string_view>

#include "core/text.h"
#include "io/output_file.h"

namespace fosssim {

namespace {

/// `text` escaped for an XML attribute value in double quotes.
std::string escaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace

std::string elastic_scene_text(const ElasticSceneSettings& settings, const ElasticShape& shape,
                               const ElasticParticles& particles, const ElasticMaterial& material) {
  std::string out;
  if (!settings.comment.empty()) {
    std::string comment = settings.comment;
    for (std::size_t at = comment.find("--"); at != std::string::npos; at = comment.find("--"))
      comment.replace(at, 2, "- -");  // "--" may not appear inside an XML comment
    out += "<!-- " + comment + " -->\n";
  }
  out += "<scene>\n";
  if (!settings.description.empty())
    out += "  <description text=\"" + escaped(settings.description) + "\"/>\n";
  out += "  <duration time=\"" + to_text(settings.duration) + "\"/>\n";
  out += "  <integrator type=\"" + escaped(settings.integrator) + "\" dt=\"" +
         to_text(settings.dt) + "\"/>\n";
  if (settings.gravity) {
    out += "  <simplegravity fx=\"" + to_text(settings.gravity->x()) + "\" fy=\"" +
           to_text(settings.gravity->y()) + "\"/>\n";
  }
  const std::string radius =
      settings.radius ? " radius=\"" + to_text(*settings.radius) + "\"" : std::string();
  for (int v = 0; v < shape.num_vertices(); ++v) {
    const bool fixed = particles.fixed[v] != 0;
    const Eigen::Vector2d velocity = fixed ? Eigen::Vector2d::Zero() : particles.velocity;
    out += "  <particle m=\"" + to_text(particles.masses[v]) + "\" px=\"" +
           to_text(particles.positions[v].x()) + "\" py=\"" + to_text(particles.positions[v].y()) +
           "\" vx=\"" + to_text(velocity.x()) + "\" vy=\"" + to_text(velocity.y()) + "\" fixed=\"" +
           (fixed ? "1" : "0") + "\"" + radius + "/>\n";
  }
  const std::string edge_radius =
      settings.edge_radius ? " radius=\"" + to_text(*settings.edge_radius) + "\"" : std::string();
  for (const auto& [a, b] : shape.edges) {
    out += "  <edge i=\"" + std::to_string(a) + "\" j=\"" + std::to_string(b) + "\"" + edge_radius +
           "/>\n";
  }
  declare_elastic_forces(shape, particles.positions, material, 0,
                         [&](std::string_view tag, std::span<const DeclaredValue> values) {
                           out += "  <";
                           out += tag;
                           for (const DeclaredValue& value : values) {
                             // An index as an integer: to_text would write 100000 as "1e+05".
                             const std::string text =
                                 value.is_index
                                     ? std::to_string(static_cast<std::int64_t>(value.value))
                                     : to_text(value.value);
                             out += std::string(" ") + value.name + "=\"" + text + "\"";
                           }
                           out += "/>\n";
                         });
  out += "</scene>\n";
  return out;
}

void write_elastic_scene(const std::string& path, const ElasticSceneSettings& settings,
                         const ElasticShape& shape, const ElasticParticles& particles,
                         const ElasticMaterial& material) {
  write_output_file(path, elastic_scene_text(settings, shape, particles, material));
}

}  // namespace fosssim
