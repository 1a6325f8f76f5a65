#include "core/forces/spring_force.h"

#include <algorithm>

#include "core/forces/make_for_dim.h"
#include "core/scene_model.h"

namespace fosssim {

template <int D>
void SpringForce<D>::add_energy(const ForceInput& in, double& energy) const {
  const Vec<D> d = particle_vec<D>(in.q, j_) - particle_vec<D>(in.q, i_);
  const double stretch = d.norm() - l0_;
  energy += 0.5 * k_ * stretch * stretch;
}

template <int D>
void SpringForce<D>::add_gradient(const ForceInput& in, Vector& gradient) const {
  const Vec<D> d = particle_vec<D>(in.q, j_) - particle_vec<D>(in.q, i_);
  const double l = d.norm();
  Vec<D> force_i;
  if (l == 0.0 && l0_ == 0.0) {
    force_i = k_ * d;
  } else {
    const Vec<D> n = d / l;
    force_i = k_ * (l - l0_) * n;
    if (b_ != 0.0) {
      const Vec<D> dv = particle_vec<D>(in.v, j_) - particle_vec<D>(in.v, i_);
      force_i += b_ * n.dot(dv) * n;
    }
  }
  gradient.template segment<D>(D * i_) -= force_i;
  gradient.template segment<D>(D * j_) += force_i;
}

template <int D>
void SpringForce<D>::add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const {
  const Vec<D> d = particle_vec<D>(in.q, j_) - particle_vec<D>(in.q, i_);
  const double l = d.norm();
  const Mat<D> I = Mat<D>::Identity();
  if (l == 0.0 && l0_ == 0.0) {
    hessian.add_pair<D>(i_, j_, k_ * I);
    return;
  }
  const Vec<D> n = d / l;
  const Mat<D> P = n * n.transpose();
  double transverse = (l - l0_) / l;
  if (hessian.project_definite()) transverse = std::max(transverse, 0.0);
  Mat<D> H = k_ * (P + transverse * (I - P));
  if (b_ != 0.0) {
    const Vec<D> dv = particle_vec<D>(in.v, j_) - particle_vec<D>(in.v, i_);
    H += (b_ / l) * (n * dv.transpose() + n.dot(dv) * I) * (I - P);
  }
  hessian.add_pair<D>(i_, j_, H);
}

template <int D>
void SpringForce<D>::add_hessian_v(const ForceInput& in, HessianBuilder& hessian) const {
  if (b_ == 0.0) return;
  const Vec<D> d = particle_vec<D>(in.q, j_) - particle_vec<D>(in.q, i_);
  const double l = d.norm();
  if (l == 0.0 && l0_ == 0.0) return;  // the damping direction is undefined, as in add_gradient
  const Vec<D> n = d / l;
  hessian.add_pair<D>(i_, j_, Mat<D>(b_ * n * n.transpose()));
}

template <int D>
bool SpringForce<D>::append_springs(std::vector<SpringTerm>& springs) const {
  springs.push_back({i_, j_, k_, l0_, b_});
  return true;
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
