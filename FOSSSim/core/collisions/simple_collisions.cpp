#include "core/collisions/simple_collisions.h"

#include <array>

#include "core/collisions/impulses.h"
#include "core/collisions/proximity.h"

namespace fosssim {

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
        context.record.collisions.push_back(
            CollisionRecord{pair.kind, pair.particle, pair.other, Vector(s.n), 0.0});
        const Impulse<D> impulse = compute_impulse<D>(model, pair, s.n, s.alpha, velocity_of, cor);
        for (int k = 0; k < impulse.count; ++k) {
          state.v.template segment<D>(D * impulse.particle[k]) += impulse.dv[k];
        }
      });
}

template class SimpleCollisionStage<2>;
template class SimpleCollisionStage<3>;

namespace {
constexpr std::array kSimpleOptionSpecs = {
    particle_contact_options::restitution(
        "coefficient of restitution: 1 elastic, 0 inelastic (outside [0, 1] with a warning)"),
};
}  // namespace

constinit const ContactMethod kSimpleContactMethod{
    .name = "simple",
    .summary = "discrete detection at the end of each step, impulses pair by pair",
    .options = kSimpleOptionSpecs,
    .scope = kParticlesIn2DAnd3D,
    .records = StepRecordLayout::kCollisions,
    .make_stage = [](const SceneModel& model) -> std::unique_ptr<StepStage> {
      if (model.dim == 3) return std::make_unique<SimpleCollisionStage<3>>(model);
      return std::make_unique<SimpleCollisionStage<2>>(model);
    },
};

}  // namespace fosssim
