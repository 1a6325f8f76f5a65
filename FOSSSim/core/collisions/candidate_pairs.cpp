#include "core/collisions/candidate_pairs.h"

#include <algorithm>
#include <tuple>
#include <vector>

#include "core/scene_model.h"

namespace fosssim {

bool precedes_in_course_order(const CandidatePair& a, const CandidatePair& b) {
  return std::tuple(a.particle, static_cast<int>(a.kind), a.other) <
         std::tuple(b.particle, static_cast<int>(b.kind), b.other);
}

void AllPairs::for_each(const PairQuery&, const Visitor& visit) const {
  const SceneModel& model = *model_;
  const int n = model.num_particles();
  const int num_edges = static_cast<int>(model.edges.size());
  const int num_half_planes = static_cast<int>(model.half_planes.size());
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) visit({CollisionKind::kParticleParticle, i, j});
    for (int e = 0; e < num_edges; ++e) {
      const Edge& edge = model.edges[e];
      if (edge.i != i && edge.j != i) visit({CollisionKind::kParticleEdge, i, e});
    }
    for (int h = 0; h < num_half_planes; ++h) visit({CollisionKind::kParticleHalfPlane, i, h});
  }
}

std::unique_ptr<CandidatePairs> make_candidate_pairs(const SceneModel& model) {
  // Both detection settings use all pairs for now; a spatial broad phase for kContest goes
  // here.
  return std::make_unique<AllPairs>(model);
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
