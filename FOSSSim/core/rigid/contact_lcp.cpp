#include "core/rigid/contact_lcp.h"

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "core/solvers/solver_failure.h"

namespace fosssim {

double contact_tolerance(const ContactProblem& problem, const Vector& lambda) {
  double scale = 1.0;
  if (problem.b.size() > 0) scale = std::max(scale, problem.b.cwiseAbs().maxCoeff());
  if (lambda.size() > 0) {
    scale = std::max(scale, problem.A.cwiseAbs().maxCoeff() * lambda.cwiseAbs().maxCoeff());
  }
  return 1e-9 * scale;
}

bool check_contact_solution(const ContactProblem& problem, const Vector& lambda,
                            std::string* problem_text) {
  const auto say = [&](const std::string& text) {
    if (problem_text != nullptr) *problem_text = text;
    return false;
  };
  if (!lambda.allFinite()) return say("a non-finite impulse");
  const double tol = contact_tolerance(problem, lambda);
  const Vector w = problem.A * lambda + problem.b;
  for (int i = 0; i < lambda.size(); ++i) {
    std::ostringstream where;
    where << " at contact " << i << " (lambda " << lambda[i] << ", w " << w[i] << ")";
    if (lambda[i] < -tol) return say("a negative impulse" + where.str());
    if (w[i] < -tol) return say("an approaching contact" + where.str());
    if (std::fabs(lambda[i] * w[i]) > tol * std::max(1.0, lambda[i])) {
      return say("an impulse on a separating contact" + where.str());
    }
  }
  return true;
}

bool is_degenerate(const Eigen::MatrixXd& A) {
  if (A.rows() == 0) return false;
  const double largest = A.diagonal().cwiseAbs().maxCoeff();
  if (!(largest > 0.0)) return true;
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(A);
  if (ldlt.info() != Eigen::Success) return true;
  return !(ldlt.vectorD().minCoeff() > 1e-10 * largest);
}

int contact_qp_iteration_limit(int contacts) { return 100 + 20 * contacts; }

namespace {

/// The columns of J, sparse (a contact touches at most two bodies: six coordinates).
struct SparseColumns {
  std::vector<std::vector<std::pair<int, double>>> own;  // when made from a dense J
  const std::vector<std::vector<std::pair<int, double>>>* columns;

  explicit SparseColumns(const ContactProblem& problem) : columns(&problem.J_columns) {
    if (!problem.J_columns.empty()) return;
    const Eigen::MatrixXd& J = problem.J;
    own.resize(J.cols());
    for (int c = 0; c < J.cols(); ++c) {
      for (int i = 0; i < J.rows(); ++i) {
        if (J(i, c) != 0.0) own[c].emplace_back(i, J(i, c));
      }
    }
    columns = &own;
  }
  double dot(int c, const Vector& x) const {
    double sum = 0.0;
    for (const auto& [i, value] : (*columns)[c]) sum += value * x[i];
    return sum;
  }
  void add(int c, double factor, Vector& x) const {
    for (const auto& [i, value] : (*columns)[c]) x[i] += factor * value;
  }
};

/// The upper triangular R of a QR factorization J_S = Q R of the active columns, kept without
/// Q: a column is added from its projection (corrected semi-normal equations, as accurate as a
/// QR), a column is removed with Givens rotations.
class ActiveFactor {
 public:
  /// Room for `capacity` active columns at most. Up to kFullStorage columns the storage is
  /// allocated at once (so small problems keep one layout, and their round-off); beyond, it
  /// grows as columns join (n² doubles of 14,000 contacts are 1.5 GB).
  static constexpr int kFullStorage = 1024;
  explicit ActiveFactor(int capacity)
      : capacity_(capacity),
        r_(std::min(capacity, kFullStorage), std::min(capacity, kFullStorage)) {}
  int size() const { return s_; }

  /// Solves RᵀR x = d in place.
  void solve_normal(Vector& d) const {
    if (s_ == 0) return;
    const auto R = r_.topLeftCorner(s_, s_).triangularView<Eigen::Upper>();
    R.transpose().solveInPlace(d);
    R.solveInPlace(d);
  }
  /// Appends a column whose least-squares coefficients on the active columns are `coefficients`
  /// and whose remainder has length `remainder`.
  void append(const Vector& coefficients, double remainder) {
    if (s_ == r_.rows()) {  // grow (the values of the top-left block are kept)
      const int grown = std::min(capacity_, 2 * static_cast<int>(r_.rows()));
      r_.conservativeResizeLike(Eigen::MatrixXd::Zero(grown, grown));
    }
    // The new column is R times the coefficients: row i sums r_ij c_j for j = i, i + 1, ...
    // in that order; the loop runs down R's columns (contiguous) with one running sum per
    // row, which is the same order of additions as a sum along each row, bit for bit.
    auto column = r_.col(s_).head(s_);
    column.setZero();
    for (int j = 0; j < s_; ++j) {
      const double c = coefficients[j];
      for (int i = 0; i <= j; ++i) column[i] += r_(i, j) * c;
    }
    for (int i = s_ + 1; i < r_.rows(); ++i) r_(i, s_) = 0.0;
    r_(s_, s_) = remainder;
    ++s_;
  }
  /// Removes column k: the columns after it move left, Givens rotations restore the triangle.
  void remove(int k) {
    for (int j = k; j + 1 < s_; ++j) r_.col(j).head(s_) = r_.col(j + 1).head(s_);
    --s_;
    for (int j = k; j < s_; ++j) {
      const double a = r_(j, j), b = r_(j + 1, j);
      const double h = std::hypot(a, b);
      if (h == 0.0) continue;
      const double c = a / h, sn = b / h;
      for (int col = j; col < s_; ++col) {
        const double x = r_(j, col), y = r_(j + 1, col);
        r_(j, col) = c * x + sn * y;
        r_(j + 1, col) = -sn * x + c * y;
      }
      r_(j + 1, j) = 0.0;
    }
  }

 private:
  int capacity_;
  Eigen::MatrixXd r_;
  int s_ = 0;
};

}  // namespace

Vector solve_contact_qp(const ContactProblem& problem, int max_iterations) {
  const Vector& b = problem.b;
  const int n = static_cast<int>(b.size());
  Vector lambda = Vector::Zero(n);
  if (n == 0) return lambda;
  const SparseColumns J(problem);
  const int dofs = static_cast<int>(problem.J_columns.empty() ? problem.J.rows() : problem.J_rows);
  const double scale = std::max(1.0, b.cwiseAbs().maxCoeff());
  // A contact is violated below −tol; one that depends on the active ones and cannot be
  // reached by drops is accepted when within −loose (round-off of the dependence).
  const double tol = 1e-12 * scale, loose = 1e-9 * scale;
  std::vector<int> active;  // S: contacts held at w = 0, their columns independent
  std::vector<char> is_active(n, 0), skipped(n, 0);
  ActiveFactor factor(n);
  int iterations = 0;
  const auto fail = [&](const std::string& why) {
    std::ostringstream message;
    message << "rigid-body contact: the velocity-projection solver " << why << " (" << n
            << " contacts, " << active.size() << " active)";
    throw SolverFailure(message.str());
  };
  const double inf = std::numeric_limits<double>::infinity();
  Vector w = b, x(dofs), z(dofs);
  // w = b + Jᵀ(Jλ), from λ afresh (no drift), in O(contacts + coordinates).
  const auto update_w = [&] {
    x.setZero();
    for (int c = 0; c < n; ++c) {
      if (lambda[c] != 0.0) J.add(c, lambda[c], x);
    }
    for (int c = 0; c < n; ++c) w[c] = b[c] + J.dot(c, x);
  };
  while (true) {
    int p = -1;
    for (int i = 0; i < n; ++i) {
      if (!is_active[i] && !skipped[i] && w[i] < -tol && (p < 0 || w[i] < w[p])) p = i;
    }
    if (p < 0) return lambda;
    z.setZero();
    J.add(p, 1.0, z);
    const double column_norm = z.norm();
    while (true) {  // move λ until contact p joins the active set or is met
      if (++iterations > max_iterations) {
        fail("did not finish within " + std::to_string(max_iterations) + " steps");
      }
      const int s = static_cast<int>(active.size());
      // r: the active columns' combination closest to column p; z: the rest of column p.
      Vector r = Vector::Zero(s);
      z.setZero();
      J.add(p, 1.0, z);
      for (int round = 0; round < 2 && s > 0; ++round) {  // a solve and one correction
        Vector d(s);
        for (int k = 0; k < s; ++k) d[k] = J.dot(active[k], z);
        factor.solve_normal(d);
        r += d;
        for (int k = 0; k < s; ++k) J.add(active[k], -d[k], z);
      }
      const double zn = z.squaredNorm();  // how fast w_p grows along the step
      const bool independent = std::sqrt(zn) > 1e-9 * column_norm;
      const double full = independent ? std::max(0.0, -w[p] / zn) : inf;
      double partial = inf;
      int drop = -1;
      for (int k = 0; k < s; ++k) {
        if (r[k] > 0.0 && lambda[active[k]] / r[k] < partial) {
          partial = lambda[active[k]] / r[k];
          drop = k;
        }
      }
      const double t = std::min(full, partial);
      if (t == inf) {
        if (w[p] >= -loose) {  // met, up to the round-off of a dependent column
          skipped[p] = 1;
          break;
        }
        std::ostringstream why;
        why << "found contact " << p << " impossible to satisfy (its normal velocity " << w[p]
            << " cannot grow: its column depends on the active contacts')";
        fail(why.str());
      }
      for (int k = 0; k < s; ++k) lambda[active[k]] -= t * r[k];
      lambda[p] += t;
      std::fill(skipped.begin(), skipped.end(), 0);
      if (full <= partial) {
        factor.append(r, std::sqrt(zn));
        active.push_back(p);
        is_active[p] = 1;
        update_w();
        break;
      }
      lambda[active[drop]] = 0.0;
      is_active[active[drop]] = 0;
      active.erase(active.begin() + drop);
      factor.remove(drop);
      update_w();
    }
  }
}

}  // namespace fosssim
