#include "support/random.h"

namespace fosssim::testing {

Vector Random::unit_vector(int n) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Vector out(n);
  for (int k = 0; k < n; ++k) out[k] = normal(rng_);
  return out.normalized();
}

PairCase random_pair_case(int dim, Random& random) {
  PairCase out;
  out.q = random.uniform_vector(3 * dim, -1.0, 1.0);
  out.v = random.uniform_vector(3 * dim, -1.0, 1.0);
  out.mass.resize(3 * dim);
  for (int p = 0; p < 3; ++p) out.mass.segment(dim * p, dim).setConstant(random.uniform(0.5, 2.0));
  out.i = random.index(3);
  out.j = (out.i + 1 + random.index(2)) % 3;
  return out;
}

PairCase pair_at_distance(int dim, Random& random, double l) {
  PairCase out;
  const Vector c = random.uniform_vector(dim, -1.0, 1.0);
  out.q.resize(3 * dim);
  out.q << c, c + l * random.unit_vector(dim), c + random.unit_vector(dim);
  out.v = random.uniform_vector(3 * dim, -1.0, 1.0);
  out.mass = Vector::Ones(3 * dim);
  return out;
}

TestScene random_spring_chain(int dim, Random& random) {
  TestScene scene(dim, "implicit-euler", 0.05);
  for (int p = 0; p < 4; ++p) {
    const double m = random.uniform(0.5, 2.0);
    const Vector x = random.uniform_vector(dim, -1.0, 1.0);
    const Vector v = random.uniform_vector(dim, -1.0, 1.0);
    scene.add_particle(m, x, v, p == 1);
  }
  scene.add_spring(0, 1, 5.0, 0.3);
  scene.add_spring(1, 2, 2.0, 1.5);
  scene.add_spring(2, 3, 7.0, 0.0);
  return scene;
}

}  // namespace fosssim::testing
