#pragma once
// The ParticleFountain scene tag (docs/viewing.md): tagged particles that fall too low come back.

#include <cstdint>
#include <vector>

#include "core/step/step_stage.h"

namespace fosssim {

/// After every step, each particle tagged `teleport` whose height (coordinate 1, y) is below
/// -1.25 returns to the origin with a random upward velocity: horizontal components uniform in
/// [-1, 1) m/s, vertical component uniform in [4, 6) m/s.
///
/// The random numbers are a hash of (seed, step, particle, component) (splitmix64), not a
/// random stream, so the velocity a particle receives depends only on when and which particle
/// it is: a rerun, the window and the grader's step-by-step replay agree bit for bit.
class ParticleFountain final : public StepStage {
 public:
  static constexpr const char* kTag = "ParticleFountain";
  static constexpr const char* kParticleTag = "teleport";
  static constexpr double kFloorHeight = -1.25;
  static constexpr double kMaxSidewaysSpeed = 1.0;
  static constexpr double kMinUpwardSpeed = 4.0;
  static constexpr double kMaxUpwardSpeed = 6.0;
  static constexpr std::uint64_t kDefaultSeed = 0x466f756e7461696eULL;  // "Fountain"

  /// teleported: indices of the particles tagged `teleport`.
  explicit ParticleFountain(std::vector<int> teleported, std::uint64_t seed = kDefaultSeed);

  void apply(const StepContext& context, State& state) override;

  /// The launch velocity particle `particle` receives at step `step` (dim components).
  Vector launch_velocity(int dim, std::int64_t step, int particle) const;

 private:
  std::vector<int> teleported_;
  std::uint64_t seed_;
};

/// A number uniform in [0, 1) that depends only on its four arguments (splitmix64 hashing).
double hashed_uniform(std::uint64_t seed, std::int64_t step, int particle, int component);

}  // namespace fosssim
