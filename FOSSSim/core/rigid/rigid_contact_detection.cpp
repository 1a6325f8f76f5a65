#include "core/rigid/rigid_contact_detection.h"

#include <algorithm>
#include <cmath>

#include "core/collisions/box_grid.h"

namespace fosssim {

namespace {

/// -1, 0, 1 for a before, equal to, after b within the tolerance.
int compare(double a, double b) {
  if (std::fabs(a - b) > RigidContactOrder::kTolerance) return a < b ? -1 : 1;
  return 0;
}

/// R(θ)ᵀ u: the body-space vector of the world vector u.
Vec2 unrotate(double theta, const Vec2& u) {
  const double c = std::cos(theta), s = std::sin(theta);
  return {c * u.x() + s * u.y(), -s * u.x() + c * u.y()};
}

}  // namespace

bool RigidContactOrder::operator()(const RigidContact& a, const RigidContact& b) const {
  if (a.i0 != b.i0) return a.i0 < b.i0;
  if (a.i1 != b.i1) return a.i1 < b.i1;
  const double left[6] = {a.arm0.x(), a.arm0.y(),   a.arm1.x(),
                          a.arm1.y(), a.normal.x(), a.normal.y()};
  const double right[6] = {b.arm0.x(), b.arm0.y(),   b.arm1.x(),
                           b.arm1.y(), b.normal.x(), b.normal.y()};
  for (int k = 0; k < 6; ++k) {
    if (const int c = compare(left[k], right[k]); c != 0) return c < 0;
  }
  return false;
}

bool test_vertex_edge(const RigidBodies& bodies, const Vector& q, int a, const Vec2& p, int b,
                      const Vec2& e0, const Vec2& e1, RigidContact& out) {
  const double ra = bodies.bodies[a].radius, rb = bodies.bodies[b].radius;
  const double ex = e1.x() - e0.x(), ey = e1.y() - e0.y();
  double alpha = ((p.y() - e0.y()) * ey + (p.x() - e0.x()) * ex) / (ey * ey + ex * ex);
  alpha = alpha > 0.0 ? std::min(alpha, 1.0) : 0.0;  // NaN (a zero-length edge) → 0
  const Vec2 c(e0.x() + alpha * ex, e0.y() + alpha * ey);
  const Vec2 n(c.x() - p.x(), c.y() - p.y());
  const double d = std::sqrt(n.y() * n.y() + n.x() * n.x());
  if (!(d < ra + rb)) return false;
  const double inv = 1.0 / d;
  const Vec2 unit(n.x() * inv, n.y() * inv);
  const Vec2 qa(unit.x() * ra + p.x(), unit.y() * ra + p.y());
  const Vec2 qb(c.x() - unit.x() * rb, c.y() - unit.y() * rb);
  const Vec2 arm_a = unrotate(body_angle(q, a), qa - body_center(q, a));
  const Vec2 arm_b = unrotate(body_angle(q, b), qb - body_center(q, b));
  if (a < b) {
    out = {a, b, arm_a, arm_b, unit};
  } else {
    out = {b, a, arm_b, arm_a, -unit};
  }
  return true;
}

namespace {

/// Every vertex of body a against every edge of body b, world vertices precomputed.
void add_vertices_against_edges(const RigidBodies& bodies, const Vector& q, int a,
                                const std::vector<Vec2>& va, int b, const std::vector<Vec2>& vb,
                                RigidContactSet& set) {
  const int n = static_cast<int>(vb.size());
  RigidContact contact;
  for (const Vec2& p : va) {
    for (int e = 0; e < n; ++e) {
      if (test_vertex_edge(bodies, q, a, p, b, vb[e], vb[(e + 1) % n], contact)) {
        set.insert(contact);
      }
    }
  }
}

std::vector<Vec2> world_vertices(const RigidBodies& bodies, const Vector& q, int b) {
  const RigidBody& body = bodies.bodies[b];
  std::vector<Vec2> out(body.num_vertices());
  for (int k = 0; k < body.num_vertices(); ++k) out[k] = world_vertex(body, q, b, k);
  return out;
}

}  // namespace

void add_pair_contacts(const RigidBodies& bodies, const Vector& q, int i, int j,
                       RigidContactSet& set) {
  const std::vector<Vec2> vi = world_vertices(bodies, q, i), vj = world_vertices(bodies, q, j);
  add_vertices_against_edges(bodies, q, i, vi, j, vj, set);
  add_vertices_against_edges(bodies, q, j, vj, i, vi, set);
}

std::vector<RigidContact> detect_rigid_contacts_all_pairs(const RigidBodies& bodies,
                                                          const Vector& q) {
  RigidContactSet set;
  for (int i = 0; i < bodies.size(); ++i) {
    for (int j = i + 1; j < bodies.size(); ++j) add_pair_contacts(bodies, q, i, j, set);
  }
  return {set.begin(), set.end()};
}

std::vector<std::pair<int, int>> rigid_candidate_pairs(const RigidBodies& bodies, const Vector& q) {
  const int n = bodies.size();
  std::vector<std::pair<int, int>> pairs;
  std::vector<Box<2>> boxes(n);
  bool finite = true;
  double scale = 0.0;
  for (int b = 0; b < n; ++b) {
    const RigidBody& body = bodies.bodies[b];
    Box<2> box{Vec2::Constant(INFINITY), Vec2::Constant(-INFINITY)};
    for (int k = 0; k < body.num_vertices(); ++k) {
      const Vec2 p = world_vertex(body, q, b, k);
      box.lo = box.lo.cwiseMin(p);
      box.hi = box.hi.cwiseMax(p);
    }
    finite = finite && box.lo.allFinite() && box.hi.allFinite() && std::isfinite(body.radius);
    boxes[b] = box;
    if (finite)
      scale = std::max({scale, box.lo.cwiseAbs().maxCoeff(), box.hi.cwiseAbs().maxCoeff()});
  }
  if (!finite) {  // the tests of non-finite positions are left to the narrow phase
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) pairs.emplace_back(i, j);
    }
    return pairs;
  }
  // Grown by the radius and a round-off allowance: the narrow phase's distance is computed
  // with a few roundings of coordinates of size `scale`, far less than 1e-12 of it.
  std::vector<double> extents(n);
  for (int b = 0; b < n; ++b) {
    const double grow = bodies.bodies[b].radius * (1.0 + 1e-12) + 1e-12 * scale + 1e-300;
    boxes[b].lo.array() -= grow;
    boxes[b].hi.array() += grow;
    extents[b] = boxes[b].extent();
  }
  if (n < 2) return pairs;
  std::nth_element(extents.begin(), extents.begin() + n / 2, extents.end());
  const double cell = std::max(extents[n / 2], 1e-300);
  BoxGrid<2> grid;
  grid.build(boxes, cell);
  for (int i = 0; i < n; ++i) {
    // Boxes at i's level and coarser; those at finer levels find i themselves.
    grid.query(boxes[i], grid.level_of(i), [&](int j) {
      if (j != i) pairs.emplace_back(std::min(i, j), std::max(i, j));
    });
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

std::vector<RigidContact> detect_rigid_contacts(const RigidBodies& bodies, const Vector& q) {
  RigidContactSet set;
  for (const auto& [i, j] : rigid_candidate_pairs(bodies, q))
    add_pair_contacts(bodies, q, i, j, set);
  return {set.begin(), set.end()};
}

bool has_finite_normal(const RigidContact& contact) {
  return std::isfinite(contact.normal.x()) && std::isfinite(contact.normal.y());
}

}  // namespace fosssim
