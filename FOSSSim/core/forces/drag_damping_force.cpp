#include "core/forces/drag_damping_force.h"

#include "core/forces/make_for_dim.h"
#include "core/scene_model.h"

namespace fosssim {

template <int D>
void DragDampingForce<D>::add_gradient(const ForceInput& in, Vector& gradient) const {
  gradient += b_ * in.v;
}

template <int D>
void DragDampingForce<D>::add_hessian_v(const ForceInput& in, HessianBuilder& hessian) const {
  for (int dof = 0; dof < in.v.size(); ++dof) hessian.add_diagonal(dof, b_);
}

template class DragDampingForce<2>;
template class DragDampingForce<3>;

std::unique_ptr<Force> make_drag_damping_force(ForceParameters& params,
                                               const ForceContext& context) {
  return make_for_dim<DragDampingForce>(context.model.dim, params.non_negative("b"));
}

}  // namespace fosssim
