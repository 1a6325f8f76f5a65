#include "scripting/particle_fountain.h"

namespace fosssim {

namespace {
/// The finalizer of splitmix64 (Steele, Lea and Flood 2014): a bijective 64-bit mix.
std::uint64_t mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
}  // namespace

double hashed_uniform(std::uint64_t seed, std::int64_t step, int particle, int component) {
  std::uint64_t h = mix(seed ^ static_cast<std::uint64_t>(step));
  h = mix(h ^ static_cast<std::uint64_t>(static_cast<std::uint32_t>(particle)));
  h = mix(h ^ static_cast<std::uint64_t>(component));
  return static_cast<double>(h >> 11) * 0x1.0p-53;  // the top 53 bits, exactly representable
}

ParticleFountain::ParticleFountain(std::vector<int> teleported, std::uint64_t seed)
    : teleported_(std::move(teleported)), seed_(seed) {}

Vector ParticleFountain::launch_velocity(int dim, std::int64_t step, int particle) const {
  Vector v(dim);
  for (int c = 0; c < dim; ++c) {
    const double u = hashed_uniform(seed_, step, particle, c);
    v[c] = c == 1 ? kMinUpwardSpeed + (kMaxUpwardSpeed - kMinUpwardSpeed) * u
                  : kMaxSidewaysSpeed * (2.0 * u - 1.0);
  }
  return v;
}

void ParticleFountain::apply(const StepContext& context, State& state) {
  const SceneModel& model = context.model;
  const int dim = model.dim;
  for (int p : teleported_) {
    if (!(state.q[dim * p + 1] < kFloorHeight)) continue;
    state.q.segment(dim * p, dim).setZero();
    state.v.segment(dim * p, dim) = launch_velocity(dim, state.step, p);
  }
}

}  // namespace fosssim
