#pragma once
// The broad phase: which pairs of objects might touch, handed to the narrow phase.

#include <functional>
#include <memory>

#include "core/collisions/collision_record.h"
#include "core/types.h"

namespace fosssim {

struct SceneModel;

/// A pair to test: particle `particle` against another particle, an edge or a half-plane.
/// For particle-particle pairs particle < other.
struct CandidatePair {
  CollisionKind kind = CollisionKind::kParticleParticle;
  int particle = 0;
  int other = 0;
  bool operator==(const CandidatePair&) const = default;
};

/// The course's pair order (course-compatible): by particle i, then particle-particle pairs
/// (i, j > i) by j, then particle-edge pairs by edge, then particle-half-plane pairs by
/// half-plane. Methods whose result depends on the order (Gauss-Seidel impulses) visit pairs
/// in this order; for sums (the penalty force) only round-off depends on it.
bool precedes_in_course_order(const CandidatePair& a, const CandidatePair& b);

/// Where the objects may be during a step, for a conservative broad phase: every particle
/// moves along the segment from `start` to `end` (the same vector for a static query), and
/// objects count as touching when they come closer than their radii plus `margin`.
struct PairQuery {
  const Vector& start;
  const Vector& end;
  double margin = 0.0;
};

/// Finds candidate pairs (the broad phase). Contract: every pair whose objects may come within
/// their radii plus the query's margin while moving as the query says is visited, each
/// unordered pair at most once; a particle is never paired with an edge it is an endpoint of.
/// Extra pairs are harmless (the narrow phase rejects them). All-pairs is the reference;
/// a spatial broad phase replaces it through make_candidate_pairs without touching the
/// detection, the responses or the penalty force.
class CandidatePairs {
 public:
  using Visitor = std::function<void(const CandidatePair&)>;
  virtual ~CandidatePairs() = default;

  /// Calls `visit` on every candidate pair for `query`.
  virtual void for_each(const PairQuery& query, const Visitor& visit) const = 0;
  /// True when for_each visits pairs in the course's order (precedes_in_course_order).
  virtual bool visits_in_course_order() const = 0;
};

/// Every pair, in the course's order: for each particle i, the particles j > i, the edges
/// without i as an endpoint, then the half-planes.
class AllPairs final : public CandidatePairs {
 public:
  /// `model` must outlive this.
  explicit AllPairs(const SceneModel& model) : model_(&model) {}
  void for_each(const PairQuery& query, const Visitor& visit) const override;
  bool visits_in_course_order() const override { return true; }

 private:
  const SceneModel* model_;
};

/// The candidate-pair finder a model asks for (model.collisions.detection).
std::unique_ptr<CandidatePairs> make_candidate_pairs(const SceneModel& model);

/// Visits the candidates of `pairs` in the course's order, sorting them first when the finder
/// does not already visit in that order.
void for_each_in_course_order(const CandidatePairs& pairs, const PairQuery& query,
                              const CandidatePairs::Visitor& visit);

}  // namespace fosssim
