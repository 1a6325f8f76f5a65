#include "core/collisions/collision_stages.h"

#include <stdexcept>
#include <vector>

#include "core/collisions/impact_zones.h"
#include "core/collisions/impulses.h"
#include "core/collisions/proximity.h"
#include "core/collisions/swept_detection.h"

namespace fosssim {

namespace {

template <int D>
CollisionRecord make_record(const CandidatePair& pair, const Vec<D>& n, double time) {
  return CollisionRecord{pair.kind, pair.particle, pair.other, Vector(n), time};
}

/// A collision found by a detection pass of hybrid handling, with what its response needs.
struct PassCollision {
  CandidatePair pair;
  SweptCollision<2> hit;
};

/// One detection pass over every pair from xs to x, logging the polynomials; `found` (cleared
/// first, its memory reused) gets the collisions.
void detect_all(const SceneModel& model, const CandidatePairs& pairs, const Vector& xs,
                const Vector& x, StepRecord& record, std::vector<PassCollision>& found) {
  found.clear();
  for_each_in_course_order(pairs, PairQuery{xs, x, 0.0}, [&](const CandidatePair& pair) {
    if (auto hit = detect_swept<2>(model, pair, xs, x, &record.polynomials)) {
      found.push_back({pair, *hit});
    }
  });
}

}  // namespace

// ---- simple ------------------------------------------------------------------------------------

template <int D>
SimpleCollisionStage<D>::SimpleCollisionStage(const SceneModel& model)
    : pairs_(make_candidate_pairs(model)) {}

template <int D>
void SimpleCollisionStage<D>::apply(const StepContext& context, State& state) {
  const SceneModel& model = context.model;
  const double cor = model.collisions.cor;
  const auto velocity_of = [&state](int p) -> Vec<D> { return particle_vec<D>(state.v, p); };
  for_each_in_course_order(
      *pairs_, PairQuery{state.q, state.q, 0.0}, [&](const CandidatePair& pair) {
        const Separation<D> s = simple_separation<D>(model, pair, state.q);
        if (!is_colliding<D>(model, pair, s, state.v)) return;
        context.record.collisions.push_back(make_record<D>(pair, s.n, 0.0));
        const Impulse<D> impulse = compute_impulse<D>(model, pair, s.n, s.alpha, velocity_of, cor);
        for (int k = 0; k < impulse.count; ++k) {
          state.v.template segment<D>(D * impulse.particle[k]) += impulse.dv[k];
        }
      });
}

// ---- continuous-time ---------------------------------------------------------------------------

template <int D>
ContinuousTimeStage<D>::ContinuousTimeStage(const SceneModel& model)
    : pairs_(make_candidate_pairs(model)) {}

template <int D>
void ContinuousTimeStage<D>::apply(const StepContext& context, State& state) {
  const SceneModel& model = context.model;
  const Vector& xs = context.start.q;
  const double h = context.h;
  const double cor = model.collisions.cor;
  const auto displacement_velocity = [&](int p) -> Vec<D> {
    return (particle_vec<D>(state.q, p) - particle_vec<D>(xs, p)) / h;
  };
  StepRecord& record = context.record;
  // The responses move particles, which later pairs must see: a moving query.
  pairs_->for_each_moving(PairQuery{xs, state.q, 0.0}, [&](const CandidatePair& pair) {
    MovedParticles moved;
    const auto hit = detect_swept<D>(model, pair, xs, state.q, &record.polynomials);
    if (!hit) return moved;
    const Separation<D>& s = hit->separation;
    record.collisions.push_back(make_record<D>(pair, s.n, hit->time));
    const Impulse<D> impulse =
        compute_impulse<D>(model, pair, s.n, s.alpha, displacement_velocity, cor);
    for (int k = 0; k < impulse.count; ++k) {
      const int p = impulse.particle[k];
      state.v.template segment<D>(D * p) += impulse.dv[k];
      state.q.template segment<D>(D * p) += h * impulse.dv[k];
      moved.particle[moved.count++] = p;
    }
    return moved;
  });
  record.sync = SyncPoint{state.q, state.v, record.polynomials.size()};
}

// ---- hybrid ------------------------------------------------------------------------------------

HybridStage::HybridStage(const SceneModel& model) : pairs_(make_candidate_pairs(model)) {}

void HybridStage::apply(const StepContext& context, State& state) {
  const SceneModel& model = context.model;
  const Vector& xs = context.start.q;
  const double h = context.h;
  const double cor = model.collisions.cor;
  StepRecord& record = context.record;
  Vector& q = state.q;
  Vector& v = state.v;

  // Impulse passes (Jacobi): detect everything, then answer from the pass's start. The
  // buffers are reused from pass to pass: only the log grows with the passes, and their number
  // is capped when the scene is read (io/collision_elements.cpp).
  bool resolved = false;
  std::vector<PassCollision> found;
  Vector q_next, v_next;
  for (int pass = 0; pass < model.collisions.max_iterations; ++pass) {
    context.cancellation.check();
    detect_all(model, *pairs_, xs, q, record, found);
    if (found.empty()) {
      resolved = true;
      break;
    }
    q_next = q;
    v_next = v;
    const auto displacement_velocity = [&](int p) -> Vec<2> {
      return (q.segment<2>(2 * p) - xs.segment<2>(2 * p)) / h;
    };
    for (const PassCollision& c : found) {
      const Separation<2>& s = c.hit.separation;
      const Impulse<2> impulse =
          compute_impulse<2>(model, c.pair, s.n, s.alpha, displacement_velocity, cor);
      for (int k = 0; k < impulse.count; ++k) {
        const int p = impulse.particle[k];
        v_next.segment<2>(2 * p) += impulse.dv[k];
        q_next.segment<2>(2 * p) += h * impulse.dv[k];
      }
    }
    q.swap(q_next);
    v.swap(v_next);
  }
  record.sync = SyncPoint{q, v, record.polynomials.size()};
  if (resolved) return;

  // Geometric stage: rigid impact zones, grown until detection adds none.
  // Zones only grow (each pass adds a particle, merges two zones or flags one), so this ends
  // within three passes per particle.
  const auto zones_of = [&](std::vector<ImpactZone> zones) {
    detect_all(model, *pairs_, xs, q, record, found);
    for (const PassCollision& c : found) zones.push_back(impact_zone_of(model, c.pair));
    return merge_impact_zones(std::move(zones));
  };
  std::vector<ImpactZone> zones = zones_of({});
  while (true) {
    context.cancellation.check();
    for (const ImpactZone& zone : zones) apply_rigid_failsafe(model, zone, xs, h, q, v);
    std::vector<ImpactZone> grown = zones_of(zones);
    if (grown == zones) break;
    zones = std::move(grown);
  }
}

// ---- factory -----------------------------------------------------------------------------------

std::unique_ptr<StepStage> make_collision_stage(const SceneModel& model) {
  const bool three = model.dim == 3;
  switch (model.collisions.method) {
    case CollisionMethod::kSimple:
      if (three) return std::make_unique<SimpleCollisionStage<3>>(model);
      return std::make_unique<SimpleCollisionStage<2>>(model);
    case CollisionMethod::kContinuousTime:
      if (three) return std::make_unique<ContinuousTimeStage<3>>(model);
      return std::make_unique<ContinuousTimeStage<2>>(model);
    case CollisionMethod::kHybrid:
      if (three) throw std::logic_error("hybrid collision handling is 2D only");
      return std::make_unique<HybridStage>(model);
    case CollisionMethod::kNone:
    case CollisionMethod::kPenalty:
      break;
  }
  return nullptr;
}

std::string_view collision_method_name(CollisionMethod method) {
  switch (method) {
    case CollisionMethod::kNone:
      return "none";
    case CollisionMethod::kSimple:
      return "simple";
    case CollisionMethod::kPenalty:
      return "penalty";
    case CollisionMethod::kContinuousTime:
      return "continuous-time";
    case CollisionMethod::kHybrid:
      return "hybrid";
  }
  return "none";
}

template class SimpleCollisionStage<2>;
template class SimpleCollisionStage<3>;
template class ContinuousTimeStage<2>;
template class ContinuousTimeStage<3>;

}  // namespace fosssim
