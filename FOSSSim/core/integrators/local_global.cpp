#include "core/integrators/local_global.h"

#include <algorithm>
#include <cmath>

#include "core/step_error.h"

namespace fosssim {

template <int D>
void LocalGlobal<D>::advance(const SceneModel& model, State& state) {
  const double h = model.integrator.dt;
  if (!prepared_) {
    const std::vector<SpringTerm> springs = classify_forces(model);
    choose_free_particles(model, state, springs);
    prepared_ = true;
  }
  std::vector<std::pair<int, double>> signature = collect_anchors(model, state, h);
  if (h != h_ || signature != factored_anchors_) {
    h_ = h;
    factored_anchors_ = std::move(signature);
    factor(model, state.step + 1);
  }
  auto q = map_points<D>(state.q);
  auto v = map_points<D>(state.v);
  p_ = q + h * v;  // y = pⁿ + h vⁿ: the start, and where fixed particles go
  assemble_constant_rhs(model, state);
  last_iterations_ = 0;
  for (int iteration = 1; iteration <= settings_.iterations; ++iteration) {
    rhs_ = constant_rhs_;
    add_spring_directions(rhs_);
    last_change_ = global_solve(rhs_);
    last_iterations_ = iteration;
    if (settings_.tolerance > 0.0 && last_change_ <= settings_.tolerance) break;
  }
  for (int p : free_) {
    v.row(p) = (p_.row(p) - q.row(p)) / h;
    q.row(p) = p_.row(p);
  }
  for (int p = 0; p < model.num_particles(); ++p) {
    if (free_index_[p] < 0) q.row(p) = p_.row(p);  // eliminated: moves with its own velocity
  }
}

template <int D>
std::vector<SpringTerm> LocalGlobal<D>::classify_forces(const SceneModel& model) {
  std::vector<SpringTerm> springs;
  std::vector<AnchorTerm> ignored;
  for (const auto& force : model.forces) {
    if (force->append_springs(springs)) continue;
    if (force->append_anchors(ignored)) {
      anchor_forces_.push_back(force.get());
    } else {
      explicit_forces_.push_back(force.get());
    }
  }
  return springs;
}

template <int D>
void LocalGlobal<D>::choose_free_particles(const SceneModel& model, const State& state,
                                           const std::vector<SpringTerm>& springs) {
  const int n = model.num_particles();
  const bool eliminate = settings_.pins == PinMethod::kElimination;
  free_index_.assign(n, -1);
  for (int p = 0; p < n; ++p) {
    if (eliminate && model.fixed[p]) continue;
    free_index_[p] = static_cast<int>(free_.size());
    free_.push_back(p);
    if (model.fixed[p]) pinned_.push_back(p);
  }
  const auto q = map_points<D>(state.q);
  const auto v = map_points<D>(state.v);
  pin_position_.resize(static_cast<Eigen::Index>(pinned_.size()), D);
  pin_velocity_.resize(static_cast<Eigen::Index>(pinned_.size()), D);
  for (std::size_t k = 0; k < pinned_.size(); ++k) {
    pin_position_.row(k) = q.row(pinned_[k]);
    pin_velocity_.row(k) = v.row(pinned_[k]);
  }
  pin_step_ = state.step;
  for (const SpringTerm& s : springs) {
    const int fi = free_index_[s.i];
    const int fj = free_index_[s.j];
    if (fi < 0 && fj < 0) continue;  // both ends eliminated: no effect on the unknowns
    springs_.push_back({s.i, s.j, fi, fj, s.k, s.l0, s.b});
  }
  d_ = Points<D>::Zero(static_cast<Eigen::Index>(springs_.size()), D);
}

template <int D>
std::vector<std::pair<int, double>> LocalGlobal<D>::collect_anchors(const SceneModel& model,
                                                                    const State& state, double h) {
  anchors_.clear();
  for (const Force* force : anchor_forces_) force->append_anchors(anchors_);
  std::erase_if(anchors_, [&](const AnchorTerm& a) { return model.fixed[a.i]; });
  const double elapsed = static_cast<double>(state.step + 1 - pin_step_) * h;
  for (std::size_t k = 0; k < pinned_.size(); ++k) {
    AnchorTerm pin{pinned_[k], settings_.penalty_weight, Eigen::Vector3d::Zero()};
    pin.target.head<D>() = (pin_position_.row(k) + elapsed * pin_velocity_.row(k)).transpose();
    anchors_.push_back(pin);
  }
  std::vector<std::pair<int, double>> signature;
  for (const AnchorTerm& a : anchors_) signature.emplace_back(a.i, a.k);
  return signature;
}

template <int D>
void LocalGlobal<D>::factor(const SceneModel& model, std::int64_t step) {
  const int n = static_cast<int>(free_.size());
  if (n == 0) return;
  const double h2 = h_ * h_;
  std::vector<Triplet> triplets;
  triplets.reserve(n + 4 * springs_.size() + anchors_.size());
  for (int f = 0; f < n; ++f) triplets.emplace_back(f, f, model.mass[D * free_[f]] / h2);
  for (const Spring& s : springs_) {
    const double w = s.k + s.b / h_;
    if (s.fi >= 0) triplets.emplace_back(s.fi, s.fi, w);
    if (s.fj >= 0) triplets.emplace_back(s.fj, s.fj, w);
    if (s.fi >= 0 && s.fj >= 0) {
      triplets.emplace_back(s.fi, s.fj, -w);
      triplets.emplace_back(s.fj, s.fi, -w);
    }
  }
  for (const AnchorTerm& a : anchors_)
    triplets.emplace_back(free_index_[a.i], free_index_[a.i], a.k);
  SparseMatrix Q(n, n);
  Q.setFromTriplets(triplets.begin(), triplets.end());
  bool ok = false;
  if (factorizations_ > 0) {
    ok = solver_.refactor(Q);
  } else {
    const bool dense =
        settings_.solver == LinearSolverChoice::kDense ||
        (settings_.solver == LinearSolverChoice::kAuto && n <= LocalGlobalSettings::kDenseLimit);
    ok = solver_.factor(Q, dense ? SpdSolver::Method::kDense : SpdSolver::Method::kSparse);
  }
  if (!ok) {
    throw StepError(step,
                    "local/global: the system matrix M/h² + AᵀKA is not positive definite "
                    "(a negative stiffness or mass?)");
  }
  ++factorizations_;
}

template <int D>
void LocalGlobal<D>::assemble_constant_rhs(const SceneModel& model, const State& state) {
  const double h = h_;
  const auto q = map_points<D>(state.q);
  explicit_gradient_.setZero(state.q.size());
  const ForceInput in{state.q, state.v, model.mass};
  for (const Force* force : explicit_forces_) force->add_gradient(in, explicit_gradient_);
  const auto gradient = map_points<D>(static_cast<const Vector&>(explicit_gradient_));
  const int n = static_cast<int>(free_.size());
  constant_rhs_.resize(n, D);
  for (int f = 0; f < n; ++f) {
    const int p = free_[f];
    constant_rhs_.row(f) = (model.mass[D * p] / (h * h)) * p_.row(p);
    if (!model.fixed[p]) constant_rhs_.row(f) -= gradient.row(p);
  }
  for (const Spring& s : springs_) {
    if (s.b != 0.0) {  // Laplacian damping: (b/h) a aᵀ pⁿ
      const Vec<D> lagged = (s.b / h) * (q.row(s.i) - q.row(s.j)).transpose();
      if (s.fi >= 0) constant_rhs_.row(s.fi) += lagged.transpose();
      if (s.fj >= 0) constant_rhs_.row(s.fj) -= lagged.transpose();
    }
    const double w = s.k + s.b / h;  // an eliminated end's known position moves to the right
    if (s.fj < 0) constant_rhs_.row(s.fi) += w * p_.row(s.j);
    if (s.fi < 0) constant_rhs_.row(s.fj) += w * p_.row(s.i);
  }
  for (const AnchorTerm& a : anchors_) {
    constant_rhs_.row(free_index_[a.i]) += a.k * a.target.head<D>().transpose();
  }
}

template <int D>
void LocalGlobal<D>::add_spring_directions(Points<D>& rhs) {
  for (std::size_t s = 0; s < springs_.size(); ++s) {
    const Spring& spring = springs_[s];
    const Vec<D> delta = (p_.row(spring.i) - p_.row(spring.j)).transpose();
    const double length = delta.norm();
    // Local step: the rest-length vector nearest the current one (kept when the length is 0).
    if (length > 0.0) d_.row(s) = (spring.l0 / length) * delta.transpose();
    if (spring.fi >= 0) rhs.row(spring.fi) += spring.k * d_.row(s);
    if (spring.fj >= 0) rhs.row(spring.fj) -= spring.k * d_.row(s);
  }
}

template <int D>
double LocalGlobal<D>::global_solve(Points<D>& rhs) {
  if (free_.empty()) return 0.0;
  solver_.solve_in_place<D>(rhs);
  double change = 0.0;
  for (std::size_t f = 0; f < free_.size(); ++f) {
    const int p = free_[f];
    change = std::max(change, (rhs.row(f) - p_.row(p)).cwiseAbs().maxCoeff());
    p_.row(p) = rhs.row(f);
  }
  return change;
}

template class LocalGlobal<2>;
template class LocalGlobal<3>;

}  // namespace fosssim
