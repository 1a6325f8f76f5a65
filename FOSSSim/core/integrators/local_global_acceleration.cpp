// The accelerated iterations of LocalGlobal (local_global.h): Anderson and Chebyshev.

#include <limits>

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
double LocalGlobal<D>::objective() const {
  const Vector u = free_positions();
  const auto U = map_points<D>(u);
  const Points<D> QU = q_matrix_ * U;
  return 0.5 * U.cwiseProduct(QU).sum() - U.cwiseProduct(rhs_).sum();
}

/// Peng et al. 2018: the local/global map G (a local step, then the global solve) is a
/// fixed-point iteration; Anderson acceleration extrapolates from its recent images, and an
/// iterate is kept only when its local/global energy (evaluated with its local step, which
/// the next global step needs anyway) is below the last accepted one. Otherwise the plain image
/// of the last accepted iterate, whose energy is never higher, replaces it and the history
/// restarts: the energy decreases monotonically, as with plain local/global. The last
/// iteration is not extrapolated, so the result is an image of G.
template <int D>
void LocalGlobal<D>::iterate_anderson() {
  if (anderson_.window() != settings_.window) anderson_ = AndersonAcceleration(settings_.window);
  anderson_.reset();
  Vector fallback;
  double accepted = std::numeric_limits<double>::infinity();
  for (int iteration = 1; iteration <= settings_.iterations; ++iteration) {
    rhs_ = constant_rhs_;
    add_spring_directions(rhs_);
    double energy = objective();
    if (iteration > 1 && !(energy < accepted)) {
      set_free_positions(fallback);
      anderson_.reset();
      rhs_ = constant_rhs_;
      add_spring_directions(rhs_);
      energy = objective();
    }
    accepted = energy;
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
    const Vector current = free_positions();
    rhs_ = constant_rhs_;
    add_spring_directions(rhs_);
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
  template double LocalGlobal<D>::objective() const;               \
  template void LocalGlobal<D>::iterate_anderson();                \
  template void LocalGlobal<D>::iterate_chebyshev();
FOSSSIM_LOCAL_GLOBAL_ACCELERATION(2)
FOSSSIM_LOCAL_GLOBAL_ACCELERATION(3)
#undef FOSSSIM_LOCAL_GLOBAL_ACCELERATION

}  // namespace fosssim
