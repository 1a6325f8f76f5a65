#include "core/collisions/impact_zones.h"

#include <algorithm>
#include <cmath>

namespace fosssim {

ImpactZone impact_zone_of(const SceneModel& model, const CandidatePair& pair) {
  ImpactZone zone;
  switch (pair.kind) {
    case CollisionKind::kParticleParticle:
      zone.particles = {pair.particle, pair.other};
      break;
    case CollisionKind::kParticleEdge: {
      const Edge& edge = model.edges[pair.other];
      zone.particles = {pair.particle, edge.i, edge.j};
      break;
    }
    case CollisionKind::kParticleHalfPlane:
    case CollisionKind::kParticleSphere:  // hybrid is 2D, spheres 3D: for completeness
      zone.particles = {pair.particle};
      zone.half_plane = true;
      break;
  }
  std::sort(zone.particles.begin(), zone.particles.end());
  zone.particles.erase(std::unique(zone.particles.begin(), zone.particles.end()),
                       zone.particles.end());
  return zone;
}

namespace {
bool share_a_particle(const ImpactZone& a, const ImpactZone& b) {
  auto i = a.particles.begin();
  auto j = b.particles.begin();
  while (i != a.particles.end() && j != b.particles.end()) {
    if (*i == *j) return true;
    if (*i < *j) {
      ++i;
    } else {
      ++j;
    }
  }
  return false;
}
}  // namespace

std::vector<ImpactZone> merge_impact_zones(std::vector<ImpactZone> zones) {
  bool merged = true;
  while (merged) {
    merged = false;
    for (std::size_t a = 0; a < zones.size() && !merged; ++a) {
      for (std::size_t b = a + 1; b < zones.size(); ++b) {
        if (!share_a_particle(zones[a], zones[b])) continue;
        std::vector<int> both;
        std::set_union(zones[a].particles.begin(), zones[a].particles.end(),
                       zones[b].particles.begin(), zones[b].particles.end(),
                       std::back_inserter(both));
        zones[a].particles = std::move(both);
        zones[a].half_plane = zones[a].half_plane || zones[b].half_plane;
        zones.erase(zones.begin() + static_cast<std::ptrdiff_t>(b));
        merged = true;
        break;
      }
    }
  }
  std::sort(zones.begin(), zones.end(), [](const ImpactZone& a, const ImpactZone& b) {
    return a.particles.front() < b.particles.front();
  });
  return zones;
}

void apply_rigid_failsafe(const SceneModel& model, const ImpactZone& zone, const Vector& xs,
                          double h, Vector& q, Vector& v) {
  using V2 = Vec<2>;
  const bool has_fixed = std::any_of(zone.particles.begin(), zone.particles.end(),
                                     [&model](int p) { return model.fixed[p]; });
  if (zone.half_plane || has_fixed) {
    for (int p : zone.particles) {
      q.segment<2>(2 * p) = xs.segment<2>(2 * p);
      v.segment<2>(2 * p).setZero();
    }
    return;
  }
  double total_mass = 0.0;
  V2 x_cm = V2::Zero(), d_cm = V2::Zero();
  for (int p : zone.particles) {
    const double m = model.mass[2 * p];
    total_mass += m;
    x_cm += m * xs.segment<2>(2 * p);
    d_cm += m * (q.segment<2>(2 * p) - xs.segment<2>(2 * p));
  }
  x_cm /= total_mass;
  d_cm /= total_mass;
  double L = 0.0, I = 0.0;
  for (int p : zone.particles) {
    const double m = model.mass[2 * p];
    const V2 r = xs.segment<2>(2 * p) - x_cm;
    const V2 d = (q.segment<2>(2 * p) - xs.segment<2>(2 * p)) - d_cm;
    L += m * (r.x() * d.y() - r.y() * d.x());
    I += m * r.squaredNorm();
  }
  const double omega = L / I;
  const double c = std::cos(omega), s = std::sin(omega);
  for (int p : zone.particles) {
    const V2 start = xs.segment<2>(2 * p);
    const V2 r = start - x_cm;
    const V2 r_perp(-r.y(), r.x());
    const V2 x = x_cm + d_cm + c * r + s * r_perp;
    q.segment<2>(2 * p) = x;
    v.segment<2>(2 * p) = (x - start) / h;
  }
}

}  // namespace fosssim
