#include "core/rigid/rigid_bodies.h"

#include <cassert>
#include <cmath>

namespace fosssim {

MassProperties compute_mass_properties(std::span<const Vec2> points,
                                       std::span<const double> masses) {
  assert(points.size() == masses.size() && !masses.empty());
  const std::size_t n = masses.size();
  MassProperties out;
  // The course sums pairs: even and odd entries separately, then the odd one out.
  double even = 0.0, odd = 0.0;
  std::size_t k = 0;
  for (; k + 1 < n; k += 2) {
    even += masses[k];
    odd += masses[k + 1];
  }
  out.mass = even + odd;
  if (k < n) out.mass += masses[k];
  Vec2 moment = Vec2::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    moment.x() += points[i].x() * masses[i];
    moment.y() += points[i].y() * masses[i];
  }
  const double inverse = 1.0 / out.mass;
  out.center = {moment.x() * inverse, moment.y() * inverse};
  for (std::size_t i = 0; i < n; ++i) {
    const double dy = points[i].y() - out.center.y();
    const double dx = points[i].x() - out.center.x();
    out.inertia += masses[i] * (dy * dy + dx * dx);
  }
  return out;
}

Vec2 rotate(double theta, const Vec2& p) {
  const double c = std::cos(theta), s = std::sin(theta);
  return {c * p.x() - s * p.y(), s * p.x() + c * p.y()};
}

Vec2 world_vertex(const RigidBody& body, const Vector& q, int b, int k) {
  const Vec2 r = rotate(body_angle(q, b), body.body_points[k]);
  return {r.x() + q[3 * b], r.y() + q[3 * b + 1]};
}

Vec2 point_velocity(const Vector& q, const Vector& v, int b, const Vec2& p) {
  const double omega = v[3 * b + 2];
  const double rx = p.x() - q[3 * b], ry = p.y() - q[3 * b + 1];
  return {v[3 * b] + -omega * ry, v[3 * b + 1] + omega * rx};
}

Vec2 reported_velocity(const RigidBodies& bodies, const Vector& v, int b) {
  const RigidBody& body = bodies.bodies[b];
  return body.fixed ? body.reported_velocity : Vec2(v[3 * b], v[3 * b + 1]);
}

double reported_omega(const RigidBodies& bodies, const Vector& v, int b) {
  const RigidBody& body = bodies.bodies[b];
  return body.fixed ? body.reported_omega : v[3 * b + 2];
}

BodyQuantities compute_body_quantities(const RigidBodies& bodies, const Vector& q, const Vector& v,
                                       int b) {
  const RigidBody& body = bodies.bodies[b];
  const Vec2 V = reported_velocity(bodies, v, b);
  const double omega = reported_omega(bodies, v, b);
  const double M = body.mass, I = body.inertia;
  const Vec2 X = body_center(q, b);
  BodyQuantities out;
  out.momentum = {M * V.x(), M * V.y()};
  out.orbital_angular_momentum = (X.x() * V.y() - X.y() * V.x()) * M;
  out.spin_angular_momentum = I * omega;
  out.orbital_kinetic_energy = (0.5 * M) * (V.y() * V.y() + V.x() * V.x());
  out.spin_kinetic_energy = (0.5 * I) * omega * omega;
  return out;
}

}  // namespace fosssim
