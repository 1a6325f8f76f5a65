#include "core/collisions/penalty_force.h"

#include <array>

#include "core/collisions/proximity.h"
#include "core/text.h"

namespace fosssim {

namespace {

/// One pair within reach of the penalty force: up to three particles with the weights w_k of
/// n = Σ w_k x_k, and for an edge whose closest point is inside it, what the change of α adds
/// to the Hessian.
template <int D>
struct Contact {
  int count = 0;
  std::array<int, 3> particle{};
  std::array<double, 3> weight{};
  Separation<D> separation;
  double distance = 0.0;  // d = ‖n‖ (signed for 3D half-spaces, Separation::distance)
  double delta = 0.0;     // δ = d - R - T < 0
  double particle_radius = 0.0;  // r_i, of pair.particle
  double other_radius = 0.0;     // the other particle's or the edge's; 0 for obstacles
  bool half_plane = false;
  bool interior_edge_point = false;
  Vec<D> edge = Vec<D>::Zero();  // x_b - x_a, for interior edge points
  Vec<D> plane_normal = Vec<D>::Zero();  // N as the scene gives it, for half-planes
};

/// Adds one contact's -F in 2D, in the course's order of operations (docs/collisions.md,
/// 'Course-exact arithmetic').
template <int D>
void add_course_gradient(const Contact<D>& c, double k, double thickness, Vector& gradient) {
  // n̂ = n × (1/l), δ = ((l - r_i) - r_other) - T with the radii subtracted one by one.
  const double l = c.distance;
  const Vec<D> nhat = c.separation.n * (1.0 / l);
  const double delta = ((l - c.particle_radius) - c.other_radius) - thickness;
  const auto add_to = [&gradient](int p, const Vec<D>& value) {
    for (int i = 0; i < D; ++i) gradient[D * p + i] = value[i] + gradient[D * p + i];
  };
  if (c.half_plane) {
    // The force re-projected onto the scene's N: -N ((n̂·N) s ÷ (N·N)), s = ((l - r_i) - T) k.
    const Vec<D>& N = c.plane_normal;
    const double s = ((l - c.particle_radius) - thickness) * k;
    const double scale = (nhat.dot(N) * s) / N.dot(N);
    add_to(c.particle[0], -(N * scale));
    return;
  }
  const double s = delta * k;
  add_to(c.particle[0], -(nhat * s));
  if (c.count == 2) {
    add_to(c.particle[1], nhat * s);
  } else if (c.count == 3) {
    const double alpha = c.weight[2];
    add_to(c.particle[1], nhat * (((1.0 - alpha) * k) * delta));
    add_to(c.particle[2], nhat * ((alpha * k) * delta));
  }
}

}  // namespace

template <int D>
PenaltyForce<D>::PenaltyForce(const SceneModel& model, double stiffness, double thickness,
                              PenaltyJacobian jacobian)
    : model_(&model),
      k_(stiffness),
      thickness_(thickness),
      jacobian_(jacobian),
      pairs_(make_candidate_pairs(model)) {}

template <int D>
template <typename Visit>
void PenaltyForce<D>::for_each_contact(const Vector& q, PenaltyPairs which, Visit&& visit) const {
  const SceneModel& model = *model_;
  const PairQuery query{q, q, thickness_};
  pairs_->for_each(query, [&](const CandidatePair& pair) {
    if (which != PenaltyPairs::kAll &&
        is_obstacle(pair.kind) != (which == PenaltyPairs::kObstacles)) {
      return;
    }
    Contact<D> c;
    c.separation = separation<D>(model, pair, q);
    c.distance = c.separation.distance;
    if (!(c.distance < c.separation.radii + thickness_)) return;
    if constexpr (D == 3) {
      if (c.separation.n.isZero(0.0)) return;  // no direction to push along
    }
    c.delta = c.distance - c.separation.radii - thickness_;
    c.particle_radius = model.particle_radius[pair.particle];
    const double alpha = c.separation.alpha;
    switch (pair.kind) {
      case CollisionKind::kParticleParticle:
        c.count = 2;
        c.particle = {pair.particle, pair.other, 0};
        c.weight = {-1.0, 1.0, 0.0};
        c.other_radius = model.particle_radius[pair.other];
        break;
      case CollisionKind::kParticleEdge: {
        const Edge& edge = model.edges[pair.other];
        c.count = 3;
        c.particle = {pair.particle, edge.i, edge.j};
        c.weight = {-1.0, 1.0 - alpha, alpha};
        c.interior_edge_point = alpha > 0.0 && alpha < 1.0;
        c.edge = particle_vec<D>(q, edge.j) - particle_vec<D>(q, edge.i);
        c.other_radius = model.edge_radius[pair.other];
        break;
      }
      case CollisionKind::kParticleHalfPlane:
      case CollisionKind::kParticleSphere:
        c.count = 1;
        c.particle = {pair.particle, 0, 0};
        c.weight = {-1.0, 0.0, 0.0};
        c.half_plane = pair.kind == CollisionKind::kParticleHalfPlane;
        if (c.half_plane) c.plane_normal = model.half_planes[pair.other].normal.template head<D>();
        break;
    }
    visit(c);
  });
}

template <int D>
void PenaltyForce<D>::add_energy(const ForceInput& in, double& energy) const {
  for_each_contact(in.q, PenaltyPairs::kAll,
                   [&](const Contact<D>& c) { energy += 0.5 * k_ * c.delta * c.delta; });
}

template <int D>
void PenaltyForce<D>::add_gradient(const ForceInput& in, Vector& gradient) const {
  add_gradient(in, gradient, PenaltyPairs::kAll);
}

template <int D>
void PenaltyForce<D>::add_gradient(const ForceInput& in, Vector& gradient,
                                   PenaltyPairs which) const {
  for_each_contact(in.q, which, [&](const Contact<D>& c) {
    if constexpr (D == 2) {
      add_course_gradient<D>(c, k_, thickness_, gradient);
      return;
    }
    const Vec<D> nhat = c.separation.n / c.separation.n.norm();
    // The particle's force is k δ n̂ and the other object's -k δ n̂ shared by the weights;
    // gradE = -F.
    const Vec<D> force = k_ * c.delta * nhat;
    gradient.segment<D>(D * c.particle[0]) -= force;
    if (c.count >= 2) gradient.segment<D>(D * c.particle[1]) += c.weight[1] * force;
    if (c.count == 3) gradient.segment<D>(D * c.particle[2]) += c.weight[2] * force;
  });
}

template <int D>
void PenaltyForce<D>::add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const {
  if (jacobian_ == PenaltyJacobian::kNone) return;
  for_each_contact(in.q, PenaltyPairs::kAll, [&](const Contact<D>& c) {
    const Vec<D> nhat = c.separation.n / c.separation.n.norm();
    const Mat<D> nn = nhat * nhat.transpose();
    if (c.half_plane) {  // d is linear in x: ∇²d = 0
      hessian.add_block<D>(c.particle[0], c.particle[0], k_ * nn);
      return;
    }
    // With f = ½‖n‖², n = Σ w_k x_k: ∇_k d = w_k n̂ and ∇²d = (∇²f - ∇f ∇fᵀ/d²)/d, where
    // ∇²_kl f = w_k w_l I - g_k g_lᵀ/(e·e) when α minimises over the edge's interior
    // (g_k = ∂²f/∂x_k∂α = w'_k n + w_k e, w' = (0, -1, 1), e = x_b - x_a), else w_k w_l I.
    const double ratio = c.delta / c.distance;
    std::array<Vec<D>, 3> g;
    if (c.interior_edge_point) {
      const std::array<double, 3> slope = {0.0, -1.0, 1.0};
      for (int a = 0; a < 3; ++a) g[a] = slope[a] * c.separation.n + c.weight[a] * c.edge;
    }
    const double ee = c.edge.squaredNorm();
    for (int a = 0; a < c.count; ++a) {
      for (int b = 0; b < c.count; ++b) {
        const double ww = c.weight[a] * c.weight[b];
        Mat<D> block = ww * nn;
        if (!in.definite_hessian) {
          Mat<D> curvature = ww * (Mat<D>::Identity() - nn);
          if (c.interior_edge_point) curvature -= g[a] * g[b].transpose() / ee;
          block += ratio * curvature;
        }
        hessian.add_block<D>(c.particle[a], c.particle[b], k_ * block);
      }
    }
  });
}

template <int D>
std::string PenaltyForce<D>::label() const {
  return "penalty(k " + to_text(k_) + ", thickness " + to_text(thickness_) + ")";
}

std::unique_ptr<Force> make_penalty_force(const SceneModel& model) {
  const CollisionSettings& s = model.collisions;
  if (model.dim == 3) {
    return std::make_unique<PenaltyForce<3>>(model, s.stiffness, s.thickness, s.penalty_jacobian);
  }
  return std::make_unique<PenaltyForce<2>>(model, s.stiffness, s.thickness, s.penalty_jacobian);
}

template class PenaltyForce<2>;
template class PenaltyForce<3>;

namespace {
namespace options = particle_contact_options;
constexpr std::array kPenaltyOptionSpecs = {
    options::restitution("accepted and unused (the course reads it for every type)"),
    options::stiffness(100.0),
    options::thickness(0.01),
    options::penalty_jacobian(),
};
}  // namespace

constinit const ContactMethod kPenaltyContactMethod{
    .name = "penalty",
    .summary = "a spring force between objects closer than their radii plus a thickness",
    .options = kPenaltyOptionSpecs,
    .scope = kParticlesIn2DAnd3D,
    .records = StepRecordLayout::kFrames,
    .make_force = make_penalty_force,
};

}  // namespace fosssim
