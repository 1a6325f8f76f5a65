#include "core/collisions/hybrid_collisions.h"

#include <array>
#include <stdexcept>
#include <vector>

#include "core/collisions/impact_zones.h"
#include "core/collisions/impulses.h"
#include "core/collisions/penalty_force.h"
#include "core/collisions/swept_detection.h"

namespace fosssim {

namespace {

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

namespace {
namespace options = particle_contact_options;
constexpr std::array kHybridOptionSpecs = {
    options::restitution("coefficient of restitution of the impulse passes: 1 elastic, 0 "
                         "inelastic (outside [0, 1] with a warning)"),
    options::stiffness(10.0),
    options::thickness(0.1),
    options::penalty_jacobian(),
    options::max_iterations(10.0),
};
}  // namespace

constinit const ContactMethod kHybridContactMethod{
    .name = "hybrid",
    .summary = "penalty force, Jacobi passes of swept impulses, then rigid impact zones",
    .options = kHybridOptionSpecs,
    .scope = {.particles = true,
              .runs_2d = true,
              .runs_3d = false,
              .restriction = "its rigid impact zones rotate in the plane"},
    .records = StepRecordLayout::kCollisionsAndPolynomials,
    .make_stage = [](const SceneModel& model) -> std::unique_ptr<StepStage> {
      if (model.dim == 3) throw std::logic_error("hybrid collision handling is 2D only");
      return std::make_unique<HybridStage>(model);
    },
    .make_force = make_penalty_force,
};

}  // namespace fosssim
