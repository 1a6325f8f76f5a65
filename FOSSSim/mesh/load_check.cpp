#include "mesh/load_check.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fosssim {

HangingStretch hanging_stretch(const Mesh& mesh, double k, double load) {
  HangingStretch result;
  const auto pairs = compute_spring_pairs(mesh);
  if (pairs.empty() || mesh.vertices.empty()) return result;
  Eigen::Vector3d low = mesh.vertices.front(), high = low;
  for (const Eigen::Vector3d& x : mesh.vertices) {
    low = low.cwiseMin(x);
    high = high.cwiseMax(x);
  }
  result.size = (high - low).norm();
  double total = 0.0;
  for (const auto& [i, j] : pairs) total += (mesh.vertices[i] - mesh.vertices[j]).norm();
  const double mean = total / static_cast<double>(pairs.size());
  if (!(result.size > 0.0) || !(mean > 0.0)) return result;
  result.springs = std::max<std::int64_t>(1, std::llround(result.size / mean));
  const double n = static_cast<double>(result.springs);
  const double carried = load * n * (n + 1.0) / 2.0;  // N·(springs), the sum over the column
  result.stretch = k > 0.0 ? carried / k : std::numeric_limits<double>::infinity();
  result.stiffness_needed = carried / result.size;
  return result;
}

}  // namespace fosssim
