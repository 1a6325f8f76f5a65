#pragma once
// Anderson acceleration of a fixed-point iteration x ← G(x).

#include "core/types.h"

namespace fosssim {

/// Anderson acceleration (type II; Anderson, "Iterative procedures for nonlinear integral
/// equations", JACM 12(4), 1965; as used for local/global solvers by Peng, Deng, Zhang and
/// Liu, "Anderson Acceleration for Geometry Optimization and Physics Simulation", ACM TOG
/// 37(4), 2018). Given an iterate x and its image g = G(x), the next iterate is
///   x' = g - ΔG γ,  γ = argmin ‖f - ΔF γ‖₂,  f = g - x,
/// with ΔF and ΔG the differences of the last `window` residuals f and images g: the affine
/// combination of recent images whose linearised residual is smallest. The small least-squares
/// problem is solved through its Gram matrix by a complete orthogonal decomposition (robust
/// when differences are nearly dependent). Deterministic; no allocation once the window is
/// full, apart from the m×m system.
class AndersonAcceleration {
 public:
  explicit AndersonAcceleration(int window = 5) : window_(window) {}

  /// Forgets the history (a new step, or a rejected iterate).
  void reset() {
    stored_ = 0;
    have_previous_ = false;
  }
  /// The accelerated next iterate from x and g = G(x), both of the same size.
  Vector next(const Vector& x, const Vector& g);

  int window() const { return window_; }

 private:
  int window_;
  int stored_ = 0;  // differences stored so far (the window's columns used are the first ones)
  bool have_previous_ = false;
  Eigen::MatrixXd residual_changes_, image_changes_;  // ΔF and ΔG, n × window
  Vector previous_residual_, previous_image_;
};

}  // namespace fosssim
