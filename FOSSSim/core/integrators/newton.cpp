#include "core/integrators/newton.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string_view>

#include "core/integrators/solver_option.h"
#include "core/step_error.h"
#include "core/text.h"

namespace fosssim {

void Newton::prepare() {
  matrix_.emplace(forces(), FixedParticleRule::kElimination);
  solver_.emplace(forces().has_symmetric_jacobians(), options_.solver, model().dim);
}

Vector Newton::solve(const SparseMatrix& A, const Vector& rhs, int step) {
  const auto delta = solver_->solve(A, matrix_->restrict(rhs));
  if (!delta) throw StepError(step, "newton: the step matrix is singular");
  Vector full = Vector::Zero(rhs.size());
  matrix_->add_solution(*delta, full);
  return full;
}

namespace {

/// The blend weight θ of A_θ = (1 - θ) A + θ Ā over one step (NewtonHessian::kAdaptive): one
/// of 1, 1/3, ..., 1/81 and 0.
class Blend {
 public:
  explicit Blend(NewtonHessian choice)
      : choice_(choice), level_(choice == NewtonHessian::kExact ? kExact : 0) {}

  double theta() const { return level_ == kExact ? 0.0 : std::pow(kFactor, -level_); }
  /// The exact matrix's direction climbed: the next try leans towards Ā (θ = 1 for kExact).
  void climbed() {
    if (choice_ == NewtonHessian::kExact) {
      level_ = 0;
    } else {
      raise();
    }
  }
  /// The line search took `fraction` of the direction.
  void stepped(double fraction) {
    if (choice_ == NewtonHessian::kExact) {
      level_ = kExact;
    } else if (choice_ == NewtonHessian::kAdaptive) {
      if (fraction >= 0.5) {
        level_ = std::min(level_ + 1, kExact);
      } else {
        raise();
      }
    }
  }

 private:
  static constexpr double kFactor = 3.0;
  static constexpr int kExact = 5;  // the level of θ = 0; 3⁻⁴ ≈ 0.012 is the smallest θ > 0
  void raise() { level_ = level_ == kExact ? 2 : std::max(level_ - 1, 0); }

  NewtonHessian choice_;
  int level_;  // θ = 3^-level, or 0 at kExact
};

}  // namespace

const SparseMatrix& Newton::blend_matrices(const SparseMatrix& exact, const SparseMatrix& projected,
                                           double theta) {
  const auto same_pattern = [](const SparseMatrix& a, const SparseMatrix& b) {
    return a.rows() == b.rows() && a.cols() == b.cols() && a.nonZeros() == b.nonZeros() &&
           std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.outerSize() + 1,
                      b.outerIndexPtr()) &&
           std::equal(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros(), b.innerIndexPtr());
  };
  if (!same_pattern(exact, projected)) {  // StepMatrix built one of them from triplets
    blended_ = (1.0 - theta) * exact + theta * projected;
    return blended_;
  }
  if (!same_pattern(blended_, exact)) blended_ = exact;  // the pattern, once
  const auto values = [](const SparseMatrix& m) {
    return Eigen::Map<const Vector>(m.valuePtr(), m.nonZeros());
  };
  Eigen::Map<Vector>(blended_.valuePtr(), blended_.nonZeros()) =
      (1.0 - theta) * values(exact) + theta * values(projected);
  return blended_;
}

Vector Newton::minimize(const BackwardEulerStep& problem) {
  const State& state = problem.start;
  const double h = problem.h;
  Blend blend(options_.hessian);
  Vector dv = Vector::Zero(state.v.size());
  Vector rhs = problem.residual(dv);
  double potential = std::numeric_limits<double>::quiet_NaN();  // Φ(dv), once known
  for (int iteration = 1; iteration <= options_.max_iterations; ++iteration) {
    cancellation().check();
    const Vector v = state.v + dv;
    const Vector q = state.q + h * v;
    const SparseMatrix* exact = nullptr;  // A and Ā at dv, assembled when first needed
    const SparseMatrix* projected = nullptr;
    const auto direction = [&](double theta) {
      if (theta < 1.0 && exact == nullptr) exact = &matrix_->assemble(q, v, h);
      if (theta > 0.0 && projected == nullptr) projected = &matrix_->assemble_definite(q, v, h);
      if (theta == 0.0) return solve(*exact, rhs, state.step + 1);
      if (theta == 1.0) return solve(*projected, rhs, state.step + 1);
      return solve(blend_matrices(*exact, *projected, theta), rhs, state.step + 1);
    };
    Vector delta = direction(blend.theta());
    // -rhs is the gradient of Φ: Δ must descend on it, which Ā's direction always does.
    while (rhs.dot(delta) <= 0.0 && rhs.squaredNorm() > 0.0 && blend.theta() < 1.0) {
      blend.climbed();
      delta = direction(blend.theta());
    }
    double fraction = 0.0;
    const Vector step = potential_line_search(problem, dv, rhs, delta, &potential, &fraction);
    blend.stepped(fraction);
    dv += step;
    rhs = problem.residual(dv);
    last_iterations_ = iteration;
    if (converged(state, dv, step)) return dv;
  }
  fail(state);
}

Vector Newton::find_root(const BackwardEulerStep& problem) {
  const State& state = problem.start;
  const double h = problem.h;
  Vector dv = Vector::Zero(state.v.size());
  Vector rhs = problem.residual(dv);
  for (int iteration = 1; iteration <= options_.max_iterations; ++iteration) {
    cancellation().check();
    const Vector v = state.v + dv;
    const Vector delta = solve(matrix_->assemble(state.q + h * v, v, h), rhs, state.step + 1);
    const Vector step = residual_line_search(problem, dv, rhs, delta);  // updates rhs
    dv += step;
    last_iterations_ = iteration;
    if (converged(state, dv, step)) return dv;
  }
  fail(state);
}

bool Newton::converged(const State& state, const Vector& dv, const Vector& step) {
  last_correction_ = step.lpNorm<Eigen::Infinity>();
  const double scale = std::max((state.v + dv).lpNorm<Eigen::Infinity>(), 1e-3);
  return last_correction_ <= options_.tolerance * scale;
}

void Newton::fail(const State& state) const {
  throw StepError(state.step + 1, "newton: no convergence in " +
                                      std::to_string(options_.max_iterations) +
                                      " iterations (last correction " + to_text(last_correction_) +
                                      " m/s); try a smaller time step or a larger max-iterations");
}

void Newton::advance(State& state) {
  const double h = model().integrator.dt;
  const BackwardEulerStep problem{forces(), state, h};
  const Vector dv = forces().is_conservative() ? minimize(problem) : find_root(problem);
  state.q += h * (state.v + dv);
  state.v += dv;
}

namespace {
constexpr NewtonOptions kNewtonDefaults;
constexpr std::array<std::string_view, 3> kHessianChoices = {"adaptive", "projected", "exact"};
constexpr std::array kNewtonOptionSpecs = {
    OptionSpec::number("tolerance", kNewtonDefaults.tolerance, 0.0, /*excluded=*/true,
                       "stop once a correction is this small relative to the velocities"),
    OptionSpec::integer("max-iterations", kNewtonDefaults.max_iterations, 1, 1000000,
                        "a step that has not converged after this many iterations fails"),
    kSolverOption,
    OptionSpec::choice(
        "hessian", kHessianChoices,
        "step matrix of the iterations when every force has a potential: a blend of the exact "
        "matrix and the projected one (each element's Hessian made semi-definite), projected at "
        "first and exact once the line search takes full steps, for robust and quadratic "
        "convergence on crumpling cloth (adaptive); always the projected one, linear "
        "convergence (projected); or the exact one, projected only where it climbs (exact)"),
};

NewtonHessian hessian_choice(const OptionValues& options) {
  const std::string_view choice = options.choice("hessian");
  return choice == "projected" ? NewtonHessian::kProjected
         : choice == "exact"   ? NewtonHessian::kExact
                               : NewtonHessian::kAdaptive;
}
}  // namespace

constinit const IntegratorMethod kNewtonMethod{
    .name = "newton",
    .aliases = {},
    .summary =
        "implicit Euler solved to round-off by Newton's method with line searches, "
        "fixed particles eliminated (the reference for meshes)",
    .options = kNewtonOptionSpecs,
    .properties = {.order = 1, .implicit = true, .energy = EnergyTrend::kDecays},
    .create = [](const OptionValues& options, int) -> std::unique_ptr<Integrator> {
      return std::make_unique<Newton>(
          NewtonOptions{options.number("tolerance"), options.integer("max-iterations"),
                        solver_choice(options), hessian_choice(options)});
    },
};

}  // namespace fosssim
