#include "baselines.h"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <optional>
#include <stdexcept>
#include <vector>

#include "core/force_evaluation.h"
#include "core/solvers/step_solver.h"
#include "core/systems/backward_euler.h"
#include "core/systems/free_dofs.h"
#include "core/systems/local_global_system.h"
#include "core/systems/step_matrix.h"

namespace fosssim::bench {

namespace {

/// The selection P (free DOFs × all DOFs) of a model's free degrees of freedom.
SparseMatrix selection(const SceneModel& model) {
  const FreeDofs free(model.fixed, model.dim);
  std::vector<Triplet> ones;
  for (int f = 0; f < free.num_particles(); ++f) {
    for (int c = 0; c < model.dim; ++c) {
      ones.emplace_back(model.dim * f + c, model.dim * free.particles()[f] + c, 1.0);
    }
  }
  SparseMatrix P(free.num_dofs(), model.num_dofs());
  P.setFromTriplets(ones.begin(), ones.end());
  return P;
}

/// Levin's recipe with any of Eigen's sparse factorizations, made afresh every step.
template <typename Factorization>
class EveryStepRecipe final : public Integrator {
 protected:
  void prepare() override {
    P_ = selection(model());
    M_ = SparseMatrix(model().mass.asDiagonal());
  }
  void advance(State& state) override {
    const double h = model().integrator.dt;
    const Vector f = compute_force(forces(), state.q, state.v);
    const SparseMatrix K = -compute_hessian_x(forces(), state.q, state.v);
    const SparseMatrix D = -compute_hessian_v(forces(), state.q, state.v);
    const SparseMatrix A = P_ * (M_ - h * h * K - h * D) * P_.transpose();
    const Vector b = P_ * (M_ * state.v + h * f - h * (D * state.v));
    Factorization solver;
    solver.compute(A);
    if (solver.info() != Eigen::Success) throw std::runtime_error("baseline: singular matrix");
    const Vector free_v = solver.solve(b);
    state.v = P_.transpose() * free_v;
    state.q += h * state.v;
  }

 private:
  SparseMatrix P_, M_;
};

/// A complete student solution of the CSC417 mass-spring assignment (a2), per its handout and
/// starter code: the state is reduced by the projection P that removes the fixed vertices
/// (q = Pᵀ q̂ + x0); every step assembles the force of every spring and the gravity, f = P f,
/// and the stiffness K of every spring from 36 triplets each (Eigen's setFromTriplets),
/// K = P K Pᵀ, then factors M - h² K with a fresh Eigen::SimplicialLDLT (analysis included) and
/// solves (M - h² K) v̂ = M v̂ + h f; q̂ += h v̂. Springs are the model's mesh springs (no
/// damping); other forces (gravity) enter the force only, as in the assignment.
class StudentLinearlyImplicit final : public Integrator {
 protected:
  void prepare() override {
    const SceneModel& model = this->model();
    const MassSpringForces split = sort_mass_spring_forces(forces());
    if (!split.anchors.empty()) throw std::runtime_error("student-lie: anchors are not supported");
    for (const SpringTerm& t : split.springs) {
      if (t.b != 0.0) throw std::runtime_error("student-lie: damped springs are not supported");
    }
    springs_ = split.springs;
    others_ = split.others;
    P_ = selection(model);
    mass_ = SparseMatrix(P_ * SparseMatrix(model.mass.asDiagonal()) * P_.transpose());
  }
  void advance(State& state) override {
    const double h = model().integrator.dt;
    if (x0_.size() == 0) x0_ = state.q - P_.transpose() * (P_ * state.q);
    Vector q = P_ * state.q;
    Vector v = P_ * state.v;
    // force(q, v), as the assignment's lambda: full coordinates, every spring, gravity, f = P f.
    Vector full_q = P_.transpose() * q + x0_;
    const Vector full_v = P_.transpose() * v;
    Vector f = Vector::Zero(full_q.size());
    for (const SpringTerm& s : springs_) {
      const Eigen::Vector3d d = full_q.segment<3>(3 * s.i) - full_q.segment<3>(3 * s.j);
      const double l = d.norm();
      const Eigen::Vector3d g = s.k * (l - s.l0) / l * d;  // dV/dq_i
      f.segment<3>(3 * s.i) -= g;
      f.segment<3>(3 * s.j) += g;
    }
    Vector gradient = Vector::Zero(full_q.size());
    const ForceInput in{full_q, full_v, model().mass};
    for (const Force* force : others_) force->add_gradient(in, gradient);
    f -= gradient;
    const Vector reduced_f = P_ * f;
    // stiffness(q, v): 36 triplets per spring, K = P K Pᵀ.
    full_q = P_.transpose() * q + x0_;
    std::vector<Triplet> triplets;
    triplets.reserve(36 * springs_.size());
    for (const SpringTerm& s : springs_) {
      const Eigen::Vector3d d = full_q.segment<3>(3 * s.i) - full_q.segment<3>(3 * s.j);
      const double l = d.norm();
      const Eigen::Matrix3d H = s.k * ((1.0 - s.l0 / l) * Eigen::Matrix3d::Identity() +
                                       s.l0 / (l * l * l) * d * d.transpose());
      for (int a = 0; a < 2; ++a) {
        for (int b = 0; b < 2; ++b) {
          const int row = 3 * (a == 0 ? s.i : s.j), col = 3 * (b == 0 ? s.i : s.j);
          const double sign = a == b ? -1.0 : 1.0;  // K = -H
          for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 3; ++c) triplets.emplace_back(row + r, col + c, sign * H(r, c));
          }
        }
      }
    }
    SparseMatrix K(full_q.size(), full_q.size());
    K.setFromTriplets(triplets.begin(), triplets.end());
    K = P_ * K * P_.transpose();
    Eigen::SimplicialLDLT<SparseMatrix> solver;
    solver.compute(mass_ - h * h * K);
    if (solver.info() != Eigen::Success) throw std::runtime_error("baseline: singular matrix");
    v = solver.solve(mass_ * v + h * reduced_f);
    q += h * v;
    state.v = P_.transpose() * v;
    state.q = P_.transpose() * q + x0_;
  }

 private:
  std::vector<SpringTerm> springs_;
  std::vector<const Force*> others_;
  SparseMatrix P_, mass_;
  Vector x0_;
};

/// FOSSSim's implicit integrators as they were: triplet assembly and Eigen's factorizations.
class OldPath final : public Integrator {
 public:
  enum class Method { kLinearly, kLinearized, kNewton };
  explicit OldPath(Method method) : method_(method) {}

 protected:
  void prepare() override {
    matrix_.emplace(forces(), method_ == Method::kLinearly ? FixedParticleRule::kElimination
                                                           : FixedParticleRule::kIdentityRows);
    solver_.emplace(forces().has_symmetric_jacobians(), SolverChoice::kEigen);
  }
  void advance(State& state) override {
    const double h = model().integrator.dt;
    if (method_ == Method::kLinearly) {
      Vector rhs = h * compute_force(forces(), state.q, state.v);
      const SparseMatrix& A = matrix_->assemble_from_triplets(state.q, state.v, h, &state.v, &rhs);
      matrix_->add_solution(solve(A, matrix_->restrict(rhs)), state.v);
    } else if (method_ == Method::kLinearized) {
      const Vector predicted = state.q + h * state.v;
      const Vector rhs = matrix_->restrict(h * compute_force(forces(), predicted, state.v));
      matrix_->add_solution(solve(matrix_->assemble_from_triplets(predicted, state.v, h), rhs),
                            state.v);
    } else {
      newton(state, h);
      return;
    }
    state.q += h * state.v;
  }

 private:
  Vector solve(const SparseMatrix& A, const Vector& b) {
    auto x = solver_->solve(A, b);
    if (!x) throw std::runtime_error("baseline: singular matrix");
    return *x;
  }
  /// The course's Newton iteration, to 1e-9.
  void newton(State& state, double h) {
    const BackwardEulerStep problem{forces(), state, h};
    Vector dv = Vector::Zero(state.v.size());
    Vector rhs = problem.residual(dv);
    for (int iteration = 0; iteration < 200; ++iteration) {
      const Vector v = state.v + dv;
      const Vector delta = solve(matrix_->assemble_from_triplets(state.q + h * v, v, h), rhs);
      dv += delta;
      if (delta.norm() < 1e-9) break;
      rhs = problem.residual(dv);
    }
    state.q += h * (state.v + dv);
    state.v += dv;
  }

  Method method_;
  std::optional<StepMatrix> matrix_;
  std::optional<StepSolver> solver_;
};

/// The course program's recipe for linearized implicit Euler: dense matrices, dense LU.
class DenseLu final : public Integrator {
 protected:
  void advance(State& state) override {
    const SceneModel& model = this->model();
    const double h = model.integrator.dt;
    const Vector predicted = state.q + h * state.v;
    Eigen::MatrixXd A = h * h * Eigen::MatrixXd(compute_hessian_x(forces(), predicted, state.v)) +
                        h * Eigen::MatrixXd(compute_hessian_v(forces(), predicted, state.v));
    A.diagonal() += model.mass;
    Vector b = h * compute_force(forces(), predicted, state.v);
    for (int dof = 0; dof < model.num_dofs(); ++dof) {
      if (!model.is_fixed_dof(dof)) continue;
      A.row(dof).setZero();
      A.col(dof).setZero();
      A(dof, dof) = 1.0;
      b[dof] = 0.0;
    }
    state.v += A.partialPivLu().solve(b);
    state.q += h * state.v;
  }
};

/// The local/global solver written plainly: Eigen's SimplicialLLT, Eigen's products.
class StudentLocalGlobal final : public Integrator {
 protected:
  void prepare() override {
    const SceneModel& model = this->model();
    const double h = model.integrator.dt;
    const int n = model.num_particles();
    iterations_ = model.integrator.options.integer("iterations");
    penalty_ = model.integrator.options.number("penalty");
    const MassSpringForces split = sort_mass_spring_forces(forces());
    springs_ = split.springs;
    others_ = split.others;
    std::vector<Triplet> q, j;
    for (int p = 0; p < n; ++p) {
      q.emplace_back(p, p, model.mass[3 * p] / (h * h));
      if (model.fixed[p]) {
        q.emplace_back(p, p, penalty_);
        pins_.push_back(p);
      }
    }
    for (std::size_t s = 0; s < springs_.size(); ++s) {
      const SpringTerm& t = springs_[s];
      q.emplace_back(t.i, t.i, t.k);
      q.emplace_back(t.j, t.j, t.k);
      q.emplace_back(t.i, t.j, -t.k);
      q.emplace_back(t.j, t.i, -t.k);
      j.emplace_back(t.i, static_cast<int>(s), t.k);
      j.emplace_back(t.j, static_cast<int>(s), -t.k);
    }
    SparseMatrix Q(n, n);
    Q.setFromTriplets(q.begin(), q.end());
    J_.resize(n, static_cast<Eigen::Index>(springs_.size()));
    J_.setFromTriplets(j.begin(), j.end());
    llt_.compute(Q);
    if (llt_.info() != Eigen::Success) throw std::runtime_error("baseline: Q is not SPD");
  }
  void advance(State& state) override {
    const SceneModel& model = this->model();
    const double h = model.integrator.dt;
    const int n = model.num_particles();
    const Eigen::MatrixX3d q = map_points<3>(state.q);
    const Eigen::MatrixX3d v = map_points<3>(state.v);
    if (pin_targets_.rows() == 0) {
      pin_targets_.resize(static_cast<Eigen::Index>(pins_.size()), 3);
      for (std::size_t k = 0; k < pins_.size(); ++k) pin_targets_.row(k) = q.row(pins_[k]);
    }
    Vector gradient = Vector::Zero(state.q.size());
    const ForceInput in{state.q, state.v, model.mass};
    for (const Force* force : others_) force->add_gradient(in, gradient);
    const Eigen::MatrixX3d y = q + h * v;
    Eigen::MatrixX3d b0(n, 3);
    for (int p = 0; p < n; ++p) {
      b0.row(p) = model.mass[3 * p] / (h * h) * y.row(p);
      if (!model.fixed[p]) b0.row(p) -= map_points<3>(gradient).row(p);
    }
    for (std::size_t k = 0; k < pins_.size(); ++k)
      b0.row(pins_[k]) += penalty_ * pin_targets_.row(k);
    Eigen::MatrixX3d p = y;
    Eigen::MatrixX3d d(static_cast<Eigen::Index>(springs_.size()), 3);
    for (int iteration = 0; iteration < iterations_; ++iteration) {
      for (std::size_t s = 0; s < springs_.size(); ++s) {
        const Eigen::RowVector3d delta = p.row(springs_[s].i) - p.row(springs_[s].j);
        d.row(s) = springs_[s].l0 * delta.normalized();
      }
      const Eigen::MatrixX3d b = b0 + J_ * d;
      p = llt_.solve(b);
    }
    map_points<3>(state.v) = (p - q) / h;
    map_points<3>(state.q) = p;
  }

 private:
  int iterations_ = 0;
  double penalty_ = 0.0;
  std::vector<SpringTerm> springs_;
  std::vector<const Force*> others_;
  std::vector<int> pins_;
  Eigen::MatrixX3d pin_targets_;
  SparseMatrix J_;
  Eigen::SimplicialLLT<SparseMatrix> llt_;
};

}  // namespace

std::unique_ptr<Integrator> make_baseline(std::string_view name) {
  using LdltRecipe = EveryStepRecipe<Eigen::SimplicialLDLT<SparseMatrix>>;
  using LuRecipe = EveryStepRecipe<Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>>>;
  if (name == "levin") return std::make_unique<LdltRecipe>();
  if (name == "sparselu") return std::make_unique<LuRecipe>();
  if (name == "old-lie") return std::make_unique<OldPath>(OldPath::Method::kLinearly);
  if (name == "old-linearized") return std::make_unique<OldPath>(OldPath::Method::kLinearized);
  if (name == "old-implicit") return std::make_unique<OldPath>(OldPath::Method::kNewton);
  if (name == "dense-lu") return std::make_unique<DenseLu>();
  if (name == "student-lg") return std::make_unique<StudentLocalGlobal>();
  if (name == "student-lie") return std::make_unique<StudentLinearlyImplicit>();
  return nullptr;
}

}  // namespace fosssim::bench
