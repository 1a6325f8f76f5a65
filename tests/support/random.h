#pragma once
// Random test data, deterministic for a seed: numbers, vectors, and configurations of particles
// for pair forces.

#include <random>

#include "core/types.h"
#include "support/scene_builder.h"

namespace fosssim::testing {

/// Uniform random numbers in [lo, hi), deterministic for a seed.
class Random {
 public:
  explicit Random(unsigned seed) : rng_(seed) {}
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  Vector uniform_vector(int n, double lo, double hi) {
    Vector out(n);
    for (int k = 0; k < n; ++k) out[k] = uniform(lo, hi);
    return out;
  }
  /// A uniformly distributed unit vector of size n. Defined in random.cpp, not here: inlined
  /// into a caller with a constant n (2 or 3), GCC 12 followed Eigen's two-double loads of the
  /// norm past the end of the n-double allocation it could then see (a -Warray-bounds false
  /// positive: Eigen never reads there at run time).
  Vector unit_vector(int n);
  int index(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }

 private:
  std::mt19937 rng_;
};

/// Three particles for testing a pair force (i, j): positions, velocities, per-DOF masses.
struct PairCase {
  Vector q, v, mass;
  int i = 0, j = 1;
};

/// Random positions and velocities in [-1, 1)ᵈ, masses in [0.5, 2) and a random pair.
PairCase random_pair_case(int dim, Random& random);

/// i = 0 at c and j = 1 at c + l u (c random in [-1, 1)ᵈ, u a random unit vector), a bystander
/// 2 at distance 1 from c; velocities random in [-1, 1)ᵈ, unit masses.
PairCase pair_at_distance(int dim, Random& random, double l);

/// Four particles of masses in [0.5, 2) at random places in [-1, 1)ᵈ with random velocities in
/// [-1, 1)ᵈ, the second fixed, joined in a chain by undamped springs (k, l0) = (5, 0.3) from 0
/// to 1, (2, 1.5) from 1 to 2 and (7, 0) from 2 to 3; implicit Euler with dt = 0.05.
TestScene random_spring_chain(int dim, Random& random);

}  // namespace fosssim::testing
