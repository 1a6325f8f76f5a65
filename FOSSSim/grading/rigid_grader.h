#pragma once
// Grading of Theme 3 (rigid-body) trajectories, with the course's criteria
// (docs/rigid-bodies.md, 'Grading').

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "core/scene.h"
#include "io/rigid_trajectory.h"

namespace fosssim {

/// The Theme 3 program's limits: every single residual and every quantity difference below
/// 1e-8, every sum of residuals below 1e-6 (strictly).
struct RigidGradingCriteria {
  double maximum_limit = 1e-8;
  double accumulated_limit = 1e-6;
  double quantity_limit = 1e-8;
};

/// The residual kinds, in the course's report order.
enum RigidResidual { kResidualX, kResidualTheta, kResidualV, kResidualOmega };

/// The derived quantities the grader checks, in the course's report order.
enum RigidQuantity {
  kQuantityM,
  kQuantityX0,
  kQuantityI,
  kQuantityP,
  kQuantityLcm,
  kQuantityLspin,
  kQuantityTcm,
  kQuantityTspin,
  kQuantityU
};
inline constexpr int kRigidQuantityCount = 9;

/// A difference found in a checked quantity (the first few are kept for the report).
struct QuantityMismatch {
  RigidQuantity quantity;
  std::int64_t frame = 0;
  int body = -1;                          ///< −1 for U
  double provided = 0.0, expected = 0.0;  ///< the first component for P and X(0)
};

/// One graded step's residuals, per kind (X, θ, V, ω): the largest over bodies with its body,
/// and the sum over bodies; and whether frame k's derived quantities were all correct.
struct RigidStepResiduals {
  std::int64_t step = 0;
  std::array<double, 4> maximum{};
  std::array<int, 4> body{-1, -1, -1, -1};
  std::array<double, 4> sum{};
  bool quantities_correct = true;
};

/// Where a Theme 3 file first goes wrong: the first step (frame) where a residual reaches the
/// maximum limit or a derived quantity differs, which body (−1 for U), which quantity ("X",
/// "Theta", "V", "Omega", or a derived one: "M", "X(0)", "I" at frame 0, "P", "Lcm", "Lspin",
/// "Tcm", "Tspin", "U"), and the residual (|provided − expected| of a derived quantity's first
/// component). Residuals come before derived quantities within a step.
struct RigidDivergence {
  std::int64_t step = 0;
  int body = -1;
  std::string quantity;
  double residual = 0.0;
};

/// The name of a residual kind ("X", "Theta", "V", "Omega") and of a derived quantity ("M",
/// "X(0)", "I", "P", "Lcm", "Lspin", "Tcm", "Tspin", "U").
const char* rigid_residual_name(RigidResidual residual);
const char* rigid_quantity_name(RigidQuantity quantity);

struct RigidGradeReport {
  RigidGradingCriteria criteria;
  std::int64_t steps = 0;
  std::array<double, 4> accumulated{};  ///< ΣX, Σθ, ΣV, Σω over bodies and steps
  std::array<double, 4> maximum{};
  std::array<bool, kRigidQuantityCount> quantity_correct{};  ///< per quantity, over every frame
  static constexpr std::size_t kMaxMismatches = 20;
  std::vector<QuantityMismatch> mismatches;  ///< the first kMaxMismatches found
  std::int64_t first_failing_step = 0;       ///< 0 when every residual is within limits
  /// The first residual over the limit or wrong derived quantity, if any.
  std::optional<RigidDivergence> first_divergence;

  bool quantities_passed() const;
  bool accumulated_passed(int r) const { return accumulated[r] < criteria.accumulated_limit; }
  bool maximum_passed(int r) const { return maximum[r] < criteria.maximum_limit; }
  bool passed() const;
};

/// Grades the Theme 3 trajectory `path` against `scene` (a rigid-body scene): checks the start
/// block against the scene's mass properties, frame 0's quantities against its state, then for
/// every step k restarts from frame k−1, takes one step with the scene's integrator and compares
/// frame k's state and quantities. Stricter than the course's grader where it is weak: the file
/// must hold exactly the scene's bytes (Error kBadInput otherwise), and a fixed body's velocity
/// must stay the one its scene declares. `on_step`, if given, receives every graded step's
/// residuals as they come (the oracle's per-step table and plot).
RigidGradeReport grade_rigid_trajectory(
    const Scene& scene, const std::string& path, const RigidGradingCriteria& criteria = {},
    const std::function<void(const RigidStepResiduals&)>& on_step = {});

/// Prints the course's report: the quantity lines, mismatches, the eight residual lines and
/// the overall verdict.
void print_rigid_grade_report(std::ostream& out, const RigidGradeReport& report);

/// Writes residual.txt as the course does: four "<1|0>   <value>" lines (accumulated X+θ,
/// accumulated V+ω, maximum X+θ, maximum V+ω) and a fifth holding the quantity checks' flag.
void write_rigid_residual_file(const std::string& path, const RigidGradeReport& report);

}  // namespace fosssim
