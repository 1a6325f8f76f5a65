#pragma once
// FOSSSim's broad phase: candidate pairs from hierarchical grids of bounding boxes, in the
// course's order (docs/collisions.md, "Broad phase").

#include <cstddef>
#include <vector>

#include "core/collisions/box_grid.h"
#include "core/collisions/candidate_pairs.h"
#include "core/scene_model.h"

namespace fosssim {

/// Candidate pairs from bounding boxes. Each particle's box holds its segment from start to end
/// position grown by its radius, each edge's box its two particles' segments grown by the
/// edge's radius, both grown further by half the query's margin and by a round-off allowance
/// (1e-10 of the scene's largest coordinate); a pair is a candidate when the boxes overlap.
/// Particles and edges are filed in two BoxGrids with the same cells (level 0's side is the
/// median box size); each particle asks both grids for the boxes at its level and coarser,
/// each edge asks the particle grid for coarser ones, so each pair is found once. Half-planes
/// are tested against every particle's box directly (their number is small).
///
/// The pairs are then sorted into the course's order (a counting sort by particle, then each
/// particle's few pairs by kind and index), so that every method, Gauss-Seidel ones included,
/// visits the pairs that matter in the same order as with all pairs, and results are
/// bit-identical: a pair all pairs would visit and this one not is a pair whose objects are
/// too far apart for the narrow phase to act on.
///
/// Static queries (start and end the same vector: the penalty force, simple impulses) grow every
/// particle's box by a skin of one median radius along every axis, and keep the pairs: a later
/// static query whose particles are all within the skin of where they were gets the same pairs
/// without a search, since the boxes of its positions lie inside the grown ones (Verlet lists).
/// Particles that move a radius in a few steps are searched for every few steps.
///
/// Moving queries (for_each_moving) keep every particle's box grown by its displacement over
/// the step, so that a response that reverses or slows a particle keeps it inside its box; a
/// particle (and its edges) that a response moves out of its box gets a grown box and is
/// asked for new partners at once, pairs later in the order joining those still to come.
///
/// Crowds: when the search finds more candidates than its budget (candidate_budget()), as when
/// thousands of balls sit in one spot and every box overlaps every other, the list is dropped
/// and the query visits the pairs directly instead: every pair in the course's order, tested
/// box against box (boxes grown as above for moving queries). The same pairs, in the same
/// order, as the list would have held, with the cost of all pairs and no memory per pair.
template <int D>
class GridPairs final : public CandidatePairs {
 public:
  /// `model` must outlive this.
  explicit GridPairs(const SceneModel& model);

  void for_each(const PairQuery& query, const Visitor& visit) const override;
  void for_each_moving(const PairQuery& query, const MovingVisitor& visit) const override;
  bool visits_in_course_order() const override { return true; }
  /// How many times the grids were built and searched (static queries served from the skin's
  /// pairs do not count).
  int searches() const { return searches_; }

  /// The default candidate budget is kCandidatesPerObject per particle and edge, and at least
  /// kMinCandidates: the pairs' memory stays within a few kilobytes per object.
  static constexpr std::size_t kCandidatesPerObject = 256;
  static constexpr std::size_t kMinCandidates = std::size_t{1} << 16;
  /// The most candidates a search may list before the query visits pairs directly.
  std::size_t candidate_budget() const { return budget_; }
  /// Replaces the default budget (tests force direct visits with a small one).
  void set_candidate_budget(std::size_t budget) {
    budget_ = budget;
    reusable_ = false;
  }
  /// True when the last search found more candidates than the budget, so that the last query
  /// (and the static queries reusing its boxes) visited the pairs directly.
  bool visits_directly() const { return direct_; }

 private:
  /// Boxes of every particle and edge for `query`; with `slack` each particle's segment is
  /// grown by its own length first, and then by `skin` along every axis.
  void compute_boxes(const PairQuery& query, bool slack, double skin = 0.0) const;
  /// True when the pairs of the last static query serve `query` (a static one): the same
  /// margin, and every particle within the skin of where it was.
  bool can_reuse(const PairQuery& query) const;
  Box<D> particle_box(const PairQuery& query, int p, bool slack) const;
  Box<D> edge_box(int e) const;  // from motion_boxes_
  void build_grids() const;
  /// Appends to found_ every pair the grids hold: particles against particles and edges at
  /// their level and coarser, edges against coarser particles, particles against half-planes
  /// and spheres. Returns false, with found_ cleared, as soon as found_ would exceed budget_.
  bool find_all_pairs() const;
  /// Appends the half-planes and spheres that particle p's motion box may come near.
  void find_obstacles(int p) const;
  bool near_half_plane(int p, int h) const;
  bool near_sphere(int p, int s) const;
  /// The pairs of overlapping boxes, in the course's order, without a list (crowds).
  void visit_directly(const Visitor& visit) const;
  /// The same for a moving query: each pair tested with the boxes as they are when it comes,
  /// grown after each visit by grow_after_move.
  void visit_moving_directly(const PairQuery& query, const MovingVisitor& visit) const;
  /// Grows p's box and its edges' boxes as follow_move does, without asking for partners.
  void grow_after_move(const PairQuery& query, int p) const;
  /// Sorts found_ into the course's order (found_ is reordered in place).
  void sort_found() const;
  /// After a visit of a moving query moved particle p: grows its box and its edges' boxes if
  /// they no longer hold the motion, and queues the new pairs after `current`.
  void follow_move(const PairQuery& query, int p, const CandidatePair& current) const;
  /// True when particle p is never paired with edge e: p is one of its ends, or e is no
  /// collision capsule (SceneModel::is_colliding_edge).
  bool never_pairs(int p, int e) const {
    const Edge& edge = model_->edges[e];
    return edge.i == p || edge.j == p || !model_->is_colliding_edge(e);
  }

  const SceneModel* model_;
  std::vector<int> incident_start_, incident_edges_;  // edges of each particle, CSR
  double skin_ = 0.0;  // how far a particle may move before static pairs are found afresh
  std::size_t budget_ = kMinCandidates;  // set by the constructor
  mutable bool direct_ = false;           // the last search ran over budget_

  // Static queries: found_ holds the pairs for every particle within skin_ (per axis) of
  // reference_, for the margin reused_margin_, while reusable_.
  mutable bool reusable_ = false;
  mutable int searches_ = 0;
  mutable Vector reference_;
  mutable double reused_margin_ = 0.0;

  // Scratch, reused from query to query (a GridPairs answers one query at a time).
  mutable double margin_ = 0.0;               // the query's margin, at least 0
  mutable double rounding_ = 0.0;             // the round-off allowance
  mutable double pad_ = 0.0;                  // half the margin plus the round-off allowance
  mutable std::vector<Box<D>> motion_boxes_;  // each particle's segment (and slack)
  mutable std::vector<Box<D>> particle_boxes_, edge_boxes_;
  mutable BoxGrid<D> particle_grid_, edge_grid_;
  mutable std::vector<double> extents_;
  mutable std::vector<CandidatePair> found_, sorted_;
  mutable std::vector<int> bucket_;
  // Moving queries: the pairs planned at the start, those found since (a heap), and the
  // particles and edges whose boxes grew since the grids were built.
  mutable std::vector<CandidatePair> planned_, later_;
  mutable std::vector<char> escaped_particle_, escaped_edge_;
  mutable std::vector<int> escaped_particles_, escaped_edges_;
};

}  // namespace fosssim
