#include "core/collisions/grid_pairs.h"

#include <algorithm>
#include <cmath>

namespace fosssim {

namespace {

template <int D>
Box<D> grown(const Box<D>& box, double by) {
  return {(box.lo.array() - by).matrix(), (box.hi.array() + by).matrix()};
}

/// The box of the segment from s to e.
template <int D>
Box<D> segment_box(const Vec<D>& s, const Vec<D>& e) {
  return {s.cwiseMin(e), s.cwiseMax(e)};
}

/// std::fmax (the larger, ignoring a NaN) without a call into the maths library.
double larger(double a, double b) { return (b > a || a != a) ? b : a; }

/// A larger absolute value, ignoring NaN.
template <int D>
double largest_magnitude(const Box<D>& box, double so_far) {
  return larger(so_far, larger(box.lo.cwiseAbs().maxCoeff(), box.hi.cwiseAbs().maxCoeff()));
}

/// For heaps that pop the earliest pair in the course's order first.
bool comes_later(const CandidatePair& a, const CandidatePair& b) {
  return precedes_in_course_order(b, a);
}

}  // namespace

template <int D>
GridPairs<D>::GridPairs(const SceneModel& model) : model_(&model) {
  const int n = model.num_particles();
  // The skin: one median radius. Larger skins are reused longer but give more candidates.
  std::vector<double> radii(model.particle_radius.begin(), model.particle_radius.end());
  if (!radii.empty()) {
    const auto middle = radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 2);
    std::nth_element(radii.begin(), middle, radii.end());
    if (std::isfinite(*middle) && *middle > 0.0) skin_ = *middle;
  }
  budget_ = std::max(kMinCandidates,
                     kCandidatesPerObject * static_cast<std::size_t>(n + model.edges.size()));
  incident_start_.assign(n + 1, 0);
  for (const Edge& edge : model.edges) {
    ++incident_start_[edge.i + 1];
    if (edge.j != edge.i) ++incident_start_[edge.j + 1];
  }
  for (int p = 0; p < n; ++p) incident_start_[p + 1] += incident_start_[p];
  incident_edges_.resize(incident_start_[n]);
  std::vector<int> next(incident_start_.begin(), incident_start_.end() - 1);
  for (int e = 0; e < static_cast<int>(model.edges.size()); ++e) {
    const Edge& edge = model.edges[e];
    incident_edges_[next[edge.i]++] = e;
    if (edge.j != edge.i) incident_edges_[next[edge.j]++] = e;
  }
}

template <int D>
void GridPairs<D>::compute_boxes(const PairQuery& query, bool slack, double skin) const {
  const SceneModel& model = *model_;
  const int n = model.num_particles();
  const int num_edges = static_cast<int>(model.edges.size());
  double scale = 0.0;
  motion_boxes_.resize(n);
  for (int p = 0; p < n; ++p) {
    const Vec<D> s = particle_vec<D>(query.start, p);
    const Vec<D> e = particle_vec<D>(query.end, p);
    motion_boxes_[p] = segment_box<D>(s, e);
    if (slack) motion_boxes_[p] = grown(motion_boxes_[p], (e - s).norm());
    if (skin > 0.0) motion_boxes_[p] = grown(motion_boxes_[p], skin);
    scale = largest_magnitude(motion_boxes_[p], scale);
    scale = larger(scale, model.particle_radius[p]);
  }
  for (int e = 0; e < num_edges; ++e) scale = larger(scale, model.edge_radius[e]);
  margin_ = larger(query.margin, 0.0);
  rounding_ = 1e-10 * (1.0 + scale + margin_);
  pad_ = 0.5 * margin_ + rounding_;
  particle_boxes_.resize(n);
  for (int p = 0; p < n; ++p) {
    particle_boxes_[p] = grown(motion_boxes_[p], larger(model.particle_radius[p], 0.0) + pad_);
  }
  edge_boxes_.resize(num_edges);
  for (int e = 0; e < num_edges; ++e) edge_boxes_[e] = edge_box(e);
}

template <int D>
Box<D> GridPairs<D>::edge_box(int e) const {
  const Edge& edge = model_->edges[e];
  return grown(motion_boxes_[edge.i].united(motion_boxes_[edge.j]),
               larger(model_->edge_radius[e], 0.0) + pad_);
}

template <int D>
void GridPairs<D>::build_grids() const {
  ++searches_;
  // Level 0's cells are the size of the median box, so most boxes are filed there and a cell
  // holds a few of them.
  extents_.clear();
  for (const Box<D>& box : particle_boxes_) extents_.push_back(box.extent());
  for (const Box<D>& box : edge_boxes_) extents_.push_back(box.extent());
  double base_cell = 1.0;
  if (!extents_.empty()) {
    const auto middle = extents_.begin() + static_cast<std::ptrdiff_t>(extents_.size() / 2);
    std::nth_element(extents_.begin(), middle, extents_.end());
    if (std::isfinite(*middle) && *middle > 0.0) base_cell = *middle;
  }
  particle_grid_.build(particle_boxes_, base_cell);
  edge_grid_.build(edge_boxes_, base_cell);
}

template <int D>
bool GridPairs<D>::near_half_plane(int p, int h) const {
  const Box<D>& motion = motion_boxes_[p];
  const Vec<D> centre = 0.5 * (motion.lo + motion.hi);
  const Vec<D> half = 0.5 * (motion.hi - motion.lo);
  // The narrow phase acts when |(x - P)·N| / ‖N‖ < r + margin for a centre x in the box (2D,
  // the course's unsigned distance), or when (x - P)·N / ‖N‖ < r + margin (3D, signed: a centre
  // deep inside the solid is still pushed out, core/collisions/proximity.h).
  const double reach = larger(model_->particle_radius[p], 0.0) + margin_ + rounding_;
  const HalfPlane& plane = model_->half_planes[h];
  const Vec<D> N = plane.normal.head<D>();
  const double f = (centre - plane.point.head<D>()).dot(N);
  const double spread = N.cwiseAbs().dot(half);
  const double limit = reach * N.norm();
  if constexpr (D == 3) return f - spread < limit;
  return f - spread < limit && f + spread > -limit;
}

template <int D>
bool GridPairs<D>::near_sphere(int p, int s) const {
  const Box<D>& motion = motion_boxes_[p];
  // A sphere acts when ‖x - C‖ < r + ρ + margin for a centre x in the box.
  const double reach = larger(model_->particle_radius[p], 0.0) + margin_ + rounding_;
  const Sphere& sphere = model_->spheres[s];
  const Vec<D> C = sphere.center.head<D>();
  const Vec<D> nearest = C.cwiseMax(motion.lo).cwiseMin(motion.hi);
  return (C - nearest).norm() < reach + sphere.radius;
}

template <int D>
void GridPairs<D>::find_obstacles(int p) const {
  const SceneModel& model = *model_;
  for (int h = 0; h < static_cast<int>(model.half_planes.size()); ++h) {
    if (near_half_plane(p, h)) found_.push_back({CollisionKind::kParticleHalfPlane, p, h});
  }
  for (int s = 0; s < static_cast<int>(model.spheres.size()); ++s) {
    if (near_sphere(p, s)) found_.push_back({CollisionKind::kParticleSphere, p, s});
  }
}

template <int D>
bool GridPairs<D>::find_all_pairs() const {
  found_.clear();
  // Stops listing once the budget is spent: a crowd is visited directly instead.
  bool over = false;
  const auto add = [&](const CandidatePair& pair) {
    if (found_.size() >= budget_) {
      over = true;
      return;
    }
    found_.push_back(pair);
  };
  // In the grid's order rather than by index: neighbours in space come one after the other.
  particle_grid_.for_each_filed([&](int a, const Box<D>& box) {
    if (over) return;
    const int level = particle_grid_.level_of(a);
    // Particles at a's level pair with it from the lower index; coarser ones always from a.
    particle_grid_.query(box, level, [&](int b) {
      if (b == a || (b < a && particle_grid_.level_of(b) == level)) return;
      add({CollisionKind::kParticleParticle, std::min(a, b), std::max(a, b)});
    });
    edge_grid_.query(box, level, [&](int e) {
      if (!never_pairs(a, e)) add({CollisionKind::kParticleEdge, a, e});
    });
    find_obstacles(a);  // at most the obstacles' number past the budget
  });
  // Edges meet the particles of coarser levels (those of their own level and finer asked).
  edge_grid_.for_each_filed([&](int e, const Box<D>& box) {
    if (over) return;
    particle_grid_.query(box, edge_grid_.level_of(e) + 1, [&](int a) {
      if (!never_pairs(a, e)) add({CollisionKind::kParticleEdge, a, e});
    });
  });
  if (over || found_.size() > budget_) {
    found_.clear();
    return false;
  }
  return true;
}

template <int D>
void GridPairs<D>::visit_directly(const Visitor& visit) const {
  const SceneModel& model = *model_;
  const int n = model.num_particles();
  const int num_edges = static_cast<int>(model.edges.size());
  const int num_half_planes = static_cast<int>(model.half_planes.size());
  const int num_spheres = static_cast<int>(model.spheres.size());
  for (int i = 0; i < n; ++i) {
    const Box<D>& box = particle_boxes_[i];
    for (int j = i + 1; j < n; ++j) {
      if (box.overlaps(particle_boxes_[j])) visit({CollisionKind::kParticleParticle, i, j});
    }
    for (int e = 0; e < num_edges; ++e) {
      if (!never_pairs(i, e) && edge_boxes_[e].overlaps(box)) {
        visit({CollisionKind::kParticleEdge, i, e});
      }
    }
    for (int h = 0; h < num_half_planes; ++h) {
      if (near_half_plane(i, h)) visit({CollisionKind::kParticleHalfPlane, i, h});
    }
    for (int s = 0; s < num_spheres; ++s) {
      if (near_sphere(i, s)) visit({CollisionKind::kParticleSphere, i, s});
    }
  }
}

template <int D>
void GridPairs<D>::visit_moving_directly(const PairQuery& query,
                                         const MovingVisitor& visit) const {
  const SceneModel& model = *model_;
  const int n = model.num_particles();
  const int num_edges = static_cast<int>(model.edges.size());
  const int num_half_planes = static_cast<int>(model.half_planes.size());
  const int num_spheres = static_cast<int>(model.spheres.size());
  const auto act = [&](const CandidatePair& pair) {
    const MovedParticles moved = visit(pair);
    for (int m = 0; m < moved.count; ++m) grow_after_move(query, moved.particle[m]);
  };
  // Boxes only grow, so a pair the list would have planned still overlaps when it comes, and
  // one a grown box reaches is found as follow_move would find it.
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      if (particle_boxes_[i].overlaps(particle_boxes_[j])) {
        act({CollisionKind::kParticleParticle, i, j});
      }
    }
    for (int e = 0; e < num_edges; ++e) {
      if (!never_pairs(i, e) && edge_boxes_[e].overlaps(particle_boxes_[i])) {
        act({CollisionKind::kParticleEdge, i, e});
      }
    }
    for (int h = 0; h < num_half_planes; ++h) {
      if (near_half_plane(i, h)) act({CollisionKind::kParticleHalfPlane, i, h});
    }
    for (int s = 0; s < num_spheres; ++s) {
      if (near_sphere(i, s)) act({CollisionKind::kParticleSphere, i, s});
    }
  }
}

template <int D>
void GridPairs<D>::grow_after_move(const PairQuery& query, int p) const {
  const Vec<D> s = particle_vec<D>(query.start, p);
  const Vec<D> e = particle_vec<D>(query.end, p);
  const Box<D> motion = segment_box<D>(s, e);
  if (motion_boxes_[p].contains(motion)) return;
  motion_boxes_[p] = motion_boxes_[p].united(grown(motion, (e - s).norm()));
  particle_boxes_[p] = grown(motion_boxes_[p], larger(model_->particle_radius[p], 0.0) + pad_);
  for (int k = incident_start_[p]; k < incident_start_[p + 1]; ++k) {
    const int edge = incident_edges_[k];
    const Box<D> edge_now = edge_box(edge);
    if (!edge_boxes_[edge].contains(edge_now)) edge_boxes_[edge] = edge_now;
  }
}

template <int D>
void GridPairs<D>::sort_found() const {
  // A counting sort by particle, then each particle's few pairs by kind and index.
  const int n = model_->num_particles();
  bucket_.assign(n + 1, 0);
  for (const CandidatePair& pair : found_) ++bucket_[pair.particle + 1];
  for (int p = 0; p < n; ++p) bucket_[p + 1] += bucket_[p];
  sorted_.resize(found_.size());
  for (const CandidatePair& pair : found_) sorted_[bucket_[pair.particle]++] = pair;
  int begin = 0;
  for (int p = 0; p < n; ++p) {
    const int end = bucket_[p];
    if (end - begin > 1) {
      std::sort(sorted_.begin() + begin, sorted_.begin() + end, precedes_in_course_order);
    }
    begin = end;
  }
  found_.swap(sorted_);
}

template <int D>
bool GridPairs<D>::can_reuse(const PairQuery& query) const {
  if (!reusable_ || query.margin != reused_margin_ || query.start.size() != reference_.size()) {
    return false;
  }
  // Every particle still within the skin of where the pairs were found (false for a NaN).
  for (Eigen::Index k = 0; k < reference_.size(); ++k) {
    if (!(std::abs(query.start[k] - reference_[k]) <= skin_)) return false;
  }
  return true;
}

template <int D>
void GridPairs<D>::for_each(const PairQuery& query, const Visitor& visit) const {
  // Particles that stay put (the penalty force, simple impulses): the pairs found with boxes
  // grown by a skin serve every later query whose particles are still within the skin.
  const bool fixed_positions = &query.start == &query.end;
  if (!(fixed_positions && can_reuse(query))) {
    compute_boxes(query, false, fixed_positions ? skin_ : 0.0);
    build_grids();
    direct_ = !find_all_pairs();
    if (!direct_) sort_found();
    reusable_ = fixed_positions;
    if (reusable_) {
      reference_ = query.start;
      reused_margin_ = query.margin;
    }
  }
  if (direct_) {
    visit_directly(visit);
    return;
  }
  // In the course's order a pair's second particle is anywhere in memory: ask for its position
  // a few pairs ahead, so that large scenes wait less for it.
  constexpr std::size_t kAhead = 8;
  const std::size_t count = found_.size();
  for (std::size_t k = 0; k < count; ++k) {
    if (k + kAhead < count) {
      const CandidatePair& ahead = found_[k + kAhead];
      if (ahead.kind == CollisionKind::kParticleParticle) {
        __builtin_prefetch(query.start.data() + D * ahead.other);
      }
    }
    visit(found_[k]);
  }
}

template <int D>
void GridPairs<D>::for_each_moving(const PairQuery& query, const MovingVisitor& visit) const {
  reusable_ = false;  // found_ and the grids change below
  compute_boxes(query, true);
  build_grids();
  direct_ = !find_all_pairs();
  if (direct_) {
    visit_moving_directly(query, visit);
    return;
  }
  sort_found();
  planned_.swap(found_);
  const int n = model_->num_particles();
  const int num_edges = static_cast<int>(model_->edges.size());
  escaped_particle_.assign(n, 0);
  escaped_edge_.assign(num_edges, 0);
  escaped_particles_.clear();
  escaped_edges_.clear();
  later_.clear();
  const std::size_t rebuild_after =
      32 + static_cast<std::size_t>(std::sqrt(static_cast<double>(n + num_edges)));

  std::size_t k = 0;
  bool visited_any = false;
  CandidatePair last;
  while (true) {
    CandidatePair pair;
    if (k < planned_.size() && (later_.empty() || !comes_later(planned_[k], later_.front()))) {
      pair = planned_[k++];
    } else if (!later_.empty()) {
      std::pop_heap(later_.begin(), later_.end(), comes_later);
      pair = later_.back();
      later_.pop_back();
    } else {
      break;
    }
    if (visited_any && pair == last) continue;  // found twice
    visited_any = true;
    last = pair;
    const MovedParticles moved = visit(pair);
    for (int m = 0; m < moved.count; ++m) follow_move(query, moved.particle[m], pair);
    if (escaped_particles_.size() + escaped_edges_.size() > rebuild_after) {
      // File the grown boxes afresh rather than scan a long list of escaped ones.
      build_grids();
      for (int p : escaped_particles_) escaped_particle_[p] = 0;
      for (int e : escaped_edges_) escaped_edge_[e] = 0;
      escaped_particles_.clear();
      escaped_edges_.clear();
    }
  }
}

template <int D>
void GridPairs<D>::follow_move(const PairQuery& query, int p, const CandidatePair& current) const {
  const Vec<D> s = particle_vec<D>(query.start, p);
  const Vec<D> e = particle_vec<D>(query.end, p);
  const Box<D> motion = segment_box<D>(s, e);
  if (motion_boxes_[p].contains(motion)) return;
  const auto consider = [&](const CandidatePair& pair) {
    if (precedes_in_course_order(current, pair)) {
      later_.push_back(pair);
      std::push_heap(later_.begin(), later_.end(), comes_later);
    }
  };
  motion_boxes_[p] = motion_boxes_[p].united(grown(motion, (e - s).norm()));
  particle_boxes_[p] = grown(motion_boxes_[p], larger(model_->particle_radius[p], 0.0) + pad_);
  if (!escaped_particle_[p]) {
    escaped_particle_[p] = 1;
    escaped_particles_.push_back(p);
  }
  // p's new partners: through the grids for boxes still where they were filed, directly for
  // boxes that grew since.
  const Box<D>& box = particle_boxes_[p];
  const auto particle_pair = [&](int b) {
    consider({CollisionKind::kParticleParticle, std::min(p, b), std::max(p, b)});
  };
  particle_grid_.query(box, 0, [&](int b) {
    if (b != p && !escaped_particle_[b]) particle_pair(b);
  });
  for (int b : escaped_particles_) {
    if (b != p && particle_boxes_[b].overlaps(box)) particle_pair(b);
  }
  edge_grid_.query(box, 0, [&](int edge) {
    if (!escaped_edge_[edge] && !never_pairs(p, edge)) {
      consider({CollisionKind::kParticleEdge, p, edge});
    }
  });
  for (int edge : escaped_edges_) {
    if (!never_pairs(p, edge) && edge_boxes_[edge].overlaps(box)) {
      consider({CollisionKind::kParticleEdge, p, edge});
    }
  }
  found_.clear();
  find_obstacles(p);
  for (const CandidatePair& pair : found_) consider(pair);
  // The edges p is an end of grew with it.
  for (int k = incident_start_[p]; k < incident_start_[p + 1]; ++k) {
    const int edge = incident_edges_[k];
    const Box<D> edge_now = edge_box(edge);
    if (edge_boxes_[edge].contains(edge_now)) continue;
    edge_boxes_[edge] = edge_now;
    if (!escaped_edge_[edge]) {
      escaped_edge_[edge] = 1;
      escaped_edges_.push_back(edge);
    }
    const auto edge_pair = [&](int a) {
      if (!never_pairs(a, edge)) consider({CollisionKind::kParticleEdge, a, edge});
    };
    particle_grid_.query(edge_now, 0, [&](int a) {
      if (!escaped_particle_[a]) edge_pair(a);
    });
    for (int a : escaped_particles_) {
      if (particle_boxes_[a].overlaps(edge_now)) edge_pair(a);
    }
  }
}

template class GridPairs<2>;
template class GridPairs<3>;

}  // namespace fosssim
