#include "core/forces/spring_set_force.h"

#include <algorithm>

#include "core/forces/spring_kernel.h"

namespace fosssim {

template <int D>
SpringSetForce<D>::SpringSetForce(std::vector<SpringTerm> springs, std::string label)
    : springs_(std::move(springs)), label_(std::move(label)) {
  damped_ =
      std::any_of(springs_.begin(), springs_.end(), [](const SpringTerm& s) { return s.b != 0.0; });
}

template <int D>
void SpringSetForce<D>::add_energy(const ForceInput& in, double& energy) const {
  for (const SpringTerm& s : springs_) {
    energy += spring_energy<D>(particle_vec<D>(in.q, s.j) - particle_vec<D>(in.q, s.i), s.k, s.l0);
  }
}

template <int D>
void SpringSetForce<D>::add_gradient(const ForceInput& in, Vector& gradient) const {
  for (const SpringTerm& s : springs_) {
    const Vec<D> d = particle_vec<D>(in.q, s.j) - particle_vec<D>(in.q, s.i);
    Vec<D> dv = Vec<D>::Zero();
    if (s.b != 0.0) dv = particle_vec<D>(in.v, s.j) - particle_vec<D>(in.v, s.i);
    add_spring_gradient<D>(s.i, s.j, spring_force_on_i<D>(d, dv, s.k, s.l0, s.b), gradient);
  }
}

template <int D>
void SpringSetForce<D>::add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const {
  hessian.reserve(4 * D * D * springs_.size());
  for (const SpringTerm& s : springs_) {
    const Vec<D> d = particle_vec<D>(in.q, s.j) - particle_vec<D>(in.q, s.i);
    Vec<D> dv = Vec<D>::Zero();
    if (s.b != 0.0) dv = particle_vec<D>(in.v, s.j) - particle_vec<D>(in.v, s.i);
    const SpringHessianParts<D> parts =
        spring_hessian_x_parts<D>(d, dv, s.k, s.l0, s.b, in.definite_hessian);
    // The same blocks as SpringForce writes, so the sums have the same bits.
    if (s.b == 0.0) {
      hessian.add_pair<D>(s.i, s.j, parts.elastic);
    } else {
      hessian.add_pair<D>(s.i, s.j, Mat<D>(parts.elastic + parts.damping));
    }
  }
}

template <int D>
void SpringSetForce<D>::add_hessian_v(const ForceInput& in, HessianBuilder& hessian) const {
  if (!damped_) return;
  for (const SpringTerm& s : springs_) {
    if (s.b == 0.0) continue;
    const Vec<D> d = particle_vec<D>(in.q, s.j) - particle_vec<D>(in.q, s.i);
    hessian.add_pair<D>(s.i, s.j, spring_hessian_v<D>(d, s.l0, s.b));
  }
}

template <int D>
std::string SpringSetForce<D>::label() const {
  return label_ + " (" + std::to_string(springs_.size()) + " springs)";
}

template class SpringSetForce<2>;
template class SpringSetForce<3>;

}  // namespace fosssim
