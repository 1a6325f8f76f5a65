#include "core/collisions/candidate_pairs.h"

#include <algorithm>
#include <vector>

#include "core/collisions/grid_pairs.h"
#include "core/scene_model.h"

namespace fosssim {

void AllPairs::for_each(const PairQuery&, const Visitor& visit) const {
  const SceneModel& model = *model_;
  const int n = model.num_particles();
  const int num_edges = static_cast<int>(model.edges.size());
  const int num_half_planes = static_cast<int>(model.half_planes.size());
  const int num_spheres = static_cast<int>(model.spheres.size());
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) visit({CollisionKind::kParticleParticle, i, j});
    for (int e = 0; e < num_edges; ++e) {
      const Edge& edge = model.edges[e];
      if (edge.i != i && edge.j != i && model.is_colliding_edge(e)) {
        visit({CollisionKind::kParticleEdge, i, e});
      }
    }
    for (int h = 0; h < num_half_planes; ++h) visit({CollisionKind::kParticleHalfPlane, i, h});
    for (int s = 0; s < num_spheres; ++s) visit({CollisionKind::kParticleSphere, i, s});
  }
}

void AllPairs::for_each_moving(const PairQuery& query, const MovingVisitor& visit) const {
  for_each(query, [&visit](const CandidatePair& pair) { visit(pair); });
}

bool uses_grid_pairs(const SceneModel& model) {
  const CollisionSettings& s = model.collisions;
  switch (s.detection) {
    case PairDetection::kAllPairs:
      return false;
    case PairDetection::kContest:
      return true;
    case PairDetection::kDefault:
      break;
  }
  // The grid visits the pairs that can act in the course's order, so penalty forces and simple
  // impulses come out bit-identical; 2D methods that record polynomials (continuous-time and
  // hybrid) log those of every pair the course visits, which only all pairs reproduces.
  return model.dim == 3 || s.method->records != StepRecordLayout::kCollisionsAndPolynomials;
}

std::unique_ptr<CandidatePairs> make_candidate_pairs(const SceneModel& model) {
  if (!uses_grid_pairs(model)) return std::make_unique<AllPairs>(model);
  if (model.dim == 3) return std::make_unique<GridPairs<3>>(model);
  return std::make_unique<GridPairs<2>>(model);
}

void for_each_in_course_order(const CandidatePairs& pairs, const PairQuery& query,
                              const CandidatePairs::Visitor& visit) {
  if (pairs.visits_in_course_order()) {
    pairs.for_each(query, visit);
    return;
  }
  std::vector<CandidatePair> found;
  pairs.for_each(query, [&found](const CandidatePair& pair) { found.push_back(pair); });
  std::sort(found.begin(), found.end(), precedes_in_course_order);
  for (const CandidatePair& pair : found) visit(pair);
}

}  // namespace fosssim
