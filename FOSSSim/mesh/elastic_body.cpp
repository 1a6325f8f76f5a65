#include "mesh/elastic_body.h"

#include <array>
#include <cmath>
#include <string>

#include "core/error.h"

namespace fosssim {

double hinge_angle(const Eigen::Vector2d& x1, const Eigen::Vector2d& x2,
                   const Eigen::Vector2d& x3) {
  const Eigen::Vector2d e1 = x2 - x1;
  const Eigen::Vector2d e2 = x3 - x2;
  return std::atan2(e1[0] * e2[1] - e1[1] * e2[0], e1.dot(e2));
}

ElasticParticles make_elastic_particles(const ElasticShape& shape,
                                        const ElasticPlacement& placement, const ElasticMass& mass,
                                        const ElasticFixing& fixing) {
  ElasticParticles out;
  const int n = shape.num_vertices();
  out.positions = place_vertices(shape, placement.origin, placement.rotation_degrees);
  out.masses = mass.kind == ElasticMass::kTotal ? lump_total_mass(shape, mass.value)
                                                : std::vector<double>(n, mass.value);
  out.fixed.assign(n, 0);
  if (fixing.side) {
    for (const int v : select_side(shape, *fixing.side)) out.fixed[v] = 1;
  }
  for (const int v : fixing.vertices) {
    if (v < 0 || v >= n) {
      throw Error(ErrorKind::kBadInput, "fixed vertex " + std::to_string(v) +
                                            " is out of range: the body has " + std::to_string(n) +
                                            " vertices (0-based)");
    }
    out.fixed[v] = 1;
  }
  out.velocity = placement.velocity;
  return out;
}

void declare_elastic_forces(const ElasticShape& shape,
                            const std::vector<Eigen::Vector2d>& positions,
                            const ElasticMaterial& material, int first_particle,
                            const DeclareForce& declare) {
  const auto index = [first_particle](int v) { return static_cast<double>(first_particle + v); };
  if (material.stretch) {
    for (const auto& [a, b] : shape.edges) {
      const double l0 = (positions[a] - positions[b]).norm();
      const std::array<DeclaredValue, 4> values = {{{"i1", index(a), true},
                                                    {"i2", index(b), true},
                                                    {"alpha", *material.stretch},
                                                    {"l0", l0}}};
      declare("elasticbodyspringforce", values);
    }
  }
  if (material.bend) {
    for (const auto& [a, b, c] : shape.hinges) {
      const double theta0 = hinge_angle(positions[a], positions[b], positions[c]);
      const std::array<DeclaredValue, 5> values = {{{"i1", index(a), true},
                                                    {"i2", index(b), true},
                                                    {"i3", index(c), true},
                                                    {"alpha", *material.bend},
                                                    {"theta0", theta0}}};
      declare("elasticbodybendingforce", values);
    }
  }
  if (material.youngs_modulus && material.poisson_ratio) {
    for (const auto& [a, b, c] : shape.triangles) {
      const std::array<DeclaredValue, 5> values = {{{"i1", index(a), true},
                                                    {"i2", index(b), true},
                                                    {"i3", index(c), true},
                                                    {"youngsmodulus", *material.youngs_modulus},
                                                    {"poissonratio", *material.poisson_ratio}}};
      declare("elasticbodycstforce", values);
    }
  }
}

}  // namespace fosssim
