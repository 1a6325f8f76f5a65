#pragma once
// The two solvers of contact problems between rigid bodies: ODE's Dantzig LCP solver (as
// Debian packages it in DART) and an exact active-set method (Goldfarb–Idnani's dual method)
// for the same problem written as a quadratic program (docs/rigid-bodies.md, "Contact").

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "core/types.h"

namespace fosssim {

/// The contact problem of one group of contacts: find λ ≥ 0 with w = Aλ + b ≥ 0 and λᵀw = 0,
/// where A = NᵀM⁻¹N (symmetric positive semidefinite; N's columns are the contacts' normal
/// Jacobians over the free bodies' velocities, M the bodies' diagonal masses) and b the
/// contacts' normal velocities before the response. It is the optimality condition of
/// min ½vᵀMv − vᵀMq̇ subject to Nᵀv + (b − Nᵀq̇) ≥ 0, whose unique solution is v = q̇ + M⁻¹Nλ:
/// every solution λ gives the same velocities.
struct ContactProblem {
  Eigen::MatrixXd A;
  Vector b;
  /// M^(−1/2)N: the columns in the kinetic metric (so A = JᵀJ), over the free coordinates of
  /// the group; solve_contact_qp finds its directions from them.
  Eigen::MatrixXd J;
  /// The same columns stored sparse, for large groups: when `J_columns` is not empty,
  /// solve_contact_qp reads them (and `J_rows`) instead of J, which may then be left empty.
  /// Column c lists the nonzero entries (row, value) of J's column c in increasing row order.
  /// A contact touches two bodies, so a column has at most six entries, while J holds
  /// (3 × bodies) × contacts doubles: 3.4 GB for one group of a pile of 10,000 polygons.
  std::vector<std::vector<std::pair<int, double>>> J_columns;
  int J_rows = 0;
};

/// Why a solve did not give a valid answer.
struct ContactSolveResult {
  Vector lambda;
  bool valid = false;   ///< λ ≥ 0, w ≥ −tol and λ_i w_i within tol (check_contact_solution)
  std::string problem;  ///< empty when valid, else what went wrong
};

/// The tolerance of check_contact_solution for a problem: 1e-9 · max(1, max|b|, max|A|·max λ).
double contact_tolerance(const ContactProblem& problem, const Vector& lambda);

/// True when λ solves the problem within contact_tolerance: λ_i ≥ −tol, w_i ≥ −tol and
/// |λ_i w_i| ≤ tol · max(1, λ_i). Otherwise `problem` says which condition failed.
bool check_contact_solution(const ContactProblem& problem, const Vector& lambda,
                            std::string* problem_text = nullptr);

/// True when A is numerically singular (redundant contacts: three collinear contacts of one
/// body, a pile in resting contact): the smallest pivot of its LDLᵀ factorization (with
/// pivoting) is at most 1e-10 of its largest diagonal entry. Dantzig's method may then stop
/// with an error or cycle; the course's program hangs on some of these problems.
bool is_degenerate(const Eigen::MatrixXd& A);

/// A and J are dense: the velocity-projection responses leave A empty (solve_contact_qp does
/// not read it) and J empty with J_columns given.
///
/// ODE's Dantzig solver (dSolveLCP of libdart-external-odelcpsolver, nub = 0, bounds [0, ∞)),
/// then check_contact_solution. The library's "LCP internal error" message is caught, not
/// printed, and makes the answer invalid. Call it on non-degenerate problems only: on singular
/// ones the method has no iteration limit.
/// The WebAssembly build has no build of that library: there it answers with solve_contact_qp
/// (the same solution to round-off on these problems; contact_lcp_dantzig_web.cpp).
ContactSolveResult solve_contact_lcp_dantzig(const ContactProblem& problem);

/// Goldfarb and Idnani's dual active-set method (1983) for the quadratic program above,
/// specialised to a diagonal Hessian M and written in the multipliers λ (x = q̇ + M⁻¹Nλ, so the
/// constraint values are w = Aλ + b). Starting from λ = 0 (the unconstrained minimum v = q̇), it
/// adds the most violated contact (w_p < −tol) and moves λ along the direction that keeps the
/// active contacts at w = 0, dropping an active contact whose multiplier would turn negative;
/// a contact whose column depends on the active ones is reached by drops alone, so redundant
/// contacts are handled. The directions come from the triangular factor R of a QR factorization
/// of the active columns of J (sparse), updated as contacts join (corrected semi-normal
/// equations: a solve and one correction) and leave (Givens rotations), as QuadProg++ updates
/// its factorization: accurate however ill-conditioned A is, O(s²) per change for s active
/// contacts. w is computed from J; A is not used. Exact to round-off and finite; after
/// `max_iterations` additions and drops, or when a contact cannot be met (only possible when b
/// holds fixed bodies' velocities that no free velocity can make up for), throws SolverFailure.
Vector solve_contact_qp(const ContactProblem& problem, int max_iterations);

/// The iteration limit solve_contact_qp is given for a problem of n contacts: 100 + 20 n.
int contact_qp_iteration_limit(int contacts);

}  // namespace fosssim
