#pragma once
// The broad phase: which pairs of objects might touch, handed to the narrow phase.

#include <array>
#include <functional>
#include <memory>

#include "core/collisions/collision_record.h"
#include "core/types.h"

namespace fosssim {

struct SceneModel;

/// A pair to test: particle `particle` against another particle, an edge, a half-plane or a
/// sphere.
/// For particle-particle pairs particle < other.
struct CandidatePair {
  CollisionKind kind = CollisionKind::kParticleParticle;
  int particle = 0;
  int other = 0;
  bool operator==(const CandidatePair&) const = default;
};

/// The course's pair order (course-compatible): by particle i, then particle-particle pairs
/// (i, j > i) by j, then particle-edge pairs by edge, then particle-half-plane pairs by
/// half-plane, then particle-sphere pairs by sphere. Methods whose result depends on the order
/// (Gauss-Seidel impulses) visit pairs in this order; for sums (the penalty force) only round-off
/// depends on it.
inline bool precedes_in_course_order(const CandidatePair& a, const CandidatePair& b) {
  if (a.particle != b.particle) return a.particle < b.particle;
  if (a.kind != b.kind) return static_cast<int>(a.kind) < static_cast<int>(b.kind);
  return a.other < b.other;
}

/// Where the objects may be during a step, for a conservative broad phase: every particle
/// moves along the segment from `start` to `end` (the same vector for a static query), and
/// objects count as touching when they come closer than their radii plus `margin`.
struct PairQuery {
  const Vector& start;
  const Vector& end;
  double margin = 0.0;
};

/// The particles whose end positions a visit changed: those a collision response moved.
struct MovedParticles {
  std::array<int, 3> particle{};
  int count = 0;
};

/// Finds candidate pairs (the broad phase). Contract: every pair whose objects may come within
/// their radii plus the query's margin while moving as the query says is visited, each
/// unordered pair at most once; a particle is never paired with an edge it is an endpoint of,
/// nor with an edge that is no collision capsule (SceneModel::is_colliding_edge).
/// Extra pairs are harmless (the narrow phase rejects them). All-pairs is the reference;
/// a spatial broad phase replaces it through make_candidate_pairs without touching the
/// detection, the responses or the penalty force.
class CandidatePairs {
 public:
  using Visitor = std::function<void(const CandidatePair&)>;
  using MovingVisitor = std::function<MovedParticles(const CandidatePair&)>;
  virtual ~CandidatePairs() = default;

  /// Calls `visit` on every candidate pair for `query`.
  virtual void for_each(const PairQuery& query, const Visitor& visit) const = 0;
  /// Calls `visit` on the candidate pairs in the course's order while the visits move
  /// particles: each visit may change end positions (the vector query.end refers to) and
  /// returns the particles it moved, and every later pair is a candidate for the positions
  /// as they are when it comes (continuous-time handling's Gauss-Seidel pass).
  virtual void for_each_moving(const PairQuery& query, const MovingVisitor& visit) const = 0;
  /// True when for_each visits pairs in the course's order (precedes_in_course_order).
  virtual bool visits_in_course_order() const = 0;
};

/// Every pair, in the course's order: for each particle i, the particles j > i, the edges
/// without i as an endpoint, the half-planes, then the spheres.
class AllPairs final : public CandidatePairs {
 public:
  /// `model` must outlive this.
  explicit AllPairs(const SceneModel& model) : model_(&model) {}
  void for_each(const PairQuery& query, const Visitor& visit) const override;
  /// Positions do not matter to all pairs: the same pairs as for_each.
  void for_each_moving(const PairQuery& query, const MovingVisitor& visit) const override;
  bool visits_in_course_order() const override { return true; }

 private:
  const SceneModel* model_;
};

/// True when the model's pairs come from FOSSSim's grid (GridPairs) rather than all pairs:
/// by model.collisions.detection, and by default where the results are those of all pairs bit
/// for bit (collision_settings.h, PairDetection).
bool uses_grid_pairs(const SceneModel& model);

/// The candidate-pair finder a model asks for (uses_grid_pairs).
std::unique_ptr<CandidatePairs> make_candidate_pairs(const SceneModel& model);

/// Visits the candidates of `pairs` in the course's order, sorting them first when the finder
/// does not already visit in that order.
void for_each_in_course_order(const CandidatePairs& pairs, const PairQuery& query,
                              const CandidatePairs::Visitor& visit);

}  // namespace fosssim
