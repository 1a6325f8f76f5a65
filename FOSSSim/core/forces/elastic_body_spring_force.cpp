#include "core/forces/elastic_body_spring_force.h"

#include <algorithm>
#include <cmath>

#include "core/forces/make_for_dim.h"
#include "core/scene_model.h"
#include "core/text.h"

namespace fosssim {

namespace {

/// The spring's length, as the course computes it: sqrt(dx² + dy² (+ dz²)), summed in order.
template <int D>
double length_of(const Vec<D>& d) {
  double sum = d[0] * d[0];
  for (int c = 1; c < D; ++c) sum += d[c] * d[c];
  return std::sqrt(sum);
}

}  // namespace

template <int D>
void ElasticBodySpringForce<D>::add_energy(const ForceInput& in, double& energy) const {
  const double stretch = length_of<D>(particle_vec<D>(in.q, i_) - particle_vec<D>(in.q, j_)) - l0_;
  energy += alpha_ / (2.0 * l0_) * stretch * stretch;
}

template <int D>
void ElasticBodySpringForce<D>::add_gradient(const ForceInput& in, Vector& gradient) const {
  const Vec<D> d = particle_vec<D>(in.q, i_) - particle_vec<D>(in.q, j_);
  const double l = length_of<D>(d);
  const double k = alpha_ / l0_;
  const double c = k * (l - l0_);
  const Vec<D> n = d / l;
  const Vec<D> grad_i = c * n;
  gradient.template segment<D>(D * i_) += grad_i;
  gradient.template segment<D>(D * j_) -= grad_i;
}

template <int D>
void ElasticBodySpringForce<D>::add_hessian_x(const ForceInput& in,
                                              HessianBuilder& hessian) const {
  const Vec<D> d = particle_vec<D>(in.q, i_) - particle_vec<D>(in.q, j_);
  const double l = length_of<D>(d);
  const double k = alpha_ / l0_;
  const Vec<D> n = d / l;
  const Mat<D> P = n * n.transpose();
  double transverse = 1.0 - l0_ / l;
  if (in.definite_hessian) transverse = std::max(transverse, 0.0);
  hessian.add_pair<D>(i_, j_, Mat<D>(k * (P + transverse * (Mat<D>::Identity() - P))));
}

template <int D>
std::string ElasticBodySpringForce<D>::label() const {
  return "elasticbodyspringforce(" + std::to_string(i_) + ", " + std::to_string(j_) + ")";
}

template class ElasticBodySpringForce<2>;
template class ElasticBodySpringForce<3>;

std::unique_ptr<Force> make_elastic_body_spring_force(ForceParameters& params,
                                                      const ForceContext& context) {
  const int i = params.particle_index("i1");
  const int j = params.particle_index("i2");
  if (i == j) params.fail("i2", "must differ from i1 (both are " + std::to_string(i) + ")");
  const double alpha = params.non_negative("alpha");
  const double l0 = params.number("l0");
  if (!(l0 > 0.0)) params.fail("l0", "must be positive, found " + to_text(l0));
  const int dim = context.model.dim;
  if (context.positions.segment(dim * i, dim) == context.positions.segment(dim * j, dim)) {
    params.fail("particles " + std::to_string(i) + " and " + std::to_string(j) +
                " start at the same point, where the spring's direction is undefined");
  }
  return make_for_dim<ElasticBodySpringForce>(dim, i, j, alpha, l0);
}

}  // namespace fosssim
