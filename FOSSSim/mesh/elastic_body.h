#pragma once
// What an elastic body declares: its particles and, element by element, the Theme 4 forces with
// their parameters, the same whether they become forces in memory (io/elastic_body_element) or
// elements of a course-format scene file (FOSSSim-generate).

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "mesh/elastic_shapes.h"

namespace fosssim {

/// The material of a body, given once. A quantity left out makes no force of its kind.
struct ElasticMaterial {
  /// CST on every triangle: Young's modulus E (Pa per unit thickness) and Poisson ratio ν.
  std::optional<double> youngs_modulus, poisson_ratio;
  /// α of an elastic spring on every edge (N: the spring's stiffness is α / l0).
  std::optional<double> stretch;
  /// α of a bending force at every hinge of a rod (N·m²).
  std::optional<double> bend;
};

/// Where a body goes and how it starts: vertex x of its own frame is placed at
/// origin + R(rotation_degrees) x (counter-clockwise), every particle moving at `velocity`.
struct ElasticPlacement {
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  double rotation_degrees = 0.0;
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();
};

/// How a body's mass is given, once: the mass of every particle, or the body's total, lumped
/// by area (triangles) or length (rods) with lump_total_mass.
struct ElasticMass {
  enum Kind { kPerParticle, kTotal };
  Kind kind = kPerParticle;
  double value = 1.0;  ///< kg
};

/// Which particles of a body are fixed: a side of its own frame and listed vertices.
struct ElasticFixing {
  std::optional<ShapeSide> side;
  std::vector<int> vertices;  ///< 0-based vertices of the body
};

/// A body's particles, vertex v of the shape being particle v of the body.
struct ElasticParticles {
  std::vector<Eigen::Vector2d> positions;
  std::vector<double> masses;
  std::vector<char> fixed;
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();  ///< of every particle that is not fixed
};

/// The particles of `shape` placed, massed and fixed as asked. Throws Error (kBadInput) for a
/// fixed vertex out of range, naming it and the body's vertex count.
ElasticParticles make_elastic_particles(const ElasticShape& shape,
                                        const ElasticPlacement& placement, const ElasticMass& mass,
                                        const ElasticFixing& fixing);

/// One parameter of a force declaration, as the scene format names it ("i1", "alpha", ...).
struct DeclaredValue {
  const char* name;
  double value;
  bool is_index = false;  ///< a particle index (an integer, written as one)
};

/// Receives one force declaration: its tag ("elasticbodycstforce") and its parameters.
using DeclareForce = std::function<void(std::string_view tag, std::span<const DeclaredValue>)>;

/// Declares the forces of `shape` placed at `positions` (its vertices after placement, vertex v
/// becoming particle first_particle + v), grouped as the scene format sums them: a spring on
/// every edge (alpha = stretch, l0 = the edge's length at `positions`), a bending force at every
/// hinge (alpha = bend, theta0 = the hinge's angle at `positions`, computed as the force computes
/// it), a CST on every triangle (its rest shape left to default to the particles' initial
/// positions). Rest shapes are thus the initial positions: the body starts at rest.
void declare_elastic_forces(const ElasticShape& shape,
                            const std::vector<Eigen::Vector2d>& positions,
                            const ElasticMaterial& material, int first_particle,
                            const DeclareForce& declare);

/// The signed angle of the turn from x2 - x1 to x3 - x2, as the bending force computes it:
/// atan2(e1 × e2, e1 · e2).
double hinge_angle(const Eigen::Vector2d& x1, const Eigen::Vector2d& x2, const Eigen::Vector2d& x3);

}  // namespace fosssim
