#include "core/forces/gravitational_force.h"

#include "core/forces/make_for_dim.h"
#include "core/forces/pair_checks.h"
#include "core/scene_model.h"

namespace fosssim {

template <int D>
void GravitationalForce<D>::add_energy(const ForceInput& in, double& energy) const {
  const Vec<D> d = particle_vec<D>(in.q, j_) - particle_vec<D>(in.q, i_);
  energy -= G_ * in.mass[D * i_] * in.mass[D * j_] / d.norm();
}

template <int D>
void GravitationalForce<D>::add_gradient(const ForceInput& in, Vector& gradient) const {
  const Vec<D> d = particle_vec<D>(in.q, j_) - particle_vec<D>(in.q, i_);
  const double l = d.norm();
  const Vec<D> force_i = (G_ * in.mass[D * i_] * in.mass[D * j_] / (l * l)) * (d / l);
  gradient.template segment<D>(D * i_) -= force_i;
  gradient.template segment<D>(D * j_) += force_i;
}

template <int D>
void GravitationalForce<D>::add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const {
  const Vec<D> d = particle_vec<D>(in.q, j_) - particle_vec<D>(in.q, i_);
  const double l = d.norm();
  const Vec<D> n = d / l;
  const double c = G_ * in.mass[D * i_] * in.mass[D * j_] / (l * l * l);
  hessian.add_pair<D>(i_, j_, Mat<D>(c * (Mat<D>::Identity() - 3.0 * n * n.transpose())));
}

template <int D>
std::string GravitationalForce<D>::label() const {
  return "gravitationalforce(" + std::to_string(i_) + ", " + std::to_string(j_) + ")";
}

template class GravitationalForce<2>;
template class GravitationalForce<3>;

std::unique_ptr<Force> make_gravitational_force(ForceParameters& params,
                                                const ForceContext& context) {
  const auto [i, j] = read_distinct_separated_pair(params, context);
  return make_for_dim<GravitationalForce>(context.model.dim, i, j, params.non_negative("G"));
}

}  // namespace fosssim
