#pragma once
// Helpers shared by the core tests: a builder for small scene models, random configurations,
// dense views of sparse matrices, an independent full-matrix finite-difference check, and the
// table of the largest finite-difference errors that the derivative tests print for the record.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <random>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "core/force.h"
#include "core/integrators/integrator.h"
#include "core/integrators/integrator_registry.h"
#include "core/scene_model.h"
#include "core/state.h"
#include "core/types.h"

namespace fosssim::testing {

// ---------------------------------------------------------------------------------------------
// Building models

/// A vector from a brace list: vec({1.0, 2.0}).
inline Vector vec(std::initializer_list<double> values) {
  Vector out(static_cast<Eigen::Index>(values.size()));
  Eigen::Index k = 0;
  for (double value : values) out[k++] = value;
  return out;
}

/// A scene model with its initial state, built particle by particle in C++ (no XML).
struct TestScene {
  SceneModel model;
  State state;

  /// integrator: the canonical name of a method of the registry.
  explicit TestScene(int dim, std::string_view integrator = "explicit-euler", double dt = 0.01) {
    model.dim = dim;
    model.integrator.use(integrator_method(integrator));
    model.integrator.dt = dt;
    state.q.resize(0);
    state.v.resize(0);
  }

  /// Appends a particle of mass m at x with velocity v (both of size dim); returns its index.
  int add_particle(double m, const Vector& x, const Vector& v, bool fixed = false) {
    const int dim = model.dim;
    const Eigen::Index n = state.q.size();
    state.q.conservativeResize(n + dim);
    state.v.conservativeResize(n + dim);
    model.mass.conservativeResize(n + dim);
    state.q.tail(dim) = x;
    state.v.tail(dim) = v;
    model.mass.tail(dim).setConstant(m);
    model.fixed.push_back(fixed);
    return model.num_particles() - 1;
  }

  /// Appends a force; forces are summed in the order they are added.
  template <typename ForceT>
  ForceT& add_force(std::unique_ptr<ForceT> force) {
    ForceT& out = *force;
    model.forces.push_back(std::move(force));
    return out;
  }

  /// Appends the edge (i, j) and an undamped or damped spring on it.
  void add_spring(int i, int j, double k, double l0, double b = 0.0);
  /// Appends Newtonian gravity between i and j.
  void add_gravitation(int i, int j, double G);
  /// Appends linear drag on every particle.
  void add_drag(double b);
  /// Appends a uniform gravitational acceleration g (size dim).
  void add_simple_gravity(const Vector& g);
};

/// Every integrator of the registry, for tests that apply to all of them
/// (core/integrators/integrator_registry.h).
inline std::span<const IntegratorMethod* const> all_integrators() { return integrator_methods(); }

/// Runs `steps` steps of the model's integrator from the scene's state and returns the result.
State run_steps(const SceneModel& model, State state, std::int64_t steps);

/// Total linear momentum Σ m_p v_p (size dim).
Vector linear_momentum(const SceneModel& model, const Vector& v);

/// Expects ‖actual - expected‖_∞ ≤ tolerance · max(1, ‖expected‖_∞), printing both on failure.
void expect_close(const Vector& actual, const Vector& expected, double tolerance,
                  const std::string& what);

/// Spring force on particle j of a spring from i to j (docs/forces.md, 'Spring'), written out for
/// expected values: F_j = -k (l - l0) n - b (n·dv) n with d = x_j - x_i, n = d/l, dv = v_j - v_i.
Vector spring_force_on_j(const Vector& xi, const Vector& xj, const Vector& vi, const Vector& vj,
                         double k, double l0, double b);

/// A particle of mass 2 at x with velocity w under gravity g (x, w in [-1, 1)ᵈ, g in [-10, 10)ᵈ,
/// random from a seed), for hand-computed steps.
struct FallingParticle {
  Vector x, w, g;

  FallingParticle(int dim, unsigned seed);
  TestScene scene(std::string_view kind, double h) const;
};

/// A spring (k, l0, damping b) from a fixed particle 0 of mass 5 at a, moving with velocity u,
/// to a free particle 1 of mass m at x with velocity w, plus drag c on both (a, u, x, w in
/// [-1, 1)ᵈ, random from a seed), for hand-computed steps.
struct AnchoredSpring {
  double m, k, l0, b, c;
  Vector a, u, x, w;

  AnchoredSpring(int dim, unsigned seed, double m, double k, double l0, double b, double c);
  TestScene scene(std::string_view kind, double h) const;
  /// Expects the fixed particle of `next` at a + h u with velocity exactly u, and the free one
  /// at (x_expected, v_expected), to the relative tolerance.
  void expect_step(const State& next, double h, const Vector& x_expected, const Vector& v_expected,
                   double tolerance) const;
};

/// A linear system with a fixed particle: particle 0 fixed at a, moving with velocity u;
/// particle 1 of mass m at x with velocity w; a zero-rest-length spring k from 0 to 1; drag c.
struct LinearAnchoredSystem {
  double h, m, k, c;
  Vector a, u, x, w;

  TestScene scene(std::string_view kind) const;
  /// One step of backward Euler in closed form. With a' = a + h u and x' = x + h v',
  /// m (v' - w) = h (-k (x' - a') - c v') gives v' = (m w - h k (x - a) + h² k u) / (m + h c + h²
  /// k); the fixed particle ends at a' with velocity u. Linearized implicit Euler is exact here
  /// too.
  State backward_euler_step() const;
};

/// A linear system of two free particles of equal mass m at xa, xb with velocities va, vb,
/// joined by a zero-rest-length spring k, with drag c on both.
struct LinearPairSystem {
  double h, m, k, c;
  Vector xa, va, xb, vb;

  TestScene scene(std::string_view kind) const;
  /// One step of backward Euler in closed form, from the sum s = va + vb and the difference
  /// r = vb - va, d = xb - xa: m (s' - s) = -h c s' and m (r' - r) = h (-2k (d + h r') - c r'),
  /// so s' = m s / (m + h c), r' = (m r - 2 h k d) / (m + h c + 2 h² k); x' = x + h v'.
  State backward_euler_step() const;
};

// ---------------------------------------------------------------------------------------------
// Randomness and dense views

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
  /// A uniformly distributed unit vector of size n.
  Vector unit_vector(int n) {
    std::normal_distribution<double> normal(0.0, 1.0);
    Vector out(n);
    for (int k = 0; k < n; ++k) out[k] = normal(rng_);
    return out.normalized();
  }
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

inline Eigen::MatrixXd dense(const SparseMatrix& A) { return Eigen::MatrixXd(A); }

/// ‖A - Aᵀ‖_F / ‖A‖_F, 0 for the zero matrix.
double asymmetry(const Eigen::MatrixXd& A);

/// The pair pattern of pair forces (docs/forces.md) as a dense n×n matrix: +H on blocks (i,i),
/// (j,j), -H on (i,j), (j,i). Written out here so tests do not depend on HessianBuilder for
/// expected values.
Eigen::MatrixXd dense_pair_pattern(int n, int dim, int i, int j, const Eigen::MatrixXd& H);

/// The 90° rotation about a unit axis in 3D, R a = axis × a (the cross-product matrix).
Mat<3> cross_product_matrix(const Vec<3>& axis);

/// Two orthonormal vectors spanning a plane for planar motions: the x and y axes in 2D, a plane
/// tilted away from every coordinate plane in 3D, e₁ = (1, 2, 2)/3, e₂ = (2, 1, -2)/3.
template <int D>
std::pair<Vector, Vector> plane_axes() {
  if constexpr (D == 2) {
    return {Vector::Unit(2, 0), Vector::Unit(2, 1)};
  } else {
    Vector e1(3), e2(3);
    e1 << 1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0;
    e2 << 2.0 / 3.0, 1.0 / 3.0, -2.0 / 3.0;
    return {e1, e2};
  }
}

/// The 90° counter-clockwise rotation R(a) = (-a_y, a_x) in 2D.
inline Mat<2> rotation_2d() {
  Mat<2> R;
  R << 0.0, -1.0, 1.0, 0.0;
  return R;
}

/// The vortex rotation for dimension D: rotation_2d() or the cross-product matrix of `axis`.
template <int D>
Mat<D> vortex_rotation(const Vec<3>& axis) {
  if constexpr (D == 2) {
    return rotation_2d();
  } else {
    return cross_product_matrix(axis.normalized());
  }
}

// ---------------------------------------------------------------------------------------------
// Derivatives of one force, assembled densely, and the independent full-matrix check

Vector gradient_of(const Force& force, const Vector& q, const Vector& v, const Vector& mass);
double energy_of(const Force& force, const Vector& q, const Vector& v, const Vector& mass);
Eigen::MatrixXd hessian_x_of(const Force& force, const Vector& q, const Vector& v,
                             const Vector& mass);
Eigen::MatrixXd hessian_v_of(const Force& force, const Vector& q, const Vector& v,
                             const Vector& mass);

/// Result of comparing an analytic derivative with its finite-difference estimate.
struct MatrixComparison {
  double absolute_error = 0.0;  ///< ‖analytic - numeric‖_F
  double scale = 0.0;           ///< max(‖analytic‖_F, ‖numeric‖_F)
  double noise_floor = 0.0;     ///< round-off level of the numeric side, absolute
  /// Passes when the error is within tolerance·scale + noise_floor.
  bool passes(double tolerance) const {
    return absolute_error <= tolerance * scale + noise_floor;  // false for NaN
  }
  double relative_error() const {
    return scale > 0.0 ? absolute_error / scale : (absolute_error > 0.0 ? INFINITY : 0.0);
  }
};

/// Compares the dense hessX (in_velocity = false) or hessV (true) of a force with the matrix
/// whose column k is the central difference (g(x + t e_k) - g(x - t e_k)) / (actual step),
/// where g is the gradient and the actual step is the floating-point difference of the two
/// perturbed coordinates (so rounding of x ± t does not enter the quotient). Normwise: no floor.
MatrixComparison compare_hessian_full(const Force& force, const Vector& q, const Vector& v,
                                      const Vector& mass, bool in_velocity, double t);

/// Compares the gradient at v = 0 with Richardson-extrapolated central differences of the
/// energy, (4 D(t/2) - D(t)) / 3, along every coordinate, with the same actual-step rule. The
/// energy is only known to round-off, ε_machine (|U| + ‖hessX‖ |q|_∞ t) per value, so the noise
/// floor is 100 ε_machine √n (|U| / t + ‖hessX‖_F |q|_∞).
MatrixComparison compare_gradient_full(const Force& force, const Vector& q, const Vector& mass,
                                       double t);

/// The shortest distance between two distinct particles of q (infinity for one particle).
double shortest_distance(const Vector& q, int dim);

// ---------------------------------------------------------------------------------------------
// The record of finite-difference errors

/// The configuration name of equilibria, where gradE is round-off: checked, not recorded.
inline const std::string kAtRest = "at-rest";

/// What a derivative test checks, for messages and the record.
struct DerivativeCase {
  std::string force;          ///< "spring", "spring(b>0)", "gravitation", ...
  std::string configuration;  ///< "random" or "near-degenerate"
  std::string detail;         ///< seed, lengths: for failure messages
};

/// Records a relative error per (force, dimension, configuration, derivative, checker), keeps
/// the largest with the case that produced it, and prints them all when the test program ends
/// (run the test binary directly to see the whole table; under ctest each test prints its rows).
/// At-rest configurations are checked but not recorded.
void record_fd_error(const DerivativeCase& what, int dim, const std::string& derivative,
                     const std::string& checker, double error);

/// The length scale L of a configuration: the shortest distance between two particles, at
/// most 1 (1 when particles coincide). Finite-difference steps are multiples of it.
double configuration_length(const Vector& q, int dim);

/// Steps of the full-matrix check relative to L. Hessians (plain central differences of
/// gradE): truncation (t/L)² = 1e-10, round-off about 1e5 ε_machine relative. Gradients
/// (Richardson-extrapolated differences of U): truncation k (t/L)⁴ L = 1e-16 k L, below the
/// round-off floor even where gradE vanishes.
constexpr double kHessianStep = 1e-5;
constexpr double kGradientStep = 1e-4;

/// Tolerance of the full-matrix check: 1e-7 leaves three orders of margin above the errors
/// that the steps above leave, and still catches a Hessian that is off by one part in 10⁴.
constexpr double kFullMatrixTolerance = 1e-7;

/// Runs the library's checker (core/analysis/derivative_check.h) with the step it suggests for
/// this configuration and the independent full-matrix check on one force, asserts both pass,
/// and records the errors. Returns false if any check failed.
bool check_force_everywhere(const Force& force, int dim, const Vector& q, const Vector& v,
                            const Vector& mass, const DerivativeCase& what);

// ---------------------------------------------------------------------------------------------
// Typed tests over the dimension

template <int D>
using Dim = std::integral_constant<int, D>;
using Dimensions = ::testing::Types<Dim<2>, Dim<3>>;

struct DimensionName {
  template <typename T>
  static std::string GetName(int) {
    return std::to_string(T::value) + "D";
  }
};

/// Declares the typed test suite `Suite`, run once in 2D and once in 3D; in its tests
/// `TypeParam::value` is the dimension.
#define FOSSSIM_TEST_SUITE_IN_2D_AND_3D(Suite) \
  template <typename T>                        \
  class Suite : public ::testing::Test {};     \
  TYPED_TEST_SUITE(Suite, ::fosssim::testing::Dimensions, ::fosssim::testing::DimensionName)

}  // namespace fosssim::testing
