#include "core/forces/elastic_body_bending_force.h"

#include <array>
#include <cmath>
#include <tuple>

#include "core/forces/psd_projection.h"
#include "core/scene_model.h"

namespace fosssim {

namespace {

using Vec2 = Vec<2>;
using Mat2 = Mat<2>;

/// R e / |e|²: the gradient of the direction angle of e with respect to e.
Vec2 angle_gradient(const Vec2& e) { return Vec2(-e[1], e[0]) / e.squaredNorm(); }

/// J(e), the derivative of R e / |e|² with respect to e (symmetric, trace-free).
Mat2 angle_hessian(const Vec2& e) {
  const double a = e[0];
  const double b = e[1];
  const double s = e.squaredNorm();
  Mat2 J;
  J << 2.0 * a * b, b * b - a * a, b * b - a * a, -2.0 * a * b;
  return J / (s * s);
}

}  // namespace

double ElasticBodyBendingForce::angle(const Vector& q) const {
  const Vec2 e1 = particle_vec<2>(q, i2_) - particle_vec<2>(q, i1_);
  const Vec2 e2 = particle_vec<2>(q, i3_) - particle_vec<2>(q, i2_);
  return std::atan2(cross(e1, e2), e1.dot(e2));
}

void ElasticBodyBendingForce::add_energy(const ForceInput& in, double& energy) const {
  const double deviation = angle(in.q) - theta0_;
  energy += alpha_ * deviation * deviation / (2.0 * rest_length_);
}

void ElasticBodyBendingForce::append_elements(const Vector& q,
                                              std::vector<ForceElement>& elements) const {
  ForceElement element;
  element.kind = ForceElement::Kind::kHinge;
  element.particles = {i1_, i2_, i3_};
  element.strain = angle(q) - theta0_;
  element.energy_density = alpha_ * element.strain * element.strain / (2.0 * rest_length_ * rest_length_);
  elements.push_back(element);
}

void ElasticBodyBendingForce::add_gradient(const ForceInput& in, Vector& gradient) const {
  const Vec2 e1 = particle_vec<2>(in.q, i2_) - particle_vec<2>(in.q, i1_);
  const Vec2 e2 = particle_vec<2>(in.q, i3_) - particle_vec<2>(in.q, i2_);
  const double c = alpha_ / rest_length_ * (angle(in.q) - theta0_);
  const Vec2 g1 = angle_gradient(e1);
  const Vec2 g3 = angle_gradient(e2);
  gradient.segment<2>(2 * i1_) += c * g1;
  gradient.segment<2>(2 * i2_) += c * (-g1 - g3);
  gradient.segment<2>(2 * i3_) += c * g3;
}

void ElasticBodyBendingForce::add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const {
  const Vec2 e1 = particle_vec<2>(in.q, i2_) - particle_vec<2>(in.q, i1_);
  const Vec2 e2 = particle_vec<2>(in.q, i3_) - particle_vec<2>(in.q, i2_);
  const double scale = alpha_ / rest_length_;
  const double deviation = angle(in.q) - theta0_;
  const std::array<Vec2, 3> grad = {angle_gradient(e1), Vec2(-angle_gradient(e1) - angle_gradient(e2)),
                                    angle_gradient(e2)};
  const Mat2 J1 = angle_hessian(e1);
  const Mat2 J2 = angle_hessian(e2);
  const Mat2 zero = Mat2::Zero();
  const std::array<std::array<Mat2, 3>, 3> second = {{{Mat2(-J1), J1, zero},
                                                      {J1, Mat2(J2 - J1), Mat2(-J2)},
                                                      {zero, Mat2(-J2), J2}}};
  // The 6×6 element block, projected as a whole when asked, added block by block either way.
  Eigen::Matrix<double, 6, 6> element;
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      element.block<2, 2>(2 * a, 2 * b) =
          scale * (grad[a] * grad[b].transpose() + deviation * second[a][b]);
    }
  }
  if (in.definite_hessian) element = projected_to_semidefinite<6>(element);
  const std::array<int, 3> particles = {i1_, i2_, i3_};
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      hessian.add_block<2>(particles[a], particles[b], Mat2(element.block<2, 2>(2 * a, 2 * b)));
    }
  }
}

std::string ElasticBodyBendingForce::label() const {
  return "elasticbodybendingforce(" + std::to_string(i1_) + ", " + std::to_string(i2_) + ", " +
         std::to_string(i3_) + ")";
}

std::unique_ptr<Force> make_elastic_body_bending_force(ForceParameters& params,
                                                       const ForceContext& context) {
  if (context.model.dim != 2) {
    params.fail(
        "a bending force needs a plane for its signed angle, so it exists in 2D scenes only "
        "(this scene has dim=\"3\")");
  }
  const int i1 = params.particle_index("i1");
  const int i2 = params.particle_index("i2");
  const int i3 = params.particle_index("i3");
  if (i2 == i1) params.fail("i2", "must differ from i1 (both are " + std::to_string(i1) + ")");
  if (i3 == i1) params.fail("i3", "must differ from i1 (both are " + std::to_string(i1) + ")");
  if (i3 == i2) params.fail("i3", "must differ from i2 (both are " + std::to_string(i2) + ")");
  const double alpha = params.non_negative("alpha");
  const double theta0 = params.number("theta0");
  const Vector& x = context.positions;
  const double edge1 = (particle_vec<2>(x, i2) - particle_vec<2>(x, i1)).norm();
  const double edge2 = (particle_vec<2>(x, i3) - particle_vec<2>(x, i2)).norm();
  for (const auto& [length, a, b] : {std::tuple{edge1, i1, i2}, std::tuple{edge2, i2, i3}}) {
    if (length == 0.0) {
      params.fail("particles " + std::to_string(a) + " and " + std::to_string(b) +
                  " start at the same point: the hinge's edge has no direction");
    }
  }
  return std::make_unique<ElasticBodyBendingForce>(i1, i2, i3, alpha, theta0, edge1 + edge2);
}

}  // namespace fosssim
