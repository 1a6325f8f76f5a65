#include "core/forces/vortex_force.h"

#include "core/forces/pair_checks.h"
#include "core/forces/ordered_arithmetic.h"
#include "core/scene_model.h"

namespace fosssim {

template <int D>
void VortexForce<D>::add_gradient(const ForceInput& in, Vector& gradient) const {
  // In 2D the course's order of operations (docs/forces.md, 'Course-exact arithmetic'):
  // n = d × (1/l), w_c = (((R n)_c kbs - dv_c) × (1/(l l))) kvc.
  const Vec<D> d = particle_vec<D>(in.q, j_) - particle_vec<D>(in.q, i_);
  const Vec<D> dv = particle_vec<D>(in.v, j_) - particle_vec<D>(in.v, i_);
  if constexpr (D == 3) {  // FOSSSim's own order in 3D, where there is no course to match
    const double l = d.norm();
    const Vec<D> w = (kvc_ / (l * l)) * (kbs_ * (rotation_ * (d / l)) - dv);
    gradient.template segment<D>(D * i_) += w;
    gradient.template segment<D>(D * j_) -= w;
  } else {
    const double l = ordered_norm<D>(d);
    const double r = 1.0 / l;
    const double inverse_square = 1.0 / (l * l);
    const double nx = d[0] * r, ny = d[1] * r;
    const double turned[2] = {-ny, nx};  // R n, the quarter turn, exactly
    for (int c = 0; c < 2; ++c) {
      const double w = ((turned[c] * kbs_ - dv[c]) * inverse_square) * kvc_;
      gradient[D * i_ + c] = gradient[D * i_ + c] + w;
      gradient[D * j_ + c] = gradient[D * j_ + c] - w;
    }
  }
}

template <int D>
void VortexForce<D>::add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const {
  const Vec<D> d = particle_vec<D>(in.q, j_) - particle_vec<D>(in.q, i_);
  const Vec<D> dv = particle_vec<D>(in.v, j_) - particle_vec<D>(in.v, i_);
  const double l = d.norm();
  const double l2 = l * l;
  const double l3 = l2 * l;
  const Mat<D> J =
      kvc_ * (kbs_ * (rotation_ / l3 - (3.0 / (l3 * l2)) * rotation_ * d * d.transpose()) +
              (2.0 / (l2 * l2)) * dv * d.transpose());
  hessian.add_pair<D>(i_, j_, Mat<D>(-J));
}

template <int D>
void VortexForce<D>::add_hessian_v(const ForceInput& in, HessianBuilder& hessian) const {
  const Vec<D> d = particle_vec<D>(in.q, j_) - particle_vec<D>(in.q, i_);
  hessian.add_pair<D>(i_, j_, Mat<D>((kvc_ / d.squaredNorm()) * Mat<D>::Identity()));
}

template <int D>
std::string VortexForce<D>::label() const {
  return "vortexforce(" + std::to_string(i_) + ", " + std::to_string(j_) + ")";
}

template class VortexForce<2>;
template class VortexForce<3>;

std::unique_ptr<Force> make_vortex_force(ForceParameters& params, const ForceContext& context) {
  const auto [i, j] = read_distinct_separated_pair(params, context);
  const double kbs = params.number("kbs");
  const double kvc = params.number("kvc");
  if (context.model.dim == 2) {
    Mat<2> rotation;
    rotation << 0.0, -1.0, 1.0, 0.0;
    return std::make_unique<VortexForce<2>>(i, j, kbs, kvc, rotation);
  }
  Vec<3> axis(params.number_or("ax", 0.0), params.number_or("ay", 0.0),
              params.number_or("az", 1.0));
  if (axis.norm() == 0.0) params.fail("ax", "the vortex axis (ax, ay, az) must not be zero");
  axis.normalize();
  Mat<3> rotation;  // the cross-product matrix: rotation * a = axis × a
  rotation << 0.0, -axis.z(), axis.y(), axis.z(), 0.0, -axis.x(), -axis.y(), axis.x(), 0.0;
  return std::make_unique<VortexForce<3>>(i, j, kbs, kvc, rotation);
}

}  // namespace fosssim
