#include "render/path_history.h"

#include <cmath>

namespace fosssim {

std::size_t trail_capacity(double duration, double dt) {
  if (!(duration > 0.0) || !(dt > 0.0)) return 0;
  const double points = std::ceil(duration / dt);  // may be infinite
  return points < static_cast<double>(kMaxTrailPoints) ? static_cast<std::size_t>(points)
                                                       : kMaxTrailPoints;
}

PathHistory::PathHistory(const Scene& scene) {
  for (const ParticlePath& path : scene.appearance.paths) {
    Trail trail;
    trail.particle = path.particle;
    trail.color = path.color;
    trail.capacity = trail_capacity(path.duration, scene.model.integrator.dt);
    trails_.push_back(std::move(trail));
  }
}

void PathHistory::record(const Vector& q, int dim) {
  for (Trail& trail : trails_) {
    if (trail.capacity == 0) continue;
    if (trail.points.size() == trail.capacity) trail.points.pop_front();
    const int i = dim * trail.particle;
    trail.points.push_back({q[i], q[i + 1], dim == 3 ? q[i + 2] : 0.0});
  }
}

void PathHistory::clear() {
  for (Trail& trail : trails_) trail.points.clear();
}

}  // namespace fosssim
