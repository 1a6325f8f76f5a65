#include "core/integrators/local_global.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "core/collisions/proximity.h"
#include "core/error.h"

namespace fosssim {

template <int D>
void LocalGlobal<D>::prepare() {
  const SceneModel& model = this->model();
  split_ = sort_mass_spring_forces(forces());
  check_local_global_roles(split_, "local-global");
  if (split_.contact != nullptr) {
    // kContact is the penalty force's role; it gives the obstacle pairs and their stiffness.
    penalty_ = dynamic_cast<const PenaltyForce<D>*>(split_.contact);
    if (penalty_ == nullptr) {
      throw Error(ErrorKind::kBadInput, "local-global: " + split_.contact->label() +
                                            " declares itself a contact force but is not the " +
                                            std::to_string(D) + "D penalty force");
    }
  }
  const bool eliminate = settings_.pins == PinMethod::kElimination;
  free_ = FreeDofs(eliminate ? model.fixed : std::vector<bool>(model.fixed.size(), false), D);
  if (!eliminate) {
    for (int p = 0; p < model.num_particles(); ++p) {
      if (model.fixed[p]) pinned_.push_back(p);
    }
  }
  for (const SpringTerm& s : split_.springs) {
    const int fi = free_.of_particle(s.i);
    const int fj = free_.of_particle(s.j);
    if (fi < 0 && fj < 0) continue;  // both ends eliminated: no effect on the unknowns
    springs_.push_back({s.i, s.j, fi, fj, s.k, s.l0, s.b});
  }
  kd_ = Points<D>::Zero(static_cast<Eigen::Index>(springs_.size()), D);
  list_incidences();
  // Q for the anchors there are now (the pins; the drag spring, if already grabbed). The pins'
  // targets only enter the right side, so they can wait for the first step.
  anchors_.clear();
  for (const Force* force : split_.anchors) {
    const std::optional<AnchorTerm> anchor = force->local_global_anchor();
    if (anchor && !model.fixed[anchor->i]) anchors_.push_back(*anchor);
  }
  for (int p : pinned_) anchors_.push_back({p, settings_.penalty_weight, Eigen::Vector3d::Zero()});
  for (const AnchorTerm& a : anchors_) factored_anchors_.emplace_back(a.i, a.k);
  factor();
}

template <int D>
void LocalGlobal<D>::list_incidences() {
  const int n = free_.num_particles();
  incidence_start_.assign(n + 1, 0);
  for (const Spring& s : springs_) {
    if (s.fi >= 0) ++incidence_start_[s.fi + 1];
    if (s.fj >= 0) ++incidence_start_[s.fj + 1];
  }
  for (int f = 0; f < n; ++f) incidence_start_[f + 1] += incidence_start_[f];
  incidence_.resize(incidence_start_[n]);
  std::vector<int> next(incidence_start_.begin(), incidence_start_.end() - 1);
  for (std::size_t k = 0; k < springs_.size(); ++k) {  // in spring order
    const int id = static_cast<int>(k) + 1;
    if (springs_[k].fi >= 0) incidence_[next[springs_[k].fi]++] = id;
    if (springs_[k].fj >= 0) incidence_[next[springs_[k].fj]++] = -id;
  }
}

template <int D>
void LocalGlobal<D>::advance(State& state) {
  const double h = model().integrator.dt;
  if (!pins_taken_) take_pins(state);
  auto q = map_points<D>(state.q);
  auto v = map_points<D>(state.v);
  y_ = q + h * v;  // where the old velocity carries every particle; eliminated ones go there
  std::vector<std::pair<int, double>> signature = collect_anchors(state);
  collect_contacts(state, signature);
  if (signature != factored_anchors_) {
    factored_anchors_ = std::move(signature);
    factor();
  }
  p_ = y_;
  if (settings_.start == IterationStart::kCurrent) {
    for (int p : free_.particles()) p_.row(p) = q.row(p);
  }
  assemble_constant_rhs(state);
  if (settings_.acceleration == Acceleration::kAnderson) start_q_ = state.q;
  last_iterations_ = 0;
  iterate();
  for (int p : free_.particles()) {
    v.row(p) = (p_.row(p) - q.row(p)) / h;
    q.row(p) = p_.row(p);
  }
  for (int p = 0; p < model().num_particles(); ++p) {
    if (free_.of_particle(p) < 0) q.row(p) = p_.row(p);  // eliminated: moves with its own velocity
  }
}

template <int D>
void LocalGlobal<D>::iterate() {
  if (settings_.acceleration == Acceleration::kAnderson) return iterate_anderson();
  if (settings_.acceleration == Acceleration::kChebyshev) return iterate_chebyshev();
  for (int iteration = 1; iteration <= settings_.iterations; ++iteration) {
    cancellation().check();
    local_step(rhs_);
    last_change_ = global_solve(rhs_);
    last_iterations_ = iteration;
    if (settings_.tolerance > 0.0 && last_change_ <= settings_.tolerance) break;
  }
}

template <int D>
void LocalGlobal<D>::take_pins(const State& state) {
  const auto q = map_points<D>(state.q);
  const auto v = map_points<D>(state.v);
  pin_position_.resize(static_cast<Eigen::Index>(pinned_.size()), D);
  pin_velocity_.resize(static_cast<Eigen::Index>(pinned_.size()), D);
  for (std::size_t k = 0; k < pinned_.size(); ++k) {
    pin_position_.row(k) = q.row(pinned_[k]);
    pin_velocity_.row(k) = v.row(pinned_[k]);
  }
  pin_step_ = state.step;
  pins_taken_ = true;
}

template <int D>
std::vector<std::pair<int, double>> LocalGlobal<D>::collect_anchors(const State& state) {
  const SceneModel& model = this->model();
  const double h = model.integrator.dt;
  anchors_.clear();
  for (const Force* force : split_.anchors) {
    if (const std::optional<AnchorTerm> anchor = force->local_global_anchor())
      anchors_.push_back(*anchor);
  }
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
void LocalGlobal<D>::collect_contacts(const State& state,
                                      std::vector<std::pair<int, double>>& signature) {
  contacts_.clear();
  if (penalty_ == nullptr) return;
  const SceneModel& model = this->model();
  const auto q = map_points<D>(state.q);
  const int num_half_planes = static_cast<int>(model.half_planes.size());
  const int num_spheres = static_cast<int>(model.spheres.size());
  for (int f = 0; f < free_.num_particles(); ++f) {
    const int p = free_.particles()[f];
    // Within reach at pⁿ, with a margin of twice the step's predicted motion (distances to an
    // obstacle change no faster than the particle moves).
    const double margin = penalty_->thickness() + 2.0 * (y_.row(p) - q.row(p)).norm();
    const auto consider = [&](CollisionKind kind, int obstacle) {
      const CandidatePair pair{kind, p, obstacle};
      const Separation<D> s = separation<D>(model, pair, state.q);
      if (s.distance < s.radii + margin) {
        contacts_.push_back({f, pair});
        signature.emplace_back(p, penalty_->stiffness());
      }
    };
    for (int o = 0; o < num_half_planes; ++o) consider(CollisionKind::kParticleHalfPlane, o);
    for (int o = 0; o < num_spheres; ++o) consider(CollisionKind::kParticleSphere, o);
  }
}

template <int D>
void LocalGlobal<D>::add_contact_targets(Points<D>& rhs) const {
  const SceneModel& model = this->model();
  const double k = penalty_ != nullptr ? penalty_->stiffness() : 0.0;
  const double thickness = penalty_ != nullptr ? penalty_->thickness() : 0.0;
  const auto position = [this](int p) -> Vec<D> { return p_.row(p).transpose(); };
  for (const ObstacleContact& c : contacts_) {
    // The nearest point out of reach, p + min(δ, 0) n̂ (n from the particle to the obstacle),
    // so that ½ k |p - t|² = ½ k δ² inside the reach and 0 outside, the penalty energy.
    const Separation<D> s = separation_of<D>(model, c.pair, position);
    const double length = s.n.norm();
    Vec<D> target = position(c.pair.particle);
    const double delta = s.distance - s.radii - thickness;
    if (length > 0.0 && delta < 0.0) target += (delta / length) * s.n;
    rhs.row(c.f) += k * target.transpose();
  }
}

template <int D>
void LocalGlobal<D>::factor() {
  const int n = free_.num_particles();
  if (n == 0) return;
  std::vector<AnchorTerm> terms = anchors_;  // and each contact's k on its particle's diagonal
  for (const ObstacleContact& c : contacts_) {
    terms.push_back({c.pair.particle, penalty_->stiffness(), Eigen::Vector3d::Zero()});
  }
  const SparseMatrix Q = assemble_local_global_matrix(model().mass, free_, split_.springs, terms,
                                                      model().integrator.dt);
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
    throw Error(ErrorKind::kStepFailed,
                "local/global: the system matrix M/h² + AᵀKA is not positive definite "
                "(a negative stiffness or mass?)");
  }
  ++factorizations_;
}

template <int D>
void LocalGlobal<D>::assemble_constant_rhs(const State& state) {
  const SceneModel& model = this->model();
  const double h = model.integrator.dt;
  const auto q = map_points<D>(state.q);
  explicit_gradient_.setZero(state.q.size());
  const ForceInput in{state.q, state.v, model.mass};
  for (const Force* force : split_.others) {
    if (force == split_.contact && penalty_ != nullptr) {  // obstacles are in Q
      penalty_->add_gradient(in, explicit_gradient_, PenaltyPairs::kAmongParticles);
    } else {
      force->add_gradient(in, explicit_gradient_);
    }
  }
  const auto gradient = map_points<D>(static_cast<const Vector&>(explicit_gradient_));
  const int n = free_.num_particles();
  constant_rhs_.resize(n, D);
  for (int f = 0; f < n; ++f) {
    const int p = free_.particles()[f];
    // Every unknown particle receives the forces, penalty-pinned ones included.
    constant_rhs_.row(f) = (model.mass[D * p] / (h * h)) * y_.row(p) - gradient.row(p);
  }
  for (const Spring& s : springs_) {
    if (s.b != 0.0) {  // Laplacian damping: (b/h) a aᵀ pⁿ
      const Vec<D> lagged = (s.b / h) * (q.row(s.i) - q.row(s.j)).transpose();
      if (s.fi >= 0) constant_rhs_.row(s.fi) += lagged.transpose();
      if (s.fj >= 0) constant_rhs_.row(s.fj) -= lagged.transpose();
    }
    const double w = s.k + s.b / h;  // an eliminated end's known position moves to the right
    if (s.fj < 0) constant_rhs_.row(s.fi) += w * y_.row(s.j);
    if (s.fi < 0) constant_rhs_.row(s.fj) += w * y_.row(s.i);
  }
  for (const AnchorTerm& a : anchors_) {
    constant_rhs_.row(free_.of_particle(a.i)) += a.k * a.target.head<D>().transpose();
  }
}

template <int D>
void LocalGlobal<D>::project_springs() {
  const std::size_t last = springs_.size();
  std::size_t s = 0;
#if defined(__SSE2__)
  // Two springs at a time: one packed square root and one packed division for both (they
  // bound the scalar loop's speed). Each lane does the scalar loop's operations in its order,
  // so the bits are the same.
  for (; s + 1 < last; s += 2) {
    const Spring& a = springs_[s];
    const Spring& b = springs_[s + 1];
    __m128d delta[D];  // (std::array would drop the type's alignment attribute)
    for (int c = 0; c < D; ++c) {
      delta[c] = _mm_sub_pd(_mm_set_pd(p_(b.i, c), p_(a.i, c)), _mm_set_pd(p_(b.j, c), p_(a.j, c)));
    }
    __m128d squared = _mm_mul_pd(delta[0], delta[0]);
    for (int c = 1; c < D; ++c) squared = _mm_add_pd(squared, _mm_mul_pd(delta[c], delta[c]));
    const __m128d length = _mm_sqrt_pd(squared);
    const __m128d scale = _mm_div_pd(_mm_set_pd(b.l0, a.l0), length);
    alignas(16) std::array<double, 2> lengths;
    alignas(16) std::array<std::array<double, 2>, D> terms;
    _mm_store_pd(lengths.data(), length);
    const __m128d k = _mm_set_pd(b.k, a.k);
    for (int c = 0; c < D; ++c) {
      _mm_store_pd(terms[c].data(), _mm_mul_pd(k, _mm_mul_pd(scale, delta[c])));
    }
    for (int lane = 0; lane < 2; ++lane) {
      if (lengths[lane] > 0.0) {
        for (int c = 0; c < D; ++c) kd_(s + lane, c) = terms[c][lane];
      }
    }
  }
#endif
  for (; s < last; ++s) {
    const Spring& spring = springs_[s];
    const Vec<D> delta = (p_.row(spring.i) - p_.row(spring.j)).transpose();
    const double length = delta.norm();
    // Local step: the rest-length vector nearest the current one d_s (kept when the length is
    // 0), times k_s.
    if (length > 0.0) kd_.row(s) = spring.k * ((spring.l0 / length) * delta.transpose());
  }
}

template <int D>
void LocalGlobal<D>::gather_spring_terms(Points<D>& rhs) const {
  rhs.resize(constant_rhs_.rows(), D);
  for (int f = 0; f < free_.num_particles(); ++f) {
    // The same sums, in the same order, as adding each spring's term to both its ends in
    // spring order: every row's springs are listed in increasing order.
    Eigen::Matrix<double, 1, D> sum = constant_rhs_.row(f);
    for (int e = incidence_start_[f]; e < incidence_start_[f + 1]; ++e) {
      const int end = incidence_[e];
      if (end > 0) {
        sum += kd_.row(end - 1);
      } else {
        sum -= kd_.row(-end - 1);
      }
    }
    rhs.row(f) = sum;
  }
}

template <int D>
void LocalGlobal<D>::local_step(Points<D>& rhs) {
  // Every spring's term first, then every row's sum of its springs' terms: a scatter of each
  // term into both its ends' rows would chain each row's additions through memory.
  project_springs();
  gather_spring_terms(rhs);
  add_contact_targets(rhs);
}

template <int D>
double LocalGlobal<D>::global_solve(Points<D>& rhs) {
  if (free_.num_particles() == 0) return 0.0;
  solver_.solve_in_place<D>(rhs);
  double change = 0.0;
  for (int f = 0; f < free_.num_particles(); ++f) {
    const int p = free_.particles()[f];
    change = std::max(change, (rhs.row(f) - p_.row(p)).cwiseAbs().maxCoeff());
    p_.row(p) = rhs.row(f);
  }
  return change;
}

template class LocalGlobal<2>;
template class LocalGlobal<3>;

namespace {
constexpr std::array<std::string_view, 1> kLocalGlobalAliases = {"fast-mass-springs"};
constexpr std::array<std::string_view, 2> kStarts = {"inertial", "current"};
constexpr std::array<std::string_view, 2> kPins = {"elimination", "penalty"};
constexpr std::array<std::string_view, 3> kSolvers = {"auto", "dense", "sparse"};
constexpr LocalGlobalSettings kLocalGlobalDefaults;
constexpr IntegratorProperties kLocalGlobalProperties = {
    .order = 1, .implicit = true, .velocity_from_positions = true, .energy = EnergyTrend::kDecays};
constexpr std::array<std::string_view, 2> kAccelerations = {"anderson", "chebyshev"};
constexpr std::array<std::string_view, 1> kAcceleratedAliases = {"anderson-local-global"};
constexpr OptionSpec kIterationsOption =
    OptionSpec::integer("iterations", kLocalGlobalDefaults.iterations, 1, 1000000,
                        "local/global iterations per step (at most, with a tolerance)");
constexpr OptionSpec kToleranceOption =
    OptionSpec::number("tolerance", kLocalGlobalDefaults.tolerance, 0.0, /*excluded=*/false,
                       "stop iterating once no coordinate moves more than this (m); 0: never");
constexpr OptionSpec kStartOption =
    OptionSpec::choice("start", kStarts,
                       "where each step's iterations begin: at pⁿ + h vⁿ (inertial) or at the "
                       "current positions pⁿ (current, as in the fast mass-springs assignment)");
constexpr OptionSpec kPinsOption =
    OptionSpec::choice("pins", kPins,
                       "fixed particles: removed from the system (exact), or held by penalty "
                       "springs as in Liu et al. 2013");
constexpr OptionSpec kPenaltyOption =
    OptionSpec::number("penalty", kLocalGlobalDefaults.penalty_weight, 0.0, /*excluded=*/true,
                       "stiffness w of penalty pins (N/m)");
constexpr OptionSpec kSolverChoiceOption =
    OptionSpec::choice("solver", kSolvers,
                       "factorization of the constant matrix: dense up to 64 free particles "
                       "(auto), dense, or sparse");
constexpr std::array kLocalGlobalOptionSpecs = {kIterationsOption, kToleranceOption,
                                                kStartOption,      kPinsOption,
                                                kPenaltyOption,    kSolverChoiceOption};
constexpr std::array kAcceleratedOptions = {
    kIterationsOption,
    kToleranceOption,
    kStartOption,
    kPinsOption,
    kPenaltyOption,
    kSolverChoiceOption,
    OptionSpec::choice("acceleration", kAccelerations,
                       "anderson (Peng et al. 2018, energy safeguarded, the default) or "
                       "chebyshev (Wang 2015, needs rho)"),
    OptionSpec::integer("window", kLocalGlobalDefaults.window, 1, 100,
                        "anderson: how many recent iterates are combined"),
    OptionSpec::number("rho", kLocalGlobalDefaults.rho, 0.0, /*excluded=*/true,
                       "chebyshev: the spectral radius of the plain iteration, below 1"),
};

std::unique_ptr<Integrator> make_local_global(const OptionValues& options, int dim) {
  const LocalGlobalSettings settings = local_global_settings(options);
  if (dim == 3) return std::make_unique<LocalGlobal<3>>(settings);
  return std::make_unique<LocalGlobal<2>>(settings);
}
}  // namespace

LocalGlobalSettings local_global_settings(const OptionValues& options) {
  LocalGlobalSettings settings;
  settings.iterations = options.integer("iterations");
  settings.tolerance = options.number("tolerance");
  settings.start =
      options.choice("start") == "current" ? IterationStart::kCurrent : IterationStart::kInertial;
  settings.pins =
      options.choice("pins") == "penalty" ? PinMethod::kPenalty : PinMethod::kElimination;
  settings.penalty_weight = options.number("penalty");
  const std::string_view solver = options.choice("solver");
  settings.solver = solver == "dense"    ? LinearSolverChoice::kDense
                    : solver == "sparse" ? LinearSolverChoice::kSparse
                                         : LinearSolverChoice::kAuto;
  if (options.has("acceleration")) {
    const std::string_view a = options.choice("acceleration");
    settings.acceleration = a == "chebyshev" ? Acceleration::kChebyshev : Acceleration::kAnderson;
    settings.window = options.integer("window");
    settings.rho = options.number("rho");
  }
  return settings;
}

constinit const IntegratorMethod kLocalGlobalMethod{
    .name = "local-global",
    .aliases = kLocalGlobalAliases,
    .summary = "implicit Euler for springs by local/global iterations (Liu et al. 2013)",
    .options = kLocalGlobalOptionSpecs,
    .properties = kLocalGlobalProperties,
    .create = &make_local_global,
};

constinit const IntegratorMethod kAcceleratedLocalGlobalMethod{
    .name = "accelerated-local-global",
    .aliases = kAcceleratedAliases,
    .summary =
        "local/global iterations with Anderson acceleration (Peng et al. 2018): the same "
        "step, reached in fewer iterations",
    .options = kAcceleratedOptions,
    .properties = kLocalGlobalProperties,
    .create = &make_local_global,
};

}  // namespace fosssim
