#include "core/systems/free_dofs.h"

namespace fosssim {

FreeDofs::FreeDofs(const std::vector<bool>& eliminated, int dim) : dim_(dim) {
  const int n = static_cast<int>(eliminated.size());
  free_index_.assign(n, -1);
  for (int p = 0; p < n; ++p) {
    if (eliminated[p]) continue;
    free_index_[p] = static_cast<int>(particles_.size());
    particles_.push_back(p);
  }
}

Vector FreeDofs::restrict(const Vector& x) const {
  Vector out(num_dofs());
  for (int f = 0; f < num_particles(); ++f) {
    out.segment(dim_ * f, dim_) = x.segment(dim_ * particles_[f], dim_);
  }
  return out;
}

void FreeDofs::add_expanded(const Vector& x, Vector& full) const {
  for (int f = 0; f < num_particles(); ++f) {
    for (int c = 0; c < dim_; ++c) full[dim_ * particles_[f] + c] += x[dim_ * f + c];
  }
}

}  // namespace fosssim
