#pragma once
// The quadratic-in-structure pieces that the local/global solver takes implicitly.

#include <Eigen/Core>

namespace fosssim {

/// A Hookean spring between particles i and j, as the local/global solver sees it:
///   U = ½ k (|x_j - x_i| - l0)²,  plus a damping coefficient b (N·s/m).
/// SpringForce::term and SpringSetForce::springs describe themselves this way.
struct SpringTerm {
  int i = 0;
  int j = 0;
  double k = 0.0;   ///< stiffness, N/m
  double l0 = 0.0;  ///< rest length, m
  double b = 0.0;   ///< damping, N·s/m
};

/// A zero-rest-length spring from particle i to a point in space:
///   U = ½ k |x_i - target|².
/// Used for penalty pins and for dragging a particle with the mouse. In 2D only the first two
/// components of target are used.
struct AnchorTerm {
  int i = 0;
  double k = 0.0;  ///< stiffness, N/m
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
};

}  // namespace fosssim
