#pragma once
// One spring's energy, force and Jacobians as small fixed-size functions (docs/forces.md,
// 'Spring'), shared by every force made of springs.

#include <algorithm>

#include "core/types.h"

namespace fosssim {

/// With d = x_j - x_i, l = |d|, n = d/l: U = ½ k (l - l0)².
template <int D>
double spring_energy(const Vec<D>& d, double k, double l0) {
  const double stretch = d.norm() - l0;
  return 0.5 * k * stretch * stretch;
}

/// The force on particle i (particle j receives its negative):
///   F_i = k (l - l0) n + b (n·dv) n,  dv = v_j - v_i.
/// A zero-rest-length undamped spring stays defined at l = 0, where F_i = k d.
template <int D>
Vec<D> spring_force_on_i(const Vec<D>& d, const Vec<D>& dv, double k, double l0, double b) {
  const double l = d.norm();
  if (l == 0.0 && l0 == 0.0) return k * d;
  const Vec<D> n = d / l;
  Vec<D> force = k * (l - l0) * n;
  if (b != 0.0) force += b * n.dot(dv) * n;
  return force;
}

/// The block H of hessX = -dF/dq in pair pattern (+H on (i,i), (j,j), -H on (i,j), (j,i)):
///   H = k [P + ((l - l0)/l)(I - P)] + (b/l)[n dvᵀ + (n·dv) I](I - P),  P = n nᵀ.
/// project_definite clamps (l - l0)/l at 0: a compressed spring's transverse stiffness is
/// negative, and dropping it leaves the elastic block positive semi-definite (Choi and Ko,
/// "Stable but responsive cloth", SIGGRAPH 2002). The damping part is not affected.
template <int D>
Mat<D> spring_hessian_x(const Vec<D>& d, const Vec<D>& dv, double k, double l0, double b,
                        bool project_definite) {
  const double l = d.norm();
  const Mat<D> I = Mat<D>::Identity();
  if (l == 0.0 && l0 == 0.0) return k * I;
  const Vec<D> n = d / l;
  const Mat<D> P = n * n.transpose();
  double transverse = (l - l0) / l;
  if (project_definite) transverse = std::max(transverse, 0.0);
  Mat<D> H = k * (P + transverse * (I - P));
  if (b != 0.0) H += (b / l) * (n * dv.transpose() + n.dot(dv) * I) * (I - P);
  return H;
}

/// The block of hessV = -dF/dv in pair pattern: b P; zero where the direction is undefined.
template <int D>
Mat<D> spring_hessian_v(const Vec<D>& d, double l0, double b) {
  const double l = d.norm();
  if (b == 0.0 || (l == 0.0 && l0 == 0.0)) return Mat<D>::Zero();
  const Vec<D> n = d / l;
  return b * n * n.transpose();
}

}  // namespace fosssim
