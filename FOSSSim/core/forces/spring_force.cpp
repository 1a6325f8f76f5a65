#include "core/forces/spring_force.h"

#include "core/forces/make_for_dim.h"
#include "core/forces/spring_kernel.h"
#include "core/scene_model.h"

namespace fosssim {

// The spring's math is spring_kernel.h's, shared with SpringSetForce (which is tested to give
// the same bits).

template <int D>
Vec<D> SpringForce<D>::extension(const Vector& q) const {
  return particle_vec<D>(q, j_) - particle_vec<D>(q, i_);
}

template <int D>
Vec<D> SpringForce<D>::relative_velocity(const Vector& v) const {
  return particle_vec<D>(v, j_) - particle_vec<D>(v, i_);
}

template <int D>
void SpringForce<D>::add_energy(const ForceInput& in, double& energy) const {
  energy += spring_energy<D>(extension(in.q), k_, l0_);
}

template <int D>
void SpringForce<D>::add_gradient(const ForceInput& in, Vector& gradient) const {
  add_spring_gradient<D>(
      i_, j_, spring_force_on_i<D>(extension(in.q), relative_velocity(in.v), k_, l0_, b_),
      gradient);
}

template <int D>
void SpringForce<D>::add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const {
  const SpringHessianParts<D> parts = spring_hessian_x_parts<D>(
      extension(in.q), relative_velocity(in.v), k_, l0_, b_, in.definite_hessian);
  if (b_ == 0.0) {
    hessian.add_pair<D>(i_, j_, parts.elastic);
  } else {
    hessian.add_pair<D>(i_, j_, Mat<D>(parts.elastic + parts.damping));
  }
}

template <int D>
void SpringForce<D>::add_hessian_v(const ForceInput& in, HessianBuilder& hessian) const {
  if (b_ == 0.0) return;
  const Vec<D> d = extension(in.q);
  if (l0_ == 0.0 && d.norm() == 0.0) return;  // the damping direction is undefined: no entries
  hessian.add_pair<D>(i_, j_, spring_hessian_v<D>(d, l0_, b_));
}

template <int D>
void SpringForce<D>::add_course_hessian_x(const ForceInput& in, HessianBuilder& hessian) const {
  const SpringHessianParts<D> parts = spring_hessian_x_parts<D>(
      extension(in.q), relative_velocity(in.v), k_, l0_, b_, in.definite_hessian);
  hessian.add_pair<D>(i_, j_, parts.elastic);
  hessian.add_pair<D>(i_, j_, parts.damping);
}

template <int D>
void SpringForce<D>::add_course_hessian_v(const ForceInput& in, HessianBuilder& hessian) const {
  const Vec<D> d = extension(in.q);
  if (l0_ == 0.0 && d.norm() == 0.0) return;
  hessian.add_pair<D>(i_, j_, spring_hessian_v<D>(d, l0_, b_));
}

template <int D>
std::string SpringForce<D>::label() const {
  return "springforce(" + std::to_string(i_) + ", " + std::to_string(j_) + ")";
}

template class SpringForce<2>;
template class SpringForce<3>;

std::unique_ptr<Force> make_spring_force(ForceParameters& params, const ForceContext& context) {
  const int e = params.edge_index("edge");
  const double k = params.non_negative("k");
  const double l0 = params.non_negative("l0");
  const double b = params.non_negative_or("b", 0.0);
  const Edge edge = context.model.edges[e];
  const int dim = context.model.dim;
  const auto xi = context.positions.segment(dim * edge.i, dim);
  const auto xj = context.positions.segment(dim * edge.j, dim);
  if (xi == xj && (l0 != 0.0 || b != 0.0)) {
    params.fail("edge " + std::to_string(e) + " has zero length (particles " +
                std::to_string(edge.i) + " and " + std::to_string(edge.j) +
                " coincide), so the spring's direction is undefined");
  }
  return make_for_dim<SpringForce>(dim, edge.i, edge.j, k, l0, b);
}

}  // namespace fosssim
