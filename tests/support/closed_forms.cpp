#include "support/closed_forms.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "support/random.h"

namespace fosssim::testing {

FallingParticle::FallingParticle(int dim, unsigned seed) {
  Random random(seed);
  x = random.uniform_vector(dim, -1.0, 1.0);
  w = random.uniform_vector(dim, -1.0, 1.0);
  g = random.uniform_vector(dim, -10.0, 10.0);
}

TestScene FallingParticle::scene(std::string_view kind, double h) const {
  TestScene out(static_cast<int>(x.size()), kind, h);
  out.add_particle(2.0, x, w);
  out.add_simple_gravity(g);
  return out;
}

AnchoredSpring::AnchoredSpring(int dim, unsigned seed, double m, double k, double l0, double b,
                               double c)
    : m(m), k(k), l0(l0), b(b), c(c) {
  Random random(seed);
  a = random.uniform_vector(dim, -1.0, 1.0);
  u = random.uniform_vector(dim, -1.0, 1.0);
  x = random.uniform_vector(dim, -1.0, 1.0);
  w = random.uniform_vector(dim, -1.0, 1.0);
}

TestScene AnchoredSpring::scene(std::string_view kind, double h) const {
  TestScene out(static_cast<int>(a.size()), kind, h);
  out.add_particle(5.0, a, u, /*fixed=*/true);
  out.add_particle(m, x, w);
  out.add_spring(0, 1, k, l0, b);
  out.add_drag(c);
  return out;
}

void AnchoredSpring::expect_step(const State& next, double h, const Vector& x_expected,
                                 const Vector& v_expected, double tolerance) const {
  const int dim = static_cast<int>(a.size());
  expect_close(next.q.head(dim), a + h * u, 1e-15, "fixed particle's position");
  EXPECT_EQ(Vector(next.v.head(dim)), u) << "a fixed particle keeps its velocity exactly";
  expect_close(next.v.tail(dim), v_expected, tolerance, "free particle's velocity");
  expect_close(next.q.tail(dim), x_expected, tolerance, "free particle's position");
}

TestScene LinearAnchoredSystem::scene(std::string_view kind) const {
  TestScene out(static_cast<int>(a.size()), kind, h);
  out.add_particle(3.0, a, u, /*fixed=*/true);
  out.add_particle(m, x, w);
  out.add_spring(0, 1, k, 0.0);
  out.add_drag(c);
  return out;
}

State LinearAnchoredSystem::backward_euler_step() const {
  const int dim = static_cast<int>(a.size());
  const Vector v = (m * w - h * k * (x - a) + h * h * k * u) / (m + h * c + h * h * k);
  State out;
  out.q.resize(2 * dim);
  out.v.resize(2 * dim);
  out.q << a + h * u, x + h * v;
  out.v << u, v;
  return out;
}

TestScene LinearPairSystem::scene(std::string_view kind) const {
  TestScene out(static_cast<int>(xa.size()), kind, h);
  out.add_particle(m, xa, va);
  out.add_particle(m, xb, vb);
  out.add_spring(0, 1, k, 0.0);
  out.add_drag(c);
  return out;
}

State LinearPairSystem::backward_euler_step() const {
  const int dim = static_cast<int>(xa.size());
  const Vector s = m * (va + vb) / (m + h * c);
  const Vector r = (m * (vb - va) - 2.0 * h * k * (xb - xa)) / (m + h * c + 2.0 * h * h * k);
  State out;
  out.q.resize(2 * dim);
  out.v.resize(2 * dim);
  out.v << 0.5 * (s - r), 0.5 * (s + r);
  out.q << xa + h * out.v.head(dim), xb + h * out.v.tail(dim);
  return out;
}

Vector linear_momentum(const SceneModel& model, const Vector& v) {
  Vector p = Vector::Zero(model.dim);
  for (int particle = 0; particle < model.num_particles(); ++particle) {
    p += model.mass[model.dim * particle] * v.segment(model.dim * particle, model.dim);
  }
  return p;
}

void expect_close(const Vector& actual, const Vector& expected, double tolerance,
                  const std::string& what) {
  ASSERT_EQ(actual.size(), expected.size()) << what;
  const double error = (actual - expected).lpNorm<Eigen::Infinity>();
  const double scale = std::max(1.0, expected.lpNorm<Eigen::Infinity>());
  EXPECT_LE(error, tolerance * scale)
      << what << "\n  actual:   " << actual.transpose() << "\n  expected: " << expected.transpose();
}

Vector spring_force_on_j(const Vector& xi, const Vector& xj, const Vector& vi, const Vector& vj,
                         double k, double l0, double b) {
  const Vector d = xj - xi;
  const double l = d.norm();
  const Vector n = d / l;
  return -k * (l - l0) * n - b * n.dot(vj - vi) * n;
}

Mat<3> cross_product_matrix(const Vec<3>& a) {
  Mat<3> R;
  R << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return R;
}

}  // namespace fosssim::testing
