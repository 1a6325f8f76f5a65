#pragma once
// The numbering of the unknowns that remain when some particles are eliminated.

#include <vector>

#include "core/types.h"

namespace fosssim {

/// The particles that are not eliminated, and their degrees of freedom, numbered in order:
/// the selection P of q = Pᵀ q̂ + q_eliminated. Implicit methods eliminate fixed particles
/// (their positions are known), so their systems only hold the free unknowns.
class FreeDofs {
 public:
  FreeDofs() = default;
  /// Every particle p with eliminated[p] false is free; dim is 2 or 3.
  FreeDofs(const std::vector<bool>& eliminated, int dim);

  int dim() const { return dim_; }
  int num_particles() const { return static_cast<int>(particles_.size()); }
  int num_dofs() const { return dim_ * num_particles(); }
  /// The free number of particle p, or -1 when p is eliminated.
  int of_particle(int p) const { return free_index_[p]; }
  /// The free number of degree of freedom `dof` (dim·p + c), or -1.
  int of_dof(int dof) const {
    const int f = free_index_[dof / dim_];
    return f < 0 ? -1 : dim_ * f + dof % dim_;
  }
  /// Free number → particle.
  const std::vector<int>& particles() const { return particles_; }

  /// P x: the entries of the free DOFs of a full vector.
  Vector restrict(const Vector& x) const;
  /// full += Pᵀ x.
  void add_expanded(const Vector& x, Vector& full) const;

 private:
  int dim_ = 2;
  std::vector<int> free_index_;  // particle -> free number, or -1
  std::vector<int> particles_;   // free number -> particle
};

}  // namespace fosssim
