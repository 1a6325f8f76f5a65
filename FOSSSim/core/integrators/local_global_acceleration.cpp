// The accelerated iterations of LocalGlobal (local_global.h): Anderson and Chebyshev.

#include <cmath>
#include <limits>

#include "core/collisions/proximity.h"
#include "core/integrators/local_global.h"

namespace fosssim {

template <int D>
Vector LocalGlobal<D>::free_positions() const {
  const int n = free_.num_particles();
  Vector u(D * n);
  for (int f = 0; f < n; ++f) {
    u.template segment<D>(D * f) = p_.row(free_.particles()[f]).transpose();
  }
  return u;
}

template <int D>
void LocalGlobal<D>::set_free_positions(const Vector& u) {
  for (int f = 0; f < free_.num_particles(); ++f) {
    p_.row(free_.particles()[f]) = u.template segment<D>(D * f).transpose();
  }
}

template <int D>
double LocalGlobal<D>::energy(double* round_off) const {
  const double h = model().integrator.dt;
  const auto gradient = map_points<D>(explicit_gradient_);
  double inertia = 0.0, potential = 0.0;
  for (int f = 0; f < free_.num_particles(); ++f) {
    const int p = free_.particles()[f];
    inertia += model().mass[D * p] * (p_.row(p) - y_.row(p)).squaredNorm();
    potential += gradient.row(p).dot(p_.row(p));
  }
  inertia /= 2.0 * h * h;
  const auto start = map_points<D>(start_q_);
  for (const Spring& s : springs_) {
    const Vec<D> delta = (p_.row(s.i) - p_.row(s.j)).transpose();
    const double stretch = delta.norm() - s.l0;
    potential += 0.5 * s.k * stretch * stretch;
    if (s.b != 0.0) {  // the Laplacian damping's ½ (b/h) |δ - δⁿ|²
      const Vec<D> start_delta = (start.row(s.i) - start.row(s.j)).transpose();
      potential += 0.5 * (s.b / h) * (delta - start_delta).squaredNorm();
    }
  }
  for (const AnchorTerm& a : anchors_) {
    potential += 0.5 * a.k * (p_.row(a.i) - a.target.template head<D>().transpose()).squaredNorm();
  }
  if (penalty_ != nullptr) {  // obstacle contacts: ½ k δ² within reach
    const double k = penalty_->stiffness();
    const auto position = [this](int p) -> Vec<D> { return p_.row(p).transpose(); };
    for (const ObstacleContact& c : contacts_) {
      const Separation<D> s = separation_of<D>(model(), c.pair, position);
      const double delta = s.distance - s.radii - penalty_->thickness();
      if (delta < 0.0) potential += 0.5 * k * delta * delta;
    }
  }
  *round_off = 1e-14 * (inertia + std::abs(potential));
  return inertia + potential;
}

/// Peng et al. 2018: the local/global map G (a local step, then the global solve) is a
/// fixed-point iteration; Anderson acceleration extrapolates from its recent images, and an
/// iterate is kept only when its energy (the incremental potential local/global minimises,
/// energy()) is below the last accepted one's. Otherwise the plain image
/// of the last accepted iterate, whose energy is never higher, replaces it and the history
/// restarts: the energy decreases monotonically, as with plain local/global, up to the
/// round-off of evaluating it (an increase within that is accepted: near convergence the
/// energies of successive iterates differ by less than their round-off). The last
/// iteration is not extrapolated, so the result is an image of G.
template <int D>
void LocalGlobal<D>::iterate_anderson() {
  if (anderson_.window() != settings_.window) anderson_ = AndersonAcceleration(settings_.window);
  anderson_.reset();
  Vector fallback;
  double accepted = std::numeric_limits<double>::infinity();
  for (int iteration = 1; iteration <= settings_.iterations; ++iteration) {
    cancellation().check();
    local_step(rhs_);
    double round_off = 0.0;
    double value = energy(&round_off);
    if (iteration > 1 && !(value < accepted + round_off)) {
      set_free_positions(fallback);
      anderson_.reset();
      local_step(rhs_);
      value = energy(&round_off);
    }
    accepted = value;
    const Vector u = free_positions();
    last_change_ = global_solve(rhs_);
    last_iterations_ = iteration;
    if (iteration == settings_.iterations ||
        (settings_.tolerance > 0.0 && last_change_ <= settings_.tolerance)) {
      break;
    }
    fallback = free_positions();
    set_free_positions(anderson_.next(u, fallback));
  }
}

/// Wang, "A Chebyshev Semi-Iterative Approach for Accelerating Projective and Position-based
/// Dynamics", ACM TOG 34(6), 2015: after S plain iterations, q ← ω (γ (q̂ - q) + q - q_prev) +
/// q_prev with ω from the spectral radius ρ of the plain iteration.
template <int D>
void LocalGlobal<D>::iterate_chebyshev() {
  constexpr int kPlainIterations = 10;      // S
  constexpr double kUnderRelaxation = 0.9;  // γ
  const double rho2 = settings_.rho * settings_.rho;
  Vector previous = free_positions();
  double omega = 1.0;
  for (int iteration = 1; iteration <= settings_.iterations; ++iteration) {
    cancellation().check();
    const Vector current = free_positions();
    local_step(rhs_);
    last_change_ = global_solve(rhs_);
    last_iterations_ = iteration;
    if (settings_.tolerance > 0.0 && last_change_ <= settings_.tolerance) break;
    if (iteration >= kPlainIterations) {
      omega = iteration == kPlainIterations ? 2.0 / (2.0 - rho2) : 4.0 / (4.0 - rho2 * omega);
      const Vector image = free_positions();
      set_free_positions(omega * (kUnderRelaxation * (image - current) + current - previous) +
                         previous);
    }
    previous = current;
  }
}

#define FOSSSIM_LOCAL_GLOBAL_ACCELERATION(D)                       \
  template Vector LocalGlobal<D>::free_positions() const;          \
  template void LocalGlobal<D>::set_free_positions(const Vector&); \
  template double LocalGlobal<D>::energy(double*) const;           \
  template void LocalGlobal<D>::iterate_anderson();                \
  template void LocalGlobal<D>::iterate_chebyshev();
FOSSSIM_LOCAL_GLOBAL_ACCELERATION(2)
FOSSSIM_LOCAL_GLOBAL_ACCELERATION(3)
#undef FOSSSIM_LOCAL_GLOBAL_ACCELERATION

}  // namespace fosssim
