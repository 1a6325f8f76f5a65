#include "core/integrators/symplectic_euler.h"

#include <array>
#include <string_view>

#include "core/force_evaluation.h"
#include "core/velocity_step.h"

namespace fosssim {

void SymplecticEuler::advance(State& state) {
  const double h = model().integrator.dt;
  Vector force = compute_force(forces(), state.q, state.v);
  zero_fixed(model(), force);
  add_velocity_step(model(), h, force, state.v);
  state.q += h * state.v;
}

namespace {
constexpr std::array<std::string_view, 2> kSymplecticEulerAliases = {"forward-backward-euler",
                                                                     "semi-implicit-euler"};
}  // namespace

constinit const IntegratorMethod kSymplecticEulerMethod{
    .name = "symplectic-euler",
    .aliases = kSymplecticEulerAliases,
    .summary = "symplectic (forward-backward) Euler: velocity first, then position",
    .properties = {.order = 1, .course_reference = true, .energy = EnergyTrend::kBounded},
    .create = [](const OptionValues&, int) -> std::unique_ptr<Integrator> {
      return std::make_unique<SymplecticEuler>();
    },
};

}  // namespace fosssim
