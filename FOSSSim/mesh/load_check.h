#pragma once
// Whether a mesh's springs hold a load on every vertex: a check for generated scenes whose
// stiffness is far too low for their number of vertices (docs/scenes-3d.md, "Stiffness against
// load").

#include <cstdint>

#include "mesh/mesh.h"

namespace fosssim {

/// The stretch of a hanging column of the mesh's springs under `load` newtons on each vertex:
/// a column of n springs of stiffness k hanging from one end stretches by
/// load / k · n (n + 1) / 2 (spring j from the bottom carries j vertices). n is the mesh's size
/// (its bounding-box diagonal) over the mean rest length of its springs, rounded, at least 1.
struct HangingStretch {
  std::int64_t springs = 0;  ///< n, springs in a column across the mesh
  double size = 0.0;         ///< the bounding-box diagonal, m
  double stretch = 0.0;      ///< the column's stretch, m (infinite for k = 0)
  /// The stiffness at which the stretch equals the size, N/m.
  double stiffness_needed = 0.0;
  /// The criterion: the mesh would hang at more than twice its size.
  bool overloaded() const { return stretch > size; }
};

/// The hanging stretch of `mesh` with springs of stiffness `k` (N/m, ≥ 0) under `load` (N) on
/// every vertex. A mesh without springs or of zero size gets a stretch of 0.
HangingStretch hanging_stretch(const Mesh& mesh, double k, double load);

}  // namespace fosssim
