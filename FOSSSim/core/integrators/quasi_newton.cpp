#include "core/integrators/quasi_newton.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string_view>

#include "core/error.h"

namespace fosssim {

namespace {

/// x ← Q⁻¹ x / scale, with x the free DOFs as rows of D coordinates.
template <int D>
void solve_columns(const SpdSolver& solver, Vector& x, double scale) {
  Points<D> columns = map_points<D>(x);
  solver.solve_in_place<D>(columns);
  map_points<D>(x) = columns / scale;
}

}  // namespace

void QuasiNewton::prepare() {
  split_ = sort_mass_spring_forces(forces());
  free_ = FreeDofs(model().fixed, model().dim);
  update_anchors();
  factor();
}

void QuasiNewton::update_anchors() {
  anchors_.clear();
  for (const Force* force : split_.anchors) {
    const std::optional<AnchorTerm> anchor = force->local_global_anchor();
    if (anchor && !model().fixed[anchor->i]) anchors_.push_back(*anchor);
  }
}

void QuasiNewton::factor() {
  factored_anchors_.clear();
  for (const AnchorTerm& a : anchors_) factored_anchors_.emplace_back(a.i, a.k);
  const int n = free_.num_particles();
  if (n == 0) return;
  const SparseMatrix Q = assemble_local_global_matrix(model().mass, free_, split_.springs, anchors_,
                                                      model().integrator.dt);
  const bool ok = factorizations_ > 0 ? solver_.refactor(Q)
                                      : solver_.factor(Q, n <= 64 ? SpdSolver::Method::kDense
                                                                  : SpdSolver::Method::kSparse);
  if (!ok) {
    throw Error(ErrorKind::kStepFailed,
                "quasi-Newton: the matrix M/h² + AᵀKA is not positive definite "
                "(a negative stiffness or mass?)");
  }
  ++factorizations_;
}

void QuasiNewton::apply_initial_inverse(Vector& x) const {
  const double h = model().integrator.dt;
  if (model().dim == 3) {
    solve_columns<3>(solver_, x, h * h);
  } else {
    solve_columns<2>(solver_, x, h * h);
  }
}

Vector QuasiNewton::lbfgs_direction(const Vector& r) {
  Vector z = r;
  std::vector<double> alphas(pairs_.size());
  for (std::size_t k = pairs_.size(); k-- > 0;) {
    const auto& [s, y] = pairs_[k];
    alphas[k] = s.dot(z) / y.dot(s);
    z -= alphas[k] * y;
  }
  apply_initial_inverse(z);
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    const auto& [s, y] = pairs_[k];
    const double beta = y.dot(z) / y.dot(s);
    z += (alphas[k] - beta) * s;
  }
  return z;
}

void QuasiNewton::advance(State& state) {
  const double h = model().integrator.dt;
  update_anchors();
  std::vector<std::pair<int, double>> signature;
  for (const AnchorTerm& a : anchors_) signature.emplace_back(a.i, a.k);
  if (signature != factored_anchors_) factor();

  const BackwardEulerStep problem{forces(), state, h};
  const bool minimize = forces().is_conservative();
  pairs_.clear();
  Vector dv = Vector::Zero(state.v.size());
  Vector rhs = problem.residual(dv);
  double potential = std::numeric_limits<double>::quiet_NaN();
  last_iterations_ = 0;
  if (free_.num_particles() > 0) {
    for (int iteration = 1; iteration <= options_.iterations; ++iteration) {
      cancellation().check();
      const Vector r = free_.restrict(rhs);
      Vector direction = Vector::Zero(dv.size());
      free_.add_expanded(lbfgs_direction(r), direction);
      const Vector step =
          minimize ? potential_line_search(problem, dv, rhs, direction, &potential) : direction;
      dv += step;
      Vector next = problem.residual(dv);
      Vector s = free_.restrict(step);
      Vector y = r - free_.restrict(next);  // the change of the gradient -r
      const double curvature = s.dot(y);
      if (curvature > 1e-12 * s.norm() * y.norm()) {
        pairs_.emplace_back(std::move(s), std::move(y));
        if (static_cast<int>(pairs_.size()) > options_.history) pairs_.pop_front();
      }
      rhs = std::move(next);
      last_iterations_ = iteration;
      const double scale = std::max((state.v + dv).lpNorm<Eigen::Infinity>(), 1e-3);
      if (step.lpNorm<Eigen::Infinity>() <= options_.tolerance * scale) break;
    }
  }
  state.q += h * (state.v + dv);
  state.v += dv;
}

namespace {
constexpr std::array<std::string_view, 1> kQuasiNewtonAliases = {"lbfgs"};
constexpr QuasiNewtonOptions kQuasiNewtonDefaults;
constexpr std::array kQuasiNewtonOptionSpecs = {
    OptionSpec::integer("iterations", kQuasiNewtonDefaults.iterations, 1, 1000000,
                        "L-BFGS iterations per step, at most"),
    OptionSpec::number("tolerance", kQuasiNewtonDefaults.tolerance, 0.0, /*excluded=*/false,
                       "stop once a correction is this small relative to the velocities; 0: "
                       "always take all iterations"),
    OptionSpec::integer("history", kQuasiNewtonDefaults.history, 1, 1000,
                        "pairs of steps and gradient changes L-BFGS keeps"),
};
}  // namespace

constinit const IntegratorMethod kQuasiNewtonMethod{
    .name = "quasi-newton",
    .aliases = kQuasiNewtonAliases,
    .summary =
        "implicit Euler by L-BFGS with the local/global matrix as initial Hessian "
        "(Liu et al. 2017)",
    .options = kQuasiNewtonOptionSpecs,
    .properties = {.order = 1, .implicit = true, .energy = EnergyTrend::kDecays},
    .create = [](const OptionValues& options, int) -> std::unique_ptr<Integrator> {
      return std::make_unique<QuasiNewton>(QuasiNewtonOptions{
          options.integer("iterations"), options.number("tolerance"), options.integer("history")});
    },
};

}  // namespace fosssim
