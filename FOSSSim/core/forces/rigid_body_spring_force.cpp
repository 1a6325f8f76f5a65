#include "core/forces/rigid_body_spring_force.h"

#include <cmath>

#include "core/forces/rigid_body_gravity_force.h"
#include "core/rigid/rigid_bodies.h"
#include "core/scene_model.h"

namespace fosssim {

namespace {
constexpr int kWorld = -1;
Vec<2> perp(const Vec<2>& a) { return {-a.y(), a.x()}; }
}  // namespace

RigidBodySpringForce::RigidBodySpringForce(int body_i, const Vec<2>& p_i, int body_j,
                                           const Vec<2>& p_j, double k, double l0)
    : body_i_(body_i), body_j_(body_j), p_i_(p_i), p_j_(p_j), k_(k), l0_(l0) {}

std::string RigidBodySpringForce::label() const {
  const auto name = [](int body) {
    return body == kWorld ? std::string("world") : "body " + std::to_string(body);
  };
  return "rigidbodyspringforce(" + name(body_i_) + " to " + name(body_j_) + ")";
}

RigidBodySpringForce::End RigidBodySpringForce::end(const Vector& q, int body,
                                                    const Vec<2>& p) const {
  if (body == kWorld) return {p, p};
  const Vec<2> arm = rotate(body_angle(q, body), p);
  return {arm, arm + body_center(q, body)};
}

Vec<2> RigidBodySpringForce::separation(const Vector& q, End& ei, End& ej) const {
  ei = end(q, body_i_, p_i_);
  ej = end(q, body_j_, p_j_);
  // The course forms ((R_j p_j − R_i p_i) − X_i) + X_j; a world end has R = identity, X = 0.
  const Vec<2> xi = body_i_ == kWorld ? Vec<2>::Zero() : body_center(q, body_i_);
  const Vec<2> xj = body_j_ == kWorld ? Vec<2>::Zero() : body_center(q, body_j_);
  return ((ej.arm - ei.arm) - xi) + xj;
}

void RigidBodySpringForce::add_energy(const ForceInput& in, double& energy) const {
  End ei, ej;
  const Vec<2> d = separation(in.q, ei, ej);
  const double l = std::sqrt(d.y() * d.y() + d.x() * d.x());
  energy = (0.5 * k_) * (l - l0_) * (l - l0_) + energy;
}

void RigidBodySpringForce::add_gradient(const ForceInput& in, Vector& gradient) const {
  End ei, ej;
  const Vec<2> d = separation(in.q, ei, ej);
  const double l = std::sqrt(d.y() * d.y() + d.x() * d.x());
  if (l0_ == 0.0 && l == 0.0) return;
  const double inverse = 1.0 / l;
  const double s = (l - l0_) * k_;
  const Vec<2> f(d.x() * inverse * s, d.y() * inverse * s);
  if (body_i_ != kWorld) {
    const int k = kRigidBodyCoordinates * body_i_;
    gradient[k] -= f.x();
    gradient[k + 1] -= f.y();
    gradient[k + 2] -= cross(ei.arm, f);
  }
  if (body_j_ != kWorld) {
    const int k = kRigidBodyCoordinates * body_j_;
    gradient[k] += f.x();
    gradient[k + 1] += f.y();
    gradient[k + 2] -= cross(ej.arm, Vec<2>(-f.x(), -f.y()));
  }
}

void RigidBodySpringForce::add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const {
  End ei, ej;
  const Vec<2> d = separation(in.q, ei, ej);
  const double l = std::sqrt(d.squaredNorm());
  Mat<2> hd = k_ * Mat<2>::Identity();  // the limit at l = l0 = 0
  Vec<2> g = Vec<2>::Zero();            // ∇_d U
  if (l > 0.0) {
    const Vec<2> n = d / l;
    hd = k_ * n * n.transpose() + (k_ * (l - l0_) / l) * (Mat<2>::Identity() - n * n.transpose());
    g = k_ * (l - l0_) * n;
  }
  // d = e_j − e_i; ∂e/∂(X, θ) = [I | perp(R p)], ∂²e/∂θ² = −R p.
  struct Side {
    int body;
    Eigen::Matrix<double, 2, 3> jacobian;
  };
  Side sides[2];
  int count = 0;
  for (const auto& [body, arm, sign] :
       {std::tuple{body_i_, ei.arm, -1.0}, std::tuple{body_j_, ej.arm, 1.0}}) {
    if (body == kWorld) continue;
    Eigen::Matrix<double, 2, 3> jacobian;
    jacobian.leftCols<2>() = sign * Mat<2>::Identity();
    jacobian.col(2) = sign * perp(arm);
    sides[count++] = {body, jacobian};
    hessian.add_entry(kRigidBodyCoordinates * body + 2, kRigidBodyCoordinates * body + 2,
                      -sign * g.dot(arm));
  }
  for (int a = 0; a < count; ++a) {
    for (int b = 0; b < count; ++b) {
      const Eigen::Matrix3d block = sides[a].jacobian.transpose() * hd * sides[b].jacobian;
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
          hessian.add_entry(kRigidBodyCoordinates * sides[a].body + r,
                            kRigidBodyCoordinates * sides[b].body + c, block(r, c));
        }
      }
    }
  }
}

std::unique_ptr<Force> make_rigid_body_spring_force(ForceParameters& params,
                                                    const ForceContext& context) {
  require_rigid_body_scene(params, context);
  const int bodies = context.model.num_particles();
  auto body_index = [&](const char* name) {
    const double value = params.number(name);
    const double whole = std::trunc(value);
    if (whole < -1.0 || whole >= bodies) {
      params.fail(name, "refers to body " + to_text(whole) + ", but the scene has " +
                            std::to_string(bodies) + " bodies (valid: −1 for a world point, 0 to " +
                            std::to_string(bodies - 1) + ")");
    }
    if (whole != value) {
      params.warn(std::string("attribute \"") + name + "\" is not a whole number; read as " +
                  to_text(whole) + ", as the course does");
    }
    return static_cast<int>(whole);
  };
  const int i = body_index("i");
  const Vec<2> p_i(params.number("pix"), params.number("piy"));
  const int j = body_index("j");
  const Vec<2> p_j(params.number("pjx"), params.number("pjy"));
  const double k = params.number("k");
  const double l0 = params.number("l0");
  if (k < 0.0)
    params.warn("negative stiffness k = " + to_text(k) + " (accepted, as the course does)");
  if (l0 < 0.0)
    params.warn("negative rest length l0 = " + to_text(l0) + " (accepted, as the course does)");
  if (i == j) {
    params.warn(i == kWorld ? "both ends are world points: the spring does nothing"
                            : "both ends are on body " + std::to_string(i) +
                                  ": the spring exerts no net force or torque on it");
  }
  return std::make_unique<RigidBodySpringForce>(i, p_i, j, p_j, k, l0);
}

}  // namespace fosssim
