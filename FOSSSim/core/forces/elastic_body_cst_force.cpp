#include "core/forces/elastic_body_cst_force.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/forces/make_for_dim.h"
#include "core/forces/psd_projection.h"
#include "core/scene_model.h"
#include "core/text.h"

namespace fosssim {

namespace {

using Mat2 = Mat<2>;

/// The strain ε = FᵀF - I as (εxx, εyy, εxy).
template <int D>
Eigen::Vector3d strain_of(const Eigen::Matrix<double, D, 2>& F) {
  const Vec<D> f0 = F.col(0);
  const Vec<D> f1 = F.col(1);
  return Eigen::Vector3d(f0.squaredNorm() - 1.0, f1.squaredNorm() - 1.0, f0.dot(f1));
}

/// w(p, c) = ∂F(:, c)/∂x_p: F's column c is Σ_p w(p, c) x_p (rows are corners 1, 2, 3).
Eigen::Matrix<double, 3, 2> corner_weights(const Mat2& B) {
  Eigen::Matrix<double, 3, 2> w;
  w.row(0) = -(B.row(0) + B.row(1));
  w.row(1) = B.row(0);
  w.row(2) = B.row(1);
  return w;
}

}  // namespace

template <int D>
CstRest compute_cst_rest(const Vec<D>& x1, const Vec<D>& x2, const Vec<D>& x3) {
  const Vec<D> e1 = x2 - x1;
  const Vec<D> e2 = x3 - x1;
  CstRest rest;
  Mat2 rest_edges;
  if constexpr (D == 2) {
    rest_edges << e1[0], e2[0], e1[1], e2[1];
    rest.area = 0.5 * std::abs(e2[0] * e1[1] - e2[1] * e1[0]);
  } else {
    const Vec<3> normal = e1.cross(e2);
    rest.area = 0.5 * normal.norm();
    const Vec<3> t1 = e1.normalized();
    const Vec<3> t2 = normal.cross(e1).normalized();  // in the plane, perpendicular to e1
    rest_edges << e1.norm(), t1.dot(e2), 0.0, t2.dot(e2);
  }
  rest.B = rest.area > 0.0 ? Mat2(rest_edges.inverse()) : Mat2::Zero();
  return rest;
}

template CstRest compute_cst_rest<2>(const Vec<2>&, const Vec<2>&, const Vec<2>&);
template CstRest compute_cst_rest<3>(const Vec<3>&, const Vec<3>&, const Vec<3>&);

template <int D>
Eigen::Matrix<double, D, 2> ElasticBodyCstForce<D>::deformation_gradient(const Vector& q) const {
  const Vec<D> x1 = particle_vec<D>(q, corners_[0]);
  Eigen::Matrix<double, D, 2> edges;
  edges.col(0) = particle_vec<D>(q, corners_[1]) - x1;
  edges.col(1) = particle_vec<D>(q, corners_[2]) - x1;
  return edges * rest_.B;
}

template <int D>
void ElasticBodyCstForce<D>::add_energy(const ForceInput& in, double& energy) const {
  const Eigen::Vector3d e = strain_of<D>(deformation_gradient(in.q));
  const double quadratic =
      e[0] * e[0] + 2.0 * nu_ * e[0] * e[1] + e[1] * e[1] + 2.0 * (1.0 - nu_) * e[2] * e[2];
  energy += E_ * rest_.area / (2.0 * (1.0 - nu_ * nu_)) * quadratic;
}

template <int D>
void ElasticBodyCstForce<D>::add_gradient(const ForceInput& in, Vector& gradient) const {
  // ∇U = K [(εxx + ν εyy) ∇εxx + (εyy + ν εxx) ∇εyy + 2(1 - ν) εxy ∇εxy], corner by corner, in
  // the course's order of operations (its worked example E3 is reproduced to the bit). This is
  // G = 2K F S Bᵀ of the header, written per corner.
  const Eigen::Matrix<double, D, 2> F = deformation_gradient(in.q);
  const Eigen::Vector3d e = strain_of<D>(F);
  const double K = E_ * rest_.area / (1.0 - nu_ * nu_);
  const double s_xx = e[0] + nu_ * e[1];
  const double s_yy = e[1] + nu_ * e[0];
  const double s_xy = 2.0 * (1.0 - nu_) * e[2];
  const Eigen::Matrix<double, 3, 2> w = corner_weights(rest_.B);
  for (int p = 0; p < 3; ++p) {
    const Vec<D> d_xx = 2.0 * w(p, 0) * F.col(0);
    const Vec<D> d_yy = 2.0 * w(p, 1) * F.col(1);
    const Vec<D> d_xy = w(p, 0) * F.col(1) + w(p, 1) * F.col(0);
    gradient.template segment<D>(D * corners_[p]) += K * (s_xx * d_xx + s_yy * d_yy + s_xy * d_xy);
  }
}

template <int D>
void ElasticBodyCstForce<D>::add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const {
  const Eigen::Matrix<double, D, 2> F = deformation_gradient(in.q);
  const Eigen::Vector3d e = strain_of<D>(F);
  const double K = E_ * rest_.area / (1.0 - nu_ * nu_);
  Eigen::Matrix3d C;
  C << 1.0, nu_, 0.0, nu_, 1.0, 0.0, 0.0, 0.0, 2.0 * (1.0 - nu_);
  const Eigen::Vector3d sigma = C * e;
  const Eigen::Matrix<double, 3, 2> w = corner_weights(rest_.B);
  // grad[p].col(s) = ∂ε_s/∂x_p for the strains s = xx, yy, xy.
  std::array<Eigen::Matrix<double, D, 3>, 3> grad;
  for (int p = 0; p < 3; ++p) {
    grad[p].col(0) = 2.0 * w(p, 0) * F.col(0);
    grad[p].col(1) = 2.0 * w(p, 1) * F.col(1);
    grad[p].col(2) = w(p, 0) * F.col(1) + w(p, 1) * F.col(0);
  }
  // The element block, corner by corner; projected as a whole when asked (the 3D×3D matrix of
  // the three corners), added block by block either way.
  Eigen::Matrix<double, 3 * D, 3 * D> element;
  for (int p = 0; p < 3; ++p) {
    for (int r = 0; r < 3; ++r) {
      // ∇²ε_s is a multiple of the identity in each corner block (ε is quadratic in F).
      const double curvature = 2.0 * sigma[0] * w(p, 0) * w(r, 0) +
                               2.0 * sigma[1] * w(p, 1) * w(r, 1) +
                               sigma[2] * (w(p, 0) * w(r, 1) + w(p, 1) * w(r, 0));
      element.template block<D, D>(D * p, D * r) =
          K * (grad[p] * C * grad[r].transpose() + curvature * Mat<D>::Identity());
    }
  }
  if (in.definite_hessian) element = projected_to_semidefinite<3 * D>(element);
  for (int p = 0; p < 3; ++p) {
    for (int r = 0; r < 3; ++r) {
      hessian.add_block<D>(corners_[p], corners_[r],
                           Mat<D>(element.template block<D, D>(D * p, D * r)));
    }
  }
}

template <int D>
void ElasticBodyCstForce<D>::append_elements(const Vector& q,
                                             std::vector<ForceElement>& elements) const {
  const Eigen::Matrix<double, D, 2> F = deformation_gradient(q);
  // The eigenvalues of the symmetric 2×2 matrix C = FᵀF are λ² of the principal stretches.
  const Mat2 C = F.transpose() * F;
  const double mean = 0.5 * (C(0, 0) + C(1, 1));
  const double half_gap = std::hypot(0.5 * (C(0, 0) - C(1, 1)), C(0, 1));
  const double small = std::sqrt(std::max(mean - half_gap, 0.0)) - 1.0;
  const double large = std::sqrt(std::max(mean + half_gap, 0.0)) - 1.0;
  ForceElement element;
  element.kind = ForceElement::Kind::kTriangle;
  element.particles = corners_;
  element.strain = std::abs(small) > std::abs(large) ? small : large;
  double energy = 0.0;
  const Vector none;
  add_energy(ForceInput{q, none, none}, energy);
  element.energy_density = rest_.area > 0.0 ? energy / rest_.area : 0.0;
  elements.push_back(element);
}

template <int D>
std::string ElasticBodyCstForce<D>::label() const {
  return "elasticbodycstforce(" + std::to_string(corners_[0]) + ", " +
         std::to_string(corners_[1]) + ", " + std::to_string(corners_[2]) + ")";
}

template class ElasticBodyCstForce<2>;
template class ElasticBodyCstForce<3>;

namespace {

template <int D>
std::unique_ptr<Force> make_cst(ForceParameters& params, const ForceContext& context,
                                const std::array<int, 3>& corners, double E, double nu) {
  static constexpr const char* kRestNames[3][3] = {
      {"xb1x", "xb1y", "xb1z"}, {"xb2x", "xb2y", "xb2z"}, {"xb3x", "xb3y", "xb3z"}};
  std::array<Vec<D>, 3> rest_corners;
  for (int p = 0; p < 3; ++p) {
    for (int c = 0; c < D; ++c) {
      const double initial = context.positions[D * corners[p] + c];
      rest_corners[p][c] = params.number_or(kRestNames[p][c], initial);
    }
  }
  const CstRest rest = compute_cst_rest<D>(rest_corners[0], rest_corners[1], rest_corners[2]);
  if (!(rest.area > 0.0) || !rest.B.allFinite()) {
    params.fail("the rest triangle (xb1, xb2, xb3, defaulting to the particles' initial "
                "positions) has zero area, so its strain is undefined");
  }
  return std::make_unique<ElasticBodyCstForce<D>>(corners, E, nu, rest);
}

}  // namespace

std::unique_ptr<Force> make_elastic_body_cst_force(ForceParameters& params,
                                                   const ForceContext& context) {
  const std::array<int, 3> corners = {params.particle_index("i1"), params.particle_index("i2"),
                                      params.particle_index("i3")};
  const char* names[3] = {"i1", "i2", "i3"};
  for (int a = 0; a < 3; ++a) {
    for (int b = a + 1; b < 3; ++b) {
      if (corners[a] == corners[b]) {
        params.fail(names[b], std::string("must differ from ") + names[a] + " (both are " +
                                  std::to_string(corners[a]) + ")");
      }
    }
  }
  const double E = params.number("youngsmodulus");
  if (!(E > 0.0)) params.fail("youngsmodulus", "must be positive, found " + to_text(E));
  const double nu = params.number("poissonratio");
  if (!(std::abs(nu) < 1.0)) {
    params.fail("poissonratio",
                "must lie strictly between -1 and 1 (the plane-stress energy divides by "
                "1 - ν²), found " +
                    to_text(nu));
  }
  if (nu < 0.0 || nu > 0.5) {
    params.warn("poissonratio " + to_text(nu) +
                " is unusual (common materials lie in [0, 0.5]); loaded as given");
  }
  for (const char* name : {"ebxx", "ebyy", "ebxy"}) {
    params.unsupported(name, "a rest strain, which the course's program never read");
  }
  if (context.model.dim == 3) return make_cst<3>(params, context, corners, E, nu);
  return make_cst<2>(params, context, corners, E, nu);
}

}  // namespace fosssim
