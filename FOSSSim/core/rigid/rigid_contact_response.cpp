#include "core/rigid/rigid_contact_response.h"

#include <algorithm>
#include <sstream>
#include <unordered_map>
#include <utility>

#include "core/solvers/solver_failure.h"

namespace fosssim {

namespace {

/// Index of the representative of x, with path halving.
int find_root(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

/// ηᵀq̇ over the free bodies only.
double free_normal_velocity(const ContactColumn& column, const Vector& v) {
  double g = 0.0;
  for (int k = 0; k < 2; ++k) {
    if (column.body[k] >= 0) g += column.entries[k].dot(v.segment<3>(3 * column.body[k]));
  }
  return g;
}

/// The inverse masses (1/M, 1/M, 1/I) of body b.
Vec<3> inverse_mass(const RigidBodies& bodies, int b) {
  const RigidBody& body = bodies.bodies[b];
  return {1.0 / body.mass, 1.0 / body.mass, 1.0 / body.inertia};
}

void check_normals(const RigidBodies& bodies, const std::vector<RigidContact>& contacts) {
  for (const RigidContact& c : contacts) {
    if (has_finite_normal(c)) continue;
    if (bodies.bodies[c.i0].fixed && bodies.bodies[c.i1].fixed) continue;
    std::ostringstream message;
    message << "rigid bodies " << c.i0 << " and " << c.i1
            << " touch exactly (a vertex lies on the other's edge, at distance 0), so the contact "
               "normal is undefined (the course's program turns velocities into NaN here)";
    throw SolverFailure(message.str());
  }
}

/// The entry A_ij = η_iᵀM⁻¹η_j of two contacts (zero unless they share a free body).
double normal_matrix_entry(const RigidBodies& bodies, const ContactColumn& ci,
                           const ContactColumn& cj) {
  double a = 0.0;
  for (int k = 0; k < 2; ++k) {
    for (int l = 0; l < 2; ++l) {
      if (ci.body[k] >= 0 && ci.body[k] == cj.body[l]) {
        a += ci.entries[k].cwiseProduct(inverse_mass(bodies, ci.body[k])).dot(cj.entries[l]);
      }
    }
  }
  return a;
}

/// What assemble builds besides b and the sparse columns of J.
enum class Assembly {
  kSparse,  ///< J_columns only: what the QP reads
  kLcp,     ///< also the dense A, for the degeneracy test and Dantzig's method
  kDense,   ///< also the dense A and J (assemble_contact_problem, for tests)
};

/// The problem of `contacts` (with their columns): b, J's columns over the group's free bodies
/// (numbered in order of appearance) and, as `assembly` asks, A = NᵀM⁻¹N and J densely. A
/// contact's entries in A are computed only with the contacts sharing a body with it (the
/// others are zero), so the cost is the group's size times its contacts per body, besides
/// clearing a dense A.
ContactProblem assemble(ContactSolver solver, const RigidBodies& bodies, const Vector& q,
                        const Vector& v, const std::vector<const RigidContact*>& contacts,
                        const std::vector<const ContactColumn*>& columns, Assembly assembly) {
  const int m = static_cast<int>(contacts.size());
  ContactProblem problem;
  problem.b.resize(m);
  // The group's free bodies in order of appearance, and the contacts on each.
  std::unordered_map<int, int> local;
  std::vector<std::vector<int>> contacts_of;
  for (int i = 0; i < m; ++i) {
    for (int b : columns[i]->body) {
      if (b < 0) continue;
      const auto [it, added] = local.emplace(b, static_cast<int>(contacts_of.size()));
      if (added) contacts_of.emplace_back();
      contacts_of[it->second].push_back(i);
    }
  }
  // J = M^(−1/2)N, each column's entries in increasing row order (a contact's two bodies by
  // their local numbers), exact zeros left out.
  problem.J_rows = 3 * static_cast<int>(contacts_of.size());
  problem.J_columns.resize(m);
  for (int i = 0; i < m; ++i) {
    int order[2] = {0, 1};
    const ContactColumn& ci = *columns[i];
    if (ci.body[0] >= 0 && ci.body[1] >= 0 && local.at(ci.body[1]) < local.at(ci.body[0])) {
      std::swap(order[0], order[1]);
    }
    for (int k : order) {
      const int b = ci.body[k];
      if (b < 0) continue;
      const Vec<3> entry = ci.entries[k].cwiseProduct(inverse_mass(bodies, b).cwiseSqrt());
      for (int r = 0; r < 3; ++r) {
        if (entry[r] != 0.0) problem.J_columns[i].emplace_back(3 * local.at(b) + r, entry[r]);
      }
    }
  }
  if (assembly == Assembly::kDense) {
    problem.J = Eigen::MatrixXd::Zero(problem.J_rows, m);
    for (int i = 0; i < m; ++i) {
      for (const auto& [row, value] : problem.J_columns[i]) problem.J(row, i) = value;
    }
  }
  if (assembly != Assembly::kSparse) {
    problem.A = Eigen::MatrixXd::Zero(m, m);
    std::vector<int> seen(m, -1);
    for (int i = 0; i < m; ++i) {
      for (int b : columns[i]->body) {
        if (b < 0) continue;
        for (int j : contacts_of[local.at(b)]) {
          if (seen[j] == i) continue;  // shares both bodies with i: done
          seen[j] = i;
          problem.A(i, j) = normal_matrix_entry(bodies, *columns[i], *columns[j]);
        }
      }
    }
  }
  for (int i = 0; i < m; ++i) {
    problem.b[i] = solver == ContactSolver::kLcp
                       ? contact_normal_velocity(bodies, q, v, *contacts[i])
                       : free_normal_velocity(*columns[i], v);
  }
  return problem;
}

}  // namespace

ContactProblem assemble_contact_problem(ContactSolver solver, const RigidBodies& bodies,
                                        const Vector& q, const Vector& v,
                                        const std::vector<RigidContact>& contacts) {
  std::vector<ContactColumn> columns;
  for (const RigidContact& c : contacts) columns.push_back(contact_column(bodies, q, c));
  std::vector<const RigidContact*> members;
  std::vector<const ContactColumn*> member_columns;
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    if (columns[c].body[0] < 0 && columns[c].body[1] < 0) continue;
    members.push_back(&contacts[c]);
    member_columns.push_back(&columns[c]);
  }
  return assemble(solver, bodies, q, v, members, member_columns, Assembly::kDense);
}

ContactColumn contact_column(const RigidBodies& bodies, const Vector& q,
                             const RigidContact& contact) {
  ContactColumn column;
  const Vec2& n = contact.normal;
  const int index[2] = {contact.i0, contact.i1};
  const Vec2* arm[2] = {&contact.arm0, &contact.arm1};
  const double sign[2] = {-1.0, 1.0};
  for (int k = 0; k < 2; ++k) {
    if (bodies.bodies[index[k]].fixed) continue;
    const Vec2 r = rotate(body_angle(q, index[k]), *arm[k]);
    column.body[k] = index[k];
    column.entries[k] = sign[k] * Vec<3>(n.x(), n.y(), cross(r, n));
  }
  return column;
}

double contact_normal_velocity(const RigidBodies& bodies, const Vector& q, const Vector& v,
                               const RigidContact& contact) {
  const auto point_velocity_of = [&](int b, const Vec2& arm) {
    const Vec2 r = rotate(body_angle(q, b), arm);
    const Vec2 V = reported_velocity(bodies, v, b);
    const double omega = reported_omega(bodies, v, b);
    return Vec2(V.x() + -omega * r.y(), V.y() + omega * r.x());
  };
  const Vec2 relative =
      point_velocity_of(contact.i1, contact.arm1) - point_velocity_of(contact.i0, contact.arm0);
  return contact.normal.dot(relative);
}

void apply_inelastic_response(ContactSolver solver, const RigidBodies& bodies, const Vector& q,
                              const std::vector<RigidContact>& contacts, Vector& v,
                              ContactReport& report, int max_group_contacts) {
  check_normals(bodies, contacts);
  // Groups: free bodies joined by contacts; a contact belongs to its free bodies' group.
  // The free bodies of the contacts, numbered in order of appearance (so that the work is
  // proportional to the contacts, not to the scene's bodies: generalized reflections call this
  // once per reflection with the few contacts still approaching).
  std::unordered_map<int, int> node_of;
  std::vector<int> parent;
  const auto node = [&](int body) {
    const auto [it, added] = node_of.emplace(body, static_cast<int>(parent.size()));
    if (added) parent.push_back(it->second);
    return it->second;
  };
  std::vector<ContactColumn> columns;
  std::vector<int> kept;  // indices into contacts
  for (int c = 0; c < static_cast<int>(contacts.size()); ++c) {
    ContactColumn column = contact_column(bodies, q, contacts[c]);
    if (column.body[0] < 0 && column.body[1] < 0) continue;  // two fixed bodies
    for (int b : column.body) {
      if (b >= 0) node(b);
    }
    if (column.body[0] >= 0 && column.body[1] >= 0) {
      parent[find_root(parent, node(column.body[0]))] = find_root(parent, node(column.body[1]));
    }
    columns.push_back(column);
    kept.push_back(c);
  }
  const int n = static_cast<int>(columns.size());
  std::vector<int> group_of_root(parent.size(), -1);  // groups in order of their first contact
  std::vector<std::vector<int>> groups;
  for (int c = 0; c < n; ++c) {
    const int root = find_root(parent, node(columns[c].body[columns[c].body[0] >= 0 ? 0 : 1]));
    if (group_of_root[root] < 0) {
      group_of_root[root] = static_cast<int>(groups.size());
      groups.emplace_back();
    }
    groups[group_of_root[root]].push_back(c);
  }
  for (const std::vector<int>& group : groups) {
    ++report.groups;
    const int m = static_cast<int>(group.size());
    if (m > max_group_contacts) {
      std::ostringstream message;
      message << "rigid-body contact: " << m << " contacts form one group (bodies touching each "
              << "other in a chain or pile), more than the limit of " << max_group_contacts
              << " (its dense matrices would hold " << m << "² doubles); raise "
              << "maxgroupcontacts=\"...\" of <rigidbodycollisionhandling> to solve it";
      throw SolverFailure(message.str());
    }
    std::vector<const RigidContact*> members;
    std::vector<const ContactColumn*> member_columns;
    for (int c : group) {
      members.push_back(&contacts[kept[c]]);
      member_columns.push_back(&columns[c]);
    }
    const ContactProblem problem =
        assemble(solver, bodies, q, v, members, member_columns,
                 solver == ContactSolver::kLcp ? Assembly::kLcp : Assembly::kSparse);
    Vector lambda;
    if (solver == ContactSolver::kLcp) {
      std::string reason;
      if (is_degenerate(problem.A)) {
        reason = "redundant contacts (a singular LCP matrix)";
      } else {
        ContactSolveResult result = solve_contact_lcp_dantzig(problem);
        if (result.valid) {
          lambda = std::move(result.lambda);
        } else {
          reason = result.problem;
        }
      }
      if (!reason.empty()) {
        if (report.fallbacks++ == 0) {
          std::ostringstream where;
          where << reason << ", " << m << " contacts of bodies";
          int shown = 0;
          for (int c : group) {
            if (shown++ < 4) where << " " << contacts[kept[c]].i0 << "-" << contacts[kept[c]].i1;
          }
          if (m > 4) where << " ...";
          report.fallback_reason = where.str();
        }
        lambda = solve_contact_qp(problem, contact_qp_iteration_limit(m));
      }
    } else {
      lambda = solve_contact_qp(problem, contact_qp_iteration_limit(m));
    }
    // q̇ += M⁻¹Nλ on the free bodies.
    for (int i = 0; i < m; ++i) {
      const ContactColumn& column = columns[group[i]];
      for (int k = 0; k < 2; ++k) {
        const int b = column.body[k];
        if (b < 0) continue;
        v.segment<3>(3 * b) +=
            (column.entries[k] * lambda[i]).cwiseProduct(inverse_mass(bodies, b));
      }
    }
  }
}

void apply_generalized_reflections(ContactSolver solver, const RigidBodies& bodies, const Vector& q,
                                   const std::vector<RigidContact>& contacts, int max_reflections,
                                   Vector& v, ContactReport& report, Cancellation cancellation,
                                   int max_group_contacts) {
  check_normals(bodies, contacts);
  std::vector<ContactColumn> columns;
  for (const RigidContact& c : contacts) columns.push_back(contact_column(bodies, q, c));
  std::vector<RigidContact> approaching;
  Vector inelastic = v;  // equal to v outside the bodies of each reflection's contacts
  std::vector<int> touched;
  while (true) {
    approaching.clear();
    for (std::size_t c = 0; c < contacts.size(); ++c) {
      if (free_normal_velocity(columns[c], v) < kReflectionThreshold) {
        approaching.push_back(contacts[c]);
      }
    }
    if (approaching.empty()) return;
    if (report.reflections >= max_reflections) {
      std::ostringstream message;
      message << "rigid-body contact: generalized reflections did not end after " << max_reflections
              << " reflections (" << approaching.size()
              << " contacts still approaching: contacts that cannot all separate elastically, "
                 "such as a body resting on a fixed body that declares a velocity, or bodies "
                 "wedged into each other, never let them end, and the course's program loops "
                 "forever there); raise maxreflections=\"...\" of <rigidbodycollisionhandling> "
                 "if the scene needs more";
      throw SolverFailure(message.str());
    }
    cancellation.check();
    ++report.reflections;
    // Only the free bodies of the approaching contacts change: for every other body the
    // inelastic velocity is v itself and 2v − v = v exactly, so the reflection is applied to
    // those bodies alone, and `inelastic` (equal to v elsewhere) is kept between reflections
    // instead of copied: a reflection costs its contacts, not the scene's bodies.
    touched.clear();
    for (const RigidContact& c : approaching) {
      for (int b : {c.i0, c.i1}) {
        if (!bodies.bodies[b].fixed) touched.push_back(b);
      }
    }
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    apply_inelastic_response(solver, bodies, q, approaching, inelastic, report, max_group_contacts);
    for (int b : touched) {
      v.segment<3>(3 * b) = 2.0 * inelastic.segment<3>(3 * b) - v.segment<3>(3 * b);
      inelastic.segment<3>(3 * b) = v.segment<3>(3 * b);
    }
  }
}

}  // namespace fosssim
