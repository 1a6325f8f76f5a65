#include "core/systems/local_global_system.h"

#include <string>

#include "core/error.h"

namespace fosssim {

MassSpringForces sort_mass_spring_forces(const ForceSet& forces) {
  MassSpringForces out;
  for (const Force* force : forces) {
    switch (force->local_global_role()) {
      case LocalGlobalRole::kSprings:
        force->append_local_global_springs(out.springs);
        break;
      case LocalGlobalRole::kAnchor:
        out.anchors.push_back(force);
        break;
      case LocalGlobalRole::kContact:
        if (out.contact != nullptr) {
          throw Error(ErrorKind::kBadInput, "local/global: two contact forces, " +
                                                out.contact->label() + " and " + force->label() +
                                                "; it takes one penalty force");
        }
        out.contact = force;
        out.others.push_back(force);
        break;
      case LocalGlobalRole::kExplicit:
        out.others.push_back(force);
        break;
      case LocalGlobalRole::kUndeclared:
        out.undeclared.push_back(force);
        break;
    }
  }
  return out;
}

void check_local_global_roles(const MassSpringForces& sorted, std::string_view solver) {
  if (sorted.undeclared.empty()) return;
  std::string message = std::string(solver) + ": the force " + sorted.undeclared.front()->label() +
                        " does not say how it enters the local/global solver (springs, anchor, "
                        "contact or explicit; Force::local_global_role), so this integrator "
                        "cannot take it";
  if (sorted.undeclared.size() > 1) {
    message += " (nor " + std::to_string(sorted.undeclared.size() - 1) + " other force(s))";
  }
  throw Error(ErrorKind::kBadInput, message + "; choose another integrator");
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
