#pragma once
// An independent full-matrix finite-difference check of a force's derivatives, the library's own
// check (core/analysis/derivative_check.h) run beside it, and the table of the largest
// finite-difference errors that the derivative tests print for the record.

#include <cmath>
#include <string>

#include "core/force.h"
#include "core/types.h"

namespace fosssim::testing {

/// Result of comparing an analytic derivative with its finite-difference estimate.
struct MatrixComparison {
  double absolute_error = 0.0;  ///< ‖analytic - numeric‖_F
  double scale = 0.0;           ///< max(‖analytic‖_F, ‖numeric‖_F)
  double noise_floor = 0.0;     ///< round-off level of the numeric side, absolute
  /// Passes when the error is within tolerance·scale + noise_floor.
  bool passes(double tolerance) const {
    return absolute_error <= tolerance * scale + noise_floor;  // false for NaN
  }
  double relative_error() const {
    return scale > 0.0 ? absolute_error / scale : (absolute_error > 0.0 ? INFINITY : 0.0);
  }
};

/// Compares the dense hessX (in_velocity = false) or hessV (true) of a force with the matrix
/// whose column k is the central difference (g(x + t e_k) - g(x - t e_k)) / (actual step),
/// where g is the gradient and the actual step is the floating-point difference of the two
/// perturbed coordinates (so rounding of x ± t does not enter the quotient). Normwise: no floor.
MatrixComparison compare_hessian_full(const Force& force, const Vector& q, const Vector& v,
                                      const Vector& mass, bool in_velocity, double t);

/// Compares the gradient at v = 0 with Richardson-extrapolated central differences of the
/// energy, (4 D(t/2) - D(t)) / 3, along every coordinate, with the same actual-step rule. The
/// energy is only known to round-off, ε_machine (|U| + ‖hessX‖ |q|_∞ t) per value, so the noise
/// floor is 100 ε_machine √n (|U| / t + ‖hessX‖_F |q|_∞).
MatrixComparison compare_gradient_full(const Force& force, const Vector& q, const Vector& mass,
                                       double t);

/// The shortest distance between two distinct particles of q (infinity for one particle).
double shortest_distance(const Vector& q, int dim);

// ---------------------------------------------------------------------------------------------
// The record of finite-difference errors

/// The configuration name of equilibria, where gradE is round-off: checked, not recorded.
inline const std::string kAtRest = "at-rest";

/// What a derivative test checks, for messages and the record.
struct DerivativeCase {
  std::string force;          ///< "spring", "spring(b>0)", "gravitation", ...
  std::string configuration;  ///< "random" or "near-degenerate"
  std::string detail;         ///< seed, lengths: for failure messages
};

/// Records a relative error per (force, dimension, configuration, derivative, checker), keeps
/// the largest with the case that produced it, and prints them all when the test program ends
/// (run the test binary directly to see the whole table; under ctest each test prints its rows).
/// At-rest configurations are checked but not recorded.
void record_fd_error(const DerivativeCase& what, int dim, const std::string& derivative,
                     const std::string& checker, double error);

/// The length scale L of a configuration: the shortest distance between two particles, at
/// most 1 (1 when particles coincide). Finite-difference steps are multiples of it.
double configuration_length(const Vector& q, int dim);

/// Steps of the full-matrix check relative to L. Hessians (plain central differences of
/// gradE): truncation (t/L)² = 1e-10, round-off about 1e5 ε_machine relative. Gradients
/// (Richardson-extrapolated differences of U): truncation k (t/L)⁴ L = 1e-16 k L, below the
/// round-off floor even where gradE vanishes.
constexpr double kHessianStep = 1e-5;
constexpr double kGradientStep = 1e-4;

/// Tolerance of the full-matrix check: 1e-7 leaves three orders of margin above the errors
/// that the steps above leave, and still catches a Hessian that is off by one part in 10⁴.
constexpr double kFullMatrixTolerance = 1e-7;

/// Runs the library's checker (core/analysis/derivative_check.h) with the step it suggests for
/// this configuration and the independent full-matrix check on one force, asserts both pass,
/// and records the errors. Returns false if any check failed.
bool check_force_everywhere(const Force& force, int dim, const Vector& q, const Vector& v,
                            const Vector& mass, const DerivativeCase& what);

}  // namespace fosssim::testing
