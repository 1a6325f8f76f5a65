#include "core/forces/simple_gravity_force.h"

#include "core/forces/make_for_dim.h"
#include "core/scene_model.h"

namespace fosssim {

template <int D>
void SimpleGravityForce<D>::add_energy(const ForceInput& in, double& energy) const {
  const int n = static_cast<int>(in.q.size()) / D;
  for (int p = 0; p < n; ++p) energy -= in.mass[D * p] * g_.dot(particle_vec<D>(in.q, p));
}

template <int D>
void SimpleGravityForce<D>::add_gradient(const ForceInput& in, Vector& gradient) const {
  const int n = static_cast<int>(in.q.size()) / D;
  for (int p = 0; p < n; ++p) gradient.template segment<D>(D * p) -= in.mass[D * p] * g_;
}

template class SimpleGravityForce<2>;
template class SimpleGravityForce<3>;

std::unique_ptr<Force> make_simple_gravity_force(ForceParameters& params,
                                                 const ForceContext& context) {
  if (context.model.dim == 3)
    return std::make_unique<SimpleGravityForce<3>>(params.vector<3>("fx", "fy", "fz"));
  return std::make_unique<SimpleGravityForce<2>>(params.vector<2>("fx", "fy", "fz"));
}

}  // namespace fosssim
