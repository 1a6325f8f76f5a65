#include "core/collisions/continuous_time_collisions.h"

#include <array>

#include "core/collisions/course_swept.h"
#include "core/collisions/impulses.h"
#include "core/collisions/swept_detection.h"

namespace fosssim {

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
    record.collisions.push_back(
        CollisionRecord{pair.kind, pair.particle, pair.other, Vector(s.n), hit->time});
    if constexpr (D == 2) {
      return respond_course_swept(model, pair, s, xs, h, cor, state);  // the course's arithmetic
    } else {
      const Impulse<D> impulse =
          compute_impulse<D>(model, pair, s.n, s.alpha, displacement_velocity, cor);
      for (int k = 0; k < impulse.count; ++k) {
        const int p = impulse.particle[k];
        state.v.template segment<D>(D * p) += impulse.dv[k];
        state.q.template segment<D>(D * p) += h * impulse.dv[k];
        moved.particle[moved.count++] = p;
      }
      return moved;
    }
  });
  record.sync = SyncPoint{state.q, state.v, record.polynomials.size()};
}

template class ContinuousTimeStage<2>;
template class ContinuousTimeStage<3>;

namespace {
constexpr std::array kContinuousTimeOptionSpecs = {
    particle_contact_options::restitution(
        "coefficient of restitution: 1 elastic, 0 inelastic (outside [0, 1] with a warning)"),
};
}  // namespace

constinit const ContactMethod kContinuousTimeContactMethod{
    .name = "continuous-time",
    .summary = "swept detection over each step (polynomial roots), impulses pair by pair",
    .options = kContinuousTimeOptionSpecs,
    .scope = kParticlesIn2DAnd3D,
    .records = StepRecordLayout::kCollisionsAndPolynomials,
    .make_stage = [](const SceneModel& model) -> std::unique_ptr<StepStage> {
      if (model.dim == 3) return std::make_unique<ContinuousTimeStage<3>>(model);
      return std::make_unique<ContinuousTimeStage<2>>(model);
    },
};

}  // namespace fosssim
