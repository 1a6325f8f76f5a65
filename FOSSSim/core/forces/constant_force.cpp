#include "core/forces/constant_force.h"

#include "core/scene_model.h"

namespace fosssim {

template <int D>
void ConstantForce<D>::add_energy(const ForceInput& in, double& energy) const {
  const int n = static_cast<int>(in.q.size()) / D;
  for (int p = 0; p < n; ++p) energy -= f_.dot(particle_vec<D>(in.q, p));
}

template <int D>
void ConstantForce<D>::add_gradient(const ForceInput& in, Vector& gradient) const {
  const int n = static_cast<int>(in.q.size()) / D;
  for (int p = 0; p < n; ++p) gradient.template segment<D>(D * p) -= f_;
}

template class ConstantForce<2>;
template class ConstantForce<3>;

std::unique_ptr<Force> make_constant_force(ForceParameters& params, const ForceContext& context) {
  if (context.model.dim == 3)
    return std::make_unique<ConstantForce<3>>(params.vector<3>("fx", "fy", "fz"));
  return std::make_unique<ConstantForce<2>>(params.vector<2>("fx", "fy", "fz"));
}

}  // namespace fosssim
