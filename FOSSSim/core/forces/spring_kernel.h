#pragma once
// One spring's energy, force and Jacobians as small fixed-size functions (docs/forces.md,
// 'Spring'), shared by every force made of springs.
//
// In 2D every formula is evaluated in the order of floating-point operations the course's
// reference programs use (docs/forces.md, 'Course-exact arithmetic'): the unit direction is d
// times the reciprocal 1/l (not d divided by l), the elastic and damping forces are accumulated
// into the gradient one after the other, and the Jacobian blocks are written out entry by entry.
// 3D, which has no course to match, keeps FOSSSim's vector forms (n = d ÷ l, matrix products).

#include <algorithm>

#include "core/forces/ordered_arithmetic.h"
#include "core/types.h"

namespace fosssim {

/// With d = x_j - x_i, l = |d|, n = d/l: U = ½ k (l - l0)².
template <int D>
double spring_energy(const Vec<D>& d, double k, double l0) {
  const double stretch = d.norm() - l0;
  return 0.5 * k * stretch * stretch;
}

/// The force on particle i (particle j receives its negative), in its two parts:
///   elastic = k (l - l0) n,  damping = b (n·dv) n,  dv = v_j - v_i.
/// Each part is accumulated on its own (the course's order): g_i -= elastic, g_j += elastic,
/// then g_i -= damping, g_j += damping. n = d × (1/l); elastic = ((l - l0) k) n and
/// damping = ((dv·n) b) n, each product rounded where written. The damping part is computed
/// even for b = 0 (it is then a signed zero). A zero-rest-length undamped spring stays defined
/// at l = 0, where elastic = k d.
template <int D>
struct SpringForceParts {
  Vec<D> elastic;
  Vec<D> damping;
};

template <int D>
SpringForceParts<D> spring_force_on_i(const Vec<D>& d, const Vec<D>& dv, double k, double l0,
                                      double b) {
  if constexpr (D == 3) {
    // FOSSSim's own order in 3D (no course to match): one vector, n = d ÷ l.
    const double l = d.norm();
    if (l == 0.0 && l0 == 0.0) return {k * d, Vec<D>::Zero()};
    const Vec<D> n = d / l;
    Vec<D> force = k * (l - l0) * n;
    if (b != 0.0) force += b * n.dot(dv) * n;
    return {force, Vec<D>::Zero()};
  }
  const double l = ordered_norm<D>(d);
  if (l == 0.0 && l0 == 0.0) return {k * d, Vec<D>::Zero()};
  const double r = 1.0 / l;
  Vec<D> n;
  for (int c = 0; c < D; ++c) n[c] = d[c] * r;
  const double s = (l - l0) * k;
  const double damping = ordered_dot<D>(dv, n) * b;
  SpringForceParts<D> parts;
  for (int c = 0; c < D; ++c) {
    parts.elastic[c] = s * n[c];
    parts.damping[c] = damping * n[c];
  }
  return parts;
}

/// Adds the spring's -F into `gradient` at particles i and j, the elastic part first and the
/// damping part second (two accumulations, the course's order).
template <int D>
void add_spring_gradient(int i, int j, const SpringForceParts<D>& parts, Vector& gradient) {
  for (int c = 0; c < D; ++c) {
    gradient[D * i + c] = gradient[D * i + c] - parts.elastic[c];
    gradient[D * j + c] = gradient[D * j + c] + parts.elastic[c];
  }
  for (int c = 0; c < D; ++c) {
    gradient[D * i + c] = gradient[D * i + c] - parts.damping[c];
    gradient[D * j + c] = gradient[D * j + c] + parts.damping[c];
  }
}

/// The blocks of hessX = -dF/dq in pair pattern (+H on (i,i), (j,j), -H on (i,j), (j,i)),
/// elastic and damping apart: the course adds the elastic block first, then the damping one.
///   elastic = k [P + ((l - l0)/l)(I - P)],  P = n nᵀ,
///     entry by entry ((((δ_rc - P_rc) λ) r) + P_rc) k with λ = l - l0, r = 1/l;
///   damping = (b/l)(M - M P),  M = n dvᵀ + (n·dv) I,
///     entry by entry -((M_rc - (M P)_rc) × (-b ÷ l)), (M P)_rc summed over k in order.
/// project_definite clamps λ at 0: a compressed spring's transverse stiffness is negative, and
/// dropping it leaves the elastic block positive semi-definite (Choi and Ko, "Stable but
/// responsive cloth", SIGGRAPH 2002). The damping part is not affected.
template <int D>
struct SpringHessianParts {
  Mat<D> elastic;
  Mat<D> damping;
};

template <int D>
SpringHessianParts<D> spring_hessian_x_parts(const Vec<D>& d, const Vec<D>& dv, double k,
                                             double l0, double b, bool project_definite) {
  if constexpr (D == 3) {
    // FOSSSim's own order in 3D (no course to match): matrix products, n = d ÷ l.
    const double l = d.norm();
    const Mat<D> I = Mat<D>::Identity();
    if (l == 0.0 && l0 == 0.0) return {k * I, Mat<D>::Zero()};
    const Vec<D> n = d / l;
    const Mat<D> P = n * n.transpose();
    double transverse = (l - l0) / l;
    if (project_definite) transverse = std::max(transverse, 0.0);
    SpringHessianParts<D> parts{k * (P + transverse * (I - P)), Mat<D>::Zero()};
    if (b != 0.0) parts.damping = (b / l) * (n * dv.transpose() + n.dot(dv) * I) * (I - P);
    return parts;
  }
  const double l = ordered_norm<D>(d);
  if (l == 0.0 && l0 == 0.0) return {k * Mat<D>::Identity(), Mat<D>::Zero()};
  const double r = 1.0 / l;
  Vec<D> n;
  for (int c = 0; c < D; ++c) n[c] = d[c] * r;
  Mat<D> P;
  for (int row = 0; row < D; ++row) {
    for (int col = 0; col < D; ++col) P(row, col) = n[row] * n[col];
  }
  double stretch = l - l0;
  if (project_definite) stretch = std::max(stretch, 0.0);
  SpringHessianParts<D> parts;
  for (int row = 0; row < D; ++row) {
    for (int col = 0; col < D; ++col) {
      const double identity = row == col ? 1.0 : 0.0;
      parts.elastic(row, col) = ((((identity - P(row, col)) * stretch) * r) + P(row, col)) * k;
    }
  }
  const double ndv = ordered_dot<D>(n, dv);
  Mat<D> M;
  for (int row = 0; row < D; ++row) {
    for (int col = 0; col < D; ++col) M(row, col) = n[row] * dv[col];
    M(row, row) = M(row, row) + ndv;
  }
  const double phi = (-b) / l;
  for (int row = 0; row < D; ++row) {
    for (int col = 0; col < D; ++col) {
      double mp = M(row, 0) * P(0, col);
      for (int m = 1; m < D; ++m) mp = mp + M(row, m) * P(m, col);
      parts.damping(row, col) = -((M(row, col) - mp) * phi);
    }
  }
  return parts;
}

/// The sum of both hessX blocks (for callers that want one matrix; the sum rounds again).
template <int D>
Mat<D> spring_hessian_x(const Vec<D>& d, const Vec<D>& dv, double k, double l0, double b,
                        bool project_definite) {
  const SpringHessianParts<D> parts = spring_hessian_x_parts<D>(d, dv, k, l0, b, project_definite);
  return parts.elastic + parts.damping;
}

/// The block of hessV = -dF/dv in pair pattern: b P, entry by entry (b n_r) n_c; zero where the
/// direction is undefined.
template <int D>
Mat<D> spring_hessian_v(const Vec<D>& d, double l0, double b) {
  if constexpr (D == 3) {
    const double l = d.norm();
    if (l == 0.0 && l0 == 0.0) return Mat<D>::Zero();
    const Vec<D> n = d / l;
    return b * n * n.transpose();
  }
  const double l = ordered_norm<D>(d);
  if (l == 0.0 && l0 == 0.0) return Mat<D>::Zero();
  const double r = 1.0 / l;
  Vec<D> n;
  for (int c = 0; c < D; ++c) n[c] = d[c] * r;
  Mat<D> V;
  for (int row = 0; row < D; ++row) {
    for (int col = 0; col < D; ++col) V(row, col) = (b * n[row]) * n[col];
  }
  return V;
}

}  // namespace fosssim
