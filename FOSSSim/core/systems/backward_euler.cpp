#include "core/systems/backward_euler.h"

#include <cmath>

#include "core/force_evaluation.h"

namespace fosssim {

namespace {
/// Armijo constant of the line searches: accept a step αΔ when the merit falls by at least
/// cα times its slope.
constexpr double kArmijo = 1e-4;
/// Give up halving the step below this fraction of the first trial.
constexpr double kSmallestStep = 1e-10;
}  // namespace

Vector BackwardEulerStep::residual(const Vector& dv) const {
  const Vector v = start.v + dv;
  const Vector q = start.q + h * v;
  Vector rhs = h * compute_force(forces, q, v) - forces.mass().cwiseProduct(dv);
  zero_fixed(forces.model(), rhs);
  return rhs;
}

double BackwardEulerStep::incremental_potential(const Vector& dv) const {
  const Vector v = start.v + dv;
  return 0.5 * dv.dot(forces.mass().cwiseProduct(dv)) +
         compute_potential_energy(forces, start.q + h * v, v);
}

Vector potential_line_search(const BackwardEulerStep& problem, const Vector& dv, const Vector& rhs,
                             const Vector& direction, double* potential, double* fraction) {
  // -rhs is the gradient of Φ.
  Vector step = direction;
  double slope = -rhs.dot(step);
  if (!(slope < 0.0)) {
    step = rhs.cwiseQuotient(problem.forces.mass());
    slope = -rhs.dot(step);
  }
  const double start = potential != nullptr && !std::isnan(*potential)
                           ? *potential
                           : problem.incremental_potential(dv);
  // Φ is a difference of large energies near convergence; allow for its round-off.
  const double noise = 1e-13 * (std::abs(start) + 1.0);
  double alpha = 1.0;
  double trial = problem.incremental_potential(dv + alpha * step);
  while (trial > start + kArmijo * alpha * slope + noise && alpha > kSmallestStep) {
    alpha *= 0.5;
    trial = problem.incremental_potential(dv + alpha * step);
  }
  if (potential != nullptr) *potential = trial;
  if (fraction != nullptr) *fraction = alpha;
  return alpha * step;
}

Vector residual_line_search(const BackwardEulerStep& problem, const Vector& dv, Vector& rhs,
                            const Vector& newton_step) {
  // The slope of ½‖r‖² along the Newton step is -‖r‖².
  const double merit = rhs.squaredNorm();
  double alpha = 1.0;
  Vector trial = problem.residual(dv + newton_step);
  while (trial.squaredNorm() > (1.0 - 2.0 * kArmijo * alpha) * merit && alpha > kSmallestStep) {
    alpha *= 0.5;
    trial = problem.residual(dv + alpha * newton_step);
  }
  rhs = std::move(trial);
  return alpha * newton_step;
}

}  // namespace fosssim
