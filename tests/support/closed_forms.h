#pragma once
// Small systems whose steps are known in closed form or by hand, the formulas the tests compare
// with (a spring's force, linear momentum, the rotations of vortices and planar motions), and
// comparing vectors to a tolerance.

#include <string>
#include <string_view>
#include <utility>

#include "core/scene_model.h"
#include "core/state.h"
#include "core/types.h"
#include "support/scene_builder.h"

namespace fosssim::testing {

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

}  // namespace fosssim::testing
