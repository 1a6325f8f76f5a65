#include "core/forces/rigid_body_wind_force.h"

#include <cmath>

#include "core/forces/rigid_body_gravity_force.h"
#include "core/rigid/rigid_bodies.h"
#include "core/scene_model.h"

namespace fosssim {

RigidBodyWindForce::RigidBodyWindForce(std::shared_ptr<const RigidBodies> bodies, double beta,
                                       const Vec<2>& wind, int points_per_edge)
    : bodies_(std::move(bodies)), beta_(beta), wind_(wind), points_per_edge_(points_per_edge) {}

template <typename Visit>
void RigidBodyWindForce::for_each_sample(const Vector& q, Visit visit) const {
  const double pieces = points_per_edge_;
  for (int b = 0; b < bodies_->size(); ++b) {
    const RigidBody& body = bodies_->bodies[b];
    const int n = body.num_vertices();
    const double theta = body_angle(q, b);
    for (int e = 0; e < n; ++e) {
      const Vec2 a = world_vertex(body, q, b, e);
      const Vec2 edge = rotate(theta, body.body_points[(e + 1) % n] - body.body_points[e]);
      const double length = std::sqrt(edge.x() * edge.x() + edge.y() * edge.y());
      const Vec2 normal(-edge.y() / length, edge.x() / length);
      const double c = beta_ * (1.0 / pieces) * length;
      for (int j = 0; j < points_per_edge_; ++j) {
        const double t = (j + 0.5) / pieces;
        const Vec2 p(a.x() + t * edge.x(), a.y() + t * edge.y());
        visit(b, p, normal, c);
      }
    }
  }
}

void RigidBodyWindForce::add_gradient(const ForceInput& in, Vector& gradient) const {
  for_each_sample(in.q, [&](int b, const Vec2& p, const Vec2& n, double c) {
    const Vec2 relative = wind_ - point_velocity(in.q, in.v, b, p);
    const double push = c * (relative.x() * n.x() + relative.y() * n.y());
    const Vec2 f(push * n.x(), push * n.y());
    const double rx = p.x() - in.q[3 * b], ry = p.y() - in.q[3 * b + 1];
    gradient[3 * b] -= f.x();
    gradient[3 * b + 1] -= f.y();
    gradient[3 * b + 2] -= rx * f.y() - ry * f.x();
  });
}

void RigidBodyWindForce::add_hessian_v(const ForceInput& in, HessianBuilder& hessian) const {
  for_each_sample(in.q, [&](int b, const Vec2& p, const Vec2& n, double c) {
    const double rx = p.x() - in.q[3 * b], ry = p.y() - in.q[3 * b + 1];
    const Eigen::Vector3d u(n.x(), n.y(), rx * n.y() - ry * n.x());
    const Eigen::Matrix3d block = c * u * u.transpose();
    for (int r = 0; r < 3; ++r) {
      for (int s = 0; s < 3; ++s) hessian.add_entry(3 * b + r, 3 * b + s, block(r, s));
    }
  });
}

std::unique_ptr<Force> make_rigid_body_wind_force(ForceParameters& params,
                                                  const ForceContext& context) {
  require_rigid_body_scene(params, context);
  const double beta = params.number("beta");
  if (beta < 0.0) params.fail("beta", "must be non-negative, found " + to_text(beta));
  const Vec<2> wind(params.number("fx"), params.number("fy"));
  const double count = params.number("pointsperedge");
  const double whole = std::trunc(count);
  if (whole < 2.0) params.fail("pointsperedge", "must be at least 2, found " + to_text(count));
  if (whole > kMaxWindPointsPerEdge) {
    params.fail("pointsperedge", "must be at most " + std::to_string(kMaxWindPointsPerEdge) +
                                     ", found " + to_text(count));
  }
  if (whole != count) {
    params.warn("attribute \"pointsperedge\" is not a whole number; read as " + to_text(whole) +
                ", as the course does");
  }
  return std::make_unique<RigidBodyWindForce>(context.model.rigid_bodies, beta, wind,
                                              static_cast<int>(whole));
}

}  // namespace fosssim
