#include "core/systems/local_global_system.h"

#include "core/collisions/penalty_force.h"
#include "core/forces/spring_force.h"
#include "core/forces/spring_set_force.h"

namespace fosssim {

namespace {

/// Appends the springs of `force` when it is made of springs; false otherwise.
template <int D>
bool append_springs(const Force& force, std::vector<SpringTerm>& springs) {
  if (const auto* spring = dynamic_cast<const SpringForce<D>*>(&force)) {
    springs.push_back(spring->term());
    return true;
  }
  if (const auto* set = dynamic_cast<const SpringSetForce<D>*>(&force)) {
    springs.insert(springs.end(), set->springs().begin(), set->springs().end());
    return true;
  }
  return false;
}

}  // namespace

MassSpringForces sort_mass_spring_forces(const ForceSet& forces) {
  MassSpringForces out;
  const int dim = forces.model().dim;
  for (const Force* force : forces) {
    const bool spring =
        dim == 3 ? append_springs<3>(*force, out.springs) : append_springs<2>(*force, out.springs);
    if (spring) continue;
    if (const auto* anchor = dynamic_cast<const DragSpringForce*>(force)) {
      out.anchors.push_back(anchor);
    } else {
      out.others.push_back(force);
      if (dynamic_cast<const PenaltyForce<2>*>(force) != nullptr ||
          dynamic_cast<const PenaltyForce<3>*>(force) != nullptr) {
        out.contact = force;
      }
    }
  }
  return out;
}

SparseMatrix assemble_local_global_matrix(const Vector& mass, const FreeDofs& free,
                                          std::span<const SpringTerm> springs,
                                          std::span<const AnchorTerm> anchors, double h) {
  const int n = free.num_particles();
  const int dim = free.dim();
  const double h2 = h * h;
  std::vector<Triplet> triplets;
  triplets.reserve(n + 4 * springs.size() + anchors.size());
  for (int f = 0; f < n; ++f) triplets.emplace_back(f, f, mass[dim * free.particles()[f]] / h2);
  for (const SpringTerm& s : springs) {
    const int fi = free.of_particle(s.i);
    const int fj = free.of_particle(s.j);
    const double w = s.k + s.b / h;
    if (fi >= 0) triplets.emplace_back(fi, fi, w);
    if (fj >= 0) triplets.emplace_back(fj, fj, w);
    if (fi >= 0 && fj >= 0) {
      triplets.emplace_back(fi, fj, -w);
      triplets.emplace_back(fj, fi, -w);
    }
  }
  for (const AnchorTerm& a : anchors)
    triplets.emplace_back(free.of_particle(a.i), free.of_particle(a.i), a.k);
  SparseMatrix Q(n, n);
  Q.setFromTriplets(triplets.begin(), triplets.end());
  return Q;
}

}  // namespace fosssim
