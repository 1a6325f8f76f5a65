#include "support/test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <tuple>

#include "core/analysis/derivative_check.h"
#include "core/forces/drag_damping_force.h"
#include "core/forces/gravitational_force.h"
#include "core/forces/make_for_dim.h"
#include "core/forces/simple_gravity_force.h"
#include "core/forces/spring_force.h"

namespace fosssim::testing {

void TestScene::add_spring(int i, int j, double k, double l0, double b) {
  model.edges.push_back({i, j});
  add_force(make_for_dim<SpringForce>(model.dim, i, j, k, l0, b));
}

void TestScene::add_gravitation(int i, int j, double G) {
  add_force(make_for_dim<GravitationalForce>(model.dim, i, j, G));
}

void TestScene::add_drag(double b) { add_force(make_for_dim<DragDampingForce>(model.dim, b)); }

void TestScene::add_simple_gravity(const Vector& g) {
  if (model.dim == 3) {
    add_force(std::make_unique<SimpleGravityForce<3>>(Vec<3>(g)));
  } else {
    add_force(std::make_unique<SimpleGravityForce<2>>(Vec<2>(g)));
  }
}

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

State run_steps(const SceneModel& model, State state, std::int64_t steps) {
  const auto integrator = make_integrator(model);
  for (std::int64_t s = 0; s < steps; ++s) integrator->step(state);
  return state;
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

double asymmetry(const Eigen::MatrixXd& A) {
  const double norm = A.norm();
  return norm > 0.0 ? (A - A.transpose()).norm() / norm : 0.0;
}

Eigen::MatrixXd dense_pair_pattern(int n, int dim, int i, int j, const Eigen::MatrixXd& H) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n, n);
  out.block(dim * i, dim * i, dim, dim) += H;
  out.block(dim * j, dim * j, dim, dim) += H;
  out.block(dim * i, dim * j, dim, dim) -= H;
  out.block(dim * j, dim * i, dim, dim) -= H;
  return out;
}

Mat<3> cross_product_matrix(const Vec<3>& a) {
  Mat<3> R;
  R << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return R;
}

Vector gradient_of(const Force& force, const Vector& q, const Vector& v, const Vector& mass) {
  Vector g = Vector::Zero(q.size());
  force.add_gradient({q, v, mass}, g);
  return g;
}

double energy_of(const Force& force, const Vector& q, const Vector& v, const Vector& mass) {
  double energy = 0.0;
  force.add_energy({q, v, mass}, energy);
  return energy;
}

Eigen::MatrixXd hessian_x_of(const Force& force, const Vector& q, const Vector& v,
                             const Vector& mass) {
  HessianBuilder builder;
  force.add_hessian_x({q, v, mass}, builder);
  return dense(builder.build(static_cast<int>(q.size())));
}

Eigen::MatrixXd hessian_v_of(const Force& force, const Vector& q, const Vector& v,
                             const Vector& mass) {
  HessianBuilder builder;
  force.add_hessian_v({q, v, mass}, builder);
  return dense(builder.build(static_cast<int>(q.size())));
}

namespace {

/// Perturbs coordinate k of x by ±t and returns both points and the actual step between them.
struct Perturbation {
  Vector plus, minus;
  double step;
};

Perturbation perturb(const Vector& x, int k, double t) {
  Perturbation p{x, x, 0.0};
  p.plus[k] = x[k] + t;
  p.minus[k] = x[k] - t;
  p.step = p.plus[k] - p.minus[k];  // exact: the two numbers are within a factor of 2
  return p;
}

MatrixComparison compare(const Eigen::MatrixXd& analytic, const Eigen::MatrixXd& numeric) {
  return {(analytic - numeric).norm(), std::max(analytic.norm(), numeric.norm()), 0.0};
}

}  // namespace

MatrixComparison compare_hessian_full(const Force& force, const Vector& q, const Vector& v,
                                      const Vector& mass, bool in_velocity, double t) {
  const int n = static_cast<int>(q.size());
  Eigen::MatrixXd numeric(n, n);
  for (int k = 0; k < n; ++k) {
    const Perturbation p = perturb(in_velocity ? v : q, k, t);
    const Vector g_plus =
        in_velocity ? gradient_of(force, q, p.plus, mass) : gradient_of(force, p.plus, v, mass);
    const Vector g_minus =
        in_velocity ? gradient_of(force, q, p.minus, mass) : gradient_of(force, p.minus, v, mass);
    numeric.col(k) = (g_plus - g_minus) / p.step;
  }
  const Eigen::MatrixXd analytic =
      in_velocity ? hessian_v_of(force, q, v, mass) : hessian_x_of(force, q, v, mass);
  return compare(analytic, numeric);
}

MatrixComparison compare_gradient_full(const Force& force, const Vector& q, const Vector& mass,
                                       double t) {
  const int n = static_cast<int>(q.size());
  const Vector rest = Vector::Zero(n);
  const auto central = [&](int k, double step) {
    const Perturbation p = perturb(q, k, step);
    return (energy_of(force, p.plus, rest, mass) - energy_of(force, p.minus, rest, mass)) / p.step;
  };
  Vector numeric(n);
  for (int k = 0; k < n; ++k) numeric[k] = (4.0 * central(k, 0.5 * t) - central(k, t)) / 3.0;
  MatrixComparison result = compare(gradient_of(force, q, rest, mass), numeric);
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  const double curvature = hessian_x_of(force, q, rest, mass).norm();
  result.noise_floor =
      100.0 * kEps * std::sqrt(static_cast<double>(n)) *
      (std::abs(energy_of(force, q, rest, mass)) / t + curvature * q.lpNorm<Eigen::Infinity>());
  return result;
}

double shortest_distance(const Vector& q, int dim) {
  const int n = static_cast<int>(q.size()) / dim;
  double shortest = std::numeric_limits<double>::infinity();
  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) {
      shortest = std::min(shortest, (q.segment(dim * a, dim) - q.segment(dim * b, dim)).norm());
    }
  }
  return shortest;
}

double configuration_length(const Vector& q, int dim) {
  const double shortest = shortest_distance(q, dim);
  return shortest > 0.0 ? std::min(1.0, shortest) : 1.0;
}

// ---------------------------------------------------------------------------------------------

namespace {

using ErrorKey = std::tuple<std::string, int, std::string, std::string, std::string>;

struct WorstCase {
  double error = -1.0;
  std::string detail;  ///< the configuration that produced it
};

std::map<ErrorKey, WorstCase>& error_table() {
  static std::map<ErrorKey, WorstCase> table;
  return table;
}

/// Prints the table of largest relative errors when the test program ends.
class ErrorTablePrinter : public ::testing::Environment {
 public:
  void TearDown() override {
    if (error_table().empty()) return;
    std::printf(
        "\nLargest finite-difference relative errors (library: the worst direction of\n"
        "core/analysis/derivative_check; full-matrix: central differences written in the\n"
        "test, relative in the Frobenius norm):\n");
    std::printf("%-14s %-3s %-16s %-9s %-12s %-9s %s\n", "force", "dim", "configuration",
                "quantity", "checker", "max error", "where");
    for (const auto& [key, worst] : error_table()) {
      const auto& [force, dim, configuration, derivative, checker] = key;
      std::printf("%-14s %dD  %-16s %-9s %-12s %.2e  %s\n", force.c_str(), dim,
                  configuration.c_str(), derivative.c_str(), checker.c_str(), worst.error,
                  worst.detail.c_str());
    }
  }
};

[[maybe_unused]] ::testing::Environment* const kErrorTablePrinter =
    ::testing::AddGlobalTestEnvironment(new ErrorTablePrinter);

}  // namespace

void record_fd_error(const DerivativeCase& what, int dim, const std::string& derivative,
                     const std::string& checker, double error) {
  if (what.configuration == kAtRest) return;  // relative errors of round-off mean nothing
  WorstCase& worst = error_table()[{what.force, dim, what.configuration, derivative, checker}];
  if (!(error <= worst.error)) worst = {error, what.detail};  // NaN is the worst of all
}

bool check_force_everywhere(const Force& force, int dim, const Vector& q, const Vector& v,
                            const Vector& mass, const DerivativeCase& what) {
  bool all_passed = true;
  const std::string where =
      what.force + " " + std::to_string(dim) + "D " + what.configuration + " (" + what.detail + ")";

  DerivativeCheckOptions options;
  options.step = suggest_finite_difference_step(q, dim);
  for (const DerivativeCheck& check : check_force_derivatives(force, q, v, mass, options)) {
    EXPECT_TRUE(check.passed()) << where << ": library check of " << derivative_name(check.which)
                                << " failed, relative error " << check.relative_error()
                                << ", allowance used " << check.allowance_used;
    all_passed = all_passed && check.passed();
    record_fd_error(what, dim, derivative_name(check.which), "library", check.relative_error());
  }

  // Independent check: whole matrices by central differences, steps relative to the
  // configuration's length (and to 1 for velocities).
  const double length = configuration_length(q, dim);
  struct Item {
    const char* name;
    MatrixComparison result;
  };
  std::vector<Item> items = {
      {"hessX", compare_hessian_full(force, q, v, mass, false, kHessianStep * length)},
      {"hessV", compare_hessian_full(force, q, v, mass, true, kHessianStep)}};
  if (force.has_potential()) {
    items.push_back({"gradient", compare_gradient_full(force, q, mass, kGradientStep * length)});
  }
  for (const Item& item : items) {
    const bool passed = item.result.passes(kFullMatrixTolerance);
    EXPECT_TRUE(passed) << where << ": full-matrix check of " << item.name << ", error "
                        << item.result.absolute_error << " against scale " << item.result.scale
                        << " and noise floor " << item.result.noise_floor;
    all_passed = all_passed && passed;
    record_fd_error(what, dim, item.name, "full-matrix", item.result.relative_error());
  }
  return all_passed;
}

}  // namespace fosssim::testing
