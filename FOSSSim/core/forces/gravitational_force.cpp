#include "core/forces/gravitational_force.h"

#include "core/forces/make_for_dim.h"
#include "core/forces/pair_checks.h"
#include "core/forces/ordered_arithmetic.h"
#include "core/scene_model.h"

namespace fosssim {

template <int D>
void GravitationalForce<D>::add_energy(const ForceInput& in, double& energy) const {
  const Vec<D> d = particle_vec<D>(in.q, j_) - particle_vec<D>(in.q, i_);
  energy -= G_ * in.mass[D * i_] * in.mass[D * j_] / d.norm();
}

// Gradient and hessX in 2D in the course's order of operations (docs/forces.md, 'Course-exact
// arithmetic'): n = d × (1/l), the masses multiplied as (m_j G) m_i, one division by l² or l³.
// 3D keeps FOSSSim's vector forms.

template <int D>
void GravitationalForce<D>::add_gradient(const ForceInput& in, Vector& gradient) const {
  const Vec<D> d = particle_vec<D>(in.q, j_) - particle_vec<D>(in.q, i_);
  if constexpr (D == 3) {  // FOSSSim's own order in 3D, where there is no course to match
    const double l = d.norm();
    const Vec<D> force_i = (G_ * in.mass[D * i_] * in.mass[D * j_] / (l * l)) * (d / l);
    gradient.template segment<D>(D * i_) -= force_i;
    gradient.template segment<D>(D * j_) += force_i;
    return;
  }
  const double l = ordered_norm<D>(d);
  const double r = 1.0 / l;
  const double s = ((in.mass[D * j_] * G_) * in.mass[D * i_]) / (l * l);
  for (int c = 0; c < D; ++c) {
    const double e = (d[c] * r) * s;  // the force on i
    gradient[D * i_ + c] = gradient[D * i_ + c] - e;
    gradient[D * j_ + c] = gradient[D * j_ + c] + e;
  }
}

template <int D>
void GravitationalForce<D>::add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const {
  const Vec<D> d = particle_vec<D>(in.q, j_) - particle_vec<D>(in.q, i_);
  if constexpr (D == 3) {
    const double l = d.norm();
    const Vec<D> n = d / l;
    const double c = G_ * in.mass[D * i_] * in.mass[D * j_] / (l * l * l);
    hessian.add_pair<D>(i_, j_, Mat<D>(c * (Mat<D>::Identity() - 3.0 * n * n.transpose())));
    return;
  }
  const double l = ordered_norm<D>(d);
  const double r = 1.0 / l;
  const double sigma = ((in.mass[D * j_] * G_) * in.mass[D * i_]) / ((l * l) * l);
  Vec<D> n;
  for (int c = 0; c < D; ++c) n[c] = d[c] * r;
  // H = σ (I - 3 n nᵀ), entry by entry (δ_rc - (3 n_r) n_c) σ.
  Mat<D> H;
  for (int row = 0; row < D; ++row) {
    const double three_n = 3.0 * n[row];
    for (int col = 0; col < D; ++col) {
      const double identity = row == col ? 1.0 : 0.0;
      H(row, col) = (identity - three_n * n[col]) * sigma;
    }
  }
  hessian.add_pair<D>(i_, j_, H);
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
