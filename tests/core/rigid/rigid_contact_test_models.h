#pragma once
// Bodies and piles of bodies for the rigid-body contact tests.

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "core/rigid_test_models.h"
#include "support/random.h"

namespace fosssim::testing {

/// The corners of an axis-aligned box, clockwise (as the course asks).
inline std::vector<Vec2> box(double x0, double y0, double x1, double y1) {
  return {{x0, y1}, {x1, y1}, {x1, y0}, {x0, y0}};  // clockwise
}

/// A body of unit vertex masses.
inline BodySpec body(std::vector<Vec2> points, double radius = 0.1, bool fixed = false) {
  BodySpec spec;
  spec.masses.assign(points.size(), 1.0);
  spec.points = std::move(points);
  spec.radius = radius;
  spec.fixed = fixed;
  return spec;
}

/// A random pile: n convex polygons (3 to 6 vertices) of size about `size`, scattered over a
/// square of side `spread`, at random angles, with random radii, one in ten fixed; then a long
/// fixed floor under them and a free stick across them.
inline std::pair<SceneModel, State> random_pile(unsigned seed, int n, double spread, double size) {
  Random random(seed);
  std::vector<BodySpec> specs;
  for (int b = 0; b < n; ++b) {
    const int vertices = 3 + random.index(4);
    const Vec2 center(random.uniform(0, spread), random.uniform(0, spread));
    const double scale = size * random.uniform(0.3, 1.5);
    std::vector<Vec2> points;
    for (int k = 0; k < vertices; ++k) {
      const double angle = -2 * std::numbers::pi * (k + random.uniform(0.1, 0.9)) / vertices;
      points.push_back(center + scale * Vec2(std::cos(angle), std::sin(angle)));
    }
    BodySpec spec = body(points, size * random.uniform(0.02, 0.4), random.index(10) == 0);
    for (double& m : spec.masses) m = random.uniform(0.5, 2);
    specs.push_back(spec);
  }
  specs.push_back(body(box(-1, -1, spread + 1, -0.5), 0.1, true));             // a long floor
  specs.push_back(body({{spread * 0.5, 0.0}, {spread * 0.6, spread}}, 0.05));  // a stick
  auto [model, state] = make_rigid_model(specs);
  for (int b = 0; b < static_cast<int>(specs.size()); ++b) {
    state.q[3 * b + 2] = random.uniform(-3, 3);
  }
  return {std::move(model), std::move(state)};
}

}  // namespace fosssim::testing
