#include "core/integrators/integrator.h"

#include <stdexcept>

namespace fosssim {

void Integrator::precompute(const SceneModel& model, std::vector<const Force*> interaction) {
  if (is_bound()) throw std::logic_error("an integrator is bound to one model only");
  forces_.emplace(model, std::move(interaction));
  dt_ = model.integrator.dt;
  prepare();
}

void Integrator::step(State& state) {
  if (!is_bound()) throw std::logic_error("Integrator::step before precompute");
  if (state.q.size() != model().num_dofs() || state.v.size() != model().num_dofs()) {
    throw std::logic_error("Integrator::step: the state does not have the model's size");
  }
  if (model().integrator.dt != dt_) {
    throw std::logic_error("Integrator::step: the model's time step changed after precompute");
  }
  advance(state);
  ++state.step;
  state.time = static_cast<double>(state.step) * model().integrator.dt;
}

std::unique_ptr<Integrator> make_integrator(const SceneModel& model,
                                            std::vector<const Force*> interaction) {
  const IntegratorSettings& settings = model.integrator;
  std::unique_ptr<Integrator> integrator = settings.method->create(settings.options, model.dim);
  integrator->precompute(model, std::move(interaction));
  return integrator;
}

}  // namespace fosssim
