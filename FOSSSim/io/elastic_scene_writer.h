#pragma once
// Writes an elastic body as a plain course-format XML scene: one <particle> per vertex, one
// <edge> per edge and one element per force, so that a student can read every number
// (FOSSSim-generate's sheet, rod, ring, polygon and obj).

#include <Eigen/Core>
#include <optional>
#include <string>

#include "mesh/elastic_body.h"

namespace fosssim {

/// What the written scene holds besides the body.
struct ElasticSceneSettings {
  std::string description;  ///< <description text>, left out when empty
  std::string comment;      ///< an XML comment at the top (how it was made)
  double duration = 5.0;    ///< <duration time> (s)
  std::string integrator = "implicit-euler";
  double dt = 0.01;                        ///< <integrator dt> (s)
  std::optional<Eigen::Vector2d> gravity;  ///< <simplegravity fx fy> (m/s²) when given
  std::optional<double> radius;            ///< every particle's radius attribute when given
  std::optional<double> edge_radius;       ///< every edge's radius attribute when given
};

/// The scene text: settings, particles (vertex v is particle v), edges, then the forces that
/// declare_elastic_forces declares, in its order. Numbers are written in their shortest form
/// that reads back to the same double, so that loading the text gives exactly the model an
/// <elasticbody> with the same shape, placement, mass and material gives.
std::string elastic_scene_text(const ElasticSceneSettings& settings, const ElasticShape& shape,
                               const ElasticParticles& particles, const ElasticMaterial& material);

/// Writes elastic_scene_text to `path` through io/output_file (never a half-written file).
void write_elastic_scene(const std::string& path, const ElasticSceneSettings& settings,
                         const ElasticShape& shape, const ElasticParticles& particles,
                         const ElasticMaterial& material);

}  // namespace fosssim
