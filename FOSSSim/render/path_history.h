#pragma once
// The trails of a scene's <particlepath> elements.

#include <cstddef>
#include <deque>
#include <vector>

#include "core/scene.h"
#include "render/camera.h"

namespace fosssim {

/// A point in world units (z = 0 in 2D scenes).
struct Point3 {
  double x = 0.0, y = 0.0, z = 0.0;
};

/// The last positions of each traced particle, oldest first.
struct Trail {
  int particle = 0;
  Color color;
  std::size_t capacity = 0;  ///< trail_capacity(path duration, dt) positions
  std::deque<Point3> points;
};

/// Records, for every <particlepath>, the last ceil(duration/dt) positions of its particle
/// (docs/scene-format.md), one per recorded state, up to kMaxTrailPoints.
class PathHistory {
 public:
  /// One trail per path of the scene, sized with the scene's current time step.
  explicit PathHistory(const Scene& scene);

  /// Appends the traced particles' current positions (q interleaved, `dim` per particle),
  /// dropping the oldest beyond each trail's capacity.
  void record(const Vector& q, int dim);
  /// Forgets every recorded position.
  void clear();

  const std::vector<Trail>& trails() const { return trails_; }

 private:
  std::vector<Trail> trails_;
};

/// The most positions a trail keeps, whatever its duration: a million points already draw
/// the same picture as more, and a run of a billion steps must not keep them all.
constexpr std::size_t kMaxTrailPoints = 1'000'000;

/// ceil(duration / dt) in double precision, 0 for a non-positive duration, and at most
/// kMaxTrailPoints (a ratio beyond any integer, as from duration 1e300 at dt 1e-300, included).
std::size_t trail_capacity(double duration, double dt);

}  // namespace fosssim
