#include "grading/rigid_grader.h"

#include <cmath>
#include <utility>

#include "core/force_set.h"
#include "core/rigid/rigid_bodies.h"
#include "core/step/step_pipeline.h"
#include "io/output_file.h"
#include "scripting/step_hooks.h"

namespace fosssim {

namespace {

constexpr std::array<const char*, kRigidQuantityCount> kQuantityNames = {
    "M", "X(0)", "I", "P", "Lcm", "Lspin", "Tcm", "Tspin", "U"};
constexpr std::array<const char*, 4> kResidualNames = {"X", "Theta", "V", "Omega"};

/// True when `a` is within the limit of `b` (NaN fails).
bool close(double a, double b, double limit) { return std::abs(a - b) < limit; }

class RigidGrader {
 public:
  RigidGrader(const Scene& scene, const std::string& path, const RigidGradingCriteria& criteria,
              std::function<void(const RigidStepResiduals&)> on_step)
      : on_step_(std::move(on_step)),
        model_(scene.model),
        bodies_(model_.num_particles()),
        file_(RigidTrajectoryReader::open(path, bodies_, model_.num_steps())),
        forces_(model_),
        pipeline_(model_, scripted_additions(scene)) {
    pipeline_.set_health_check(false);
    report_.criteria = criteria;
    report_.steps = model_.num_steps();
    report_.quantity_correct.fill(true);
  }

  RigidGradeReport grade() {
    RigidFrame previous = file_.read_frame(0);
    check_start(previous.start);
    State start = rigid_state_from_block(model_, previous.state);
    check_quantities(0, rigid_quantities_block(forces_, start.q, start.v), previous.quantities);
    for (std::int64_t k = 1; k <= report_.steps; ++k) {
      State state = rigid_state_from_block(model_, previous.state);
      state.step = k - 1;
      state.time = static_cast<double>(k - 1) * model_.integrator.dt;
      pipeline_.step(state);
      RigidFrame frame = file_.read_frame(k);
      step_ = RigidStepResiduals{};
      step_.step = k;
      compare_states(k, rigid_state_block(model_, state), frame.state);
      check_quantities(k, rigid_quantities_block(forces_, state.q, state.v), frame.quantities);
      if (on_step_) on_step_(step_);
      previous = std::move(frame);
    }
    return report_;
  }

 private:
  void mismatch(RigidQuantity quantity, std::int64_t frame, int body, double provided,
                double expected) {
    report_.quantity_correct[quantity] = false;
    step_.quantities_correct = false;
    if (!report_.first_divergence) {
      report_.first_divergence = RigidDivergence{frame, body, kQuantityNames[quantity],
                                                 std::abs(provided - expected)};
    }
    if (report_.mismatches.size() < RigidGradeReport::kMaxMismatches) {
      report_.mismatches.push_back({quantity, frame, body, provided, expected});
    }
  }

  void check_start(const Vector& start) {
    const Vector expected = rigid_start_block(model_);
    const double limit = report_.criteria.quantity_limit;
    const int n = bodies_;
    for (int b = 0; b < n; ++b) {
      if (!close(start[b], expected[b], limit)) mismatch(kQuantityM, 0, b, start[b], expected[b]);
      const double dx = std::hypot(start[n + 2 * b] - expected[n + 2 * b],
                                   start[n + 2 * b + 1] - expected[n + 2 * b + 1]);
      if (!(dx < limit)) mismatch(kQuantityX0, 0, b, start[n + 2 * b], expected[n + 2 * b]);
      if (!close(start[3 * n + b], expected[3 * n + b], limit)) {
        mismatch(kQuantityI, 0, b, start[3 * n + b], expected[3 * n + b]);
      }
    }
  }

  void check_quantities(std::int64_t frame, const Vector& expected, const Vector& provided) {
    const double limit = report_.criteria.quantity_limit;
    const int n = bodies_;
    for (int b = 0; b < n; ++b) {
      const double dp =
          std::hypot(provided[2 * b] - expected[2 * b], provided[2 * b + 1] - expected[2 * b + 1]);
      if (!(dp < limit)) mismatch(kQuantityP, frame, b, provided[2 * b], expected[2 * b]);
      for (int q = 0; q < 4; ++q) {
        const int at = (2 + q) * n + b;
        if (!close(provided[at], expected[at], limit)) {
          mismatch(static_cast<RigidQuantity>(kQuantityLcm + q), frame, b, provided[at],
                   expected[at]);
        }
      }
    }
    if (!close(provided[6 * n], expected[6 * n], limit)) {
      mismatch(kQuantityU, frame, -1, provided[6 * n], expected[6 * n]);
    }
  }

  void compare_states(std::int64_t step, const Vector& expected, const Vector& provided) {
    bool failed = false;
    for (int b = 0; b < bodies_; ++b) {
      const Vector d = provided.segment<6>(6 * b) - expected.segment<6>(6 * b);
      const std::array<double, 4> r = {std::hypot(d[0], d[1]), std::abs(d[2]),
                                       std::hypot(d[3], d[4]), std::abs(d[5])};
      for (int k = 0; k < 4; ++k) {
        report_.accumulated[k] += r[k];
        if (std::isnan(r[k]) || r[k] > report_.maximum[k]) report_.maximum[k] = r[k];
        failed = failed || !(r[k] < report_.criteria.maximum_limit);
        step_.sum[k] += r[k];
        const bool larger = std::isnan(r[k]) || r[k] > step_.maximum[k];  // NaN is the largest
        if (step_.body[k] < 0 || (!std::isnan(step_.maximum[k]) && larger)) {
          step_.maximum[k] = r[k];
          step_.body[k] = b;
        }
      }
    }
    if (failed && report_.first_failing_step == 0) report_.first_failing_step = step;
    if (failed && !report_.first_divergence) {  // the kind and body of the largest excess
      int worst = -1;
      for (int k = 0; k < 4; ++k) {
        const double r = step_.maximum[k];
        if (r < report_.criteria.maximum_limit) continue;
        const double w = worst < 0 ? 0.0 : step_.maximum[worst];
        if (worst < 0 || (!std::isnan(w) && (std::isnan(r) || r > w))) worst = k;
      }
      report_.first_divergence =
          RigidDivergence{step, step_.body[worst], kResidualNames[worst], step_.maximum[worst]};
    }
  }

  std::function<void(const RigidStepResiduals&)> on_step_;
  RigidStepResiduals step_;  ///< the step being graded
  const SceneModel& model_;
  int bodies_;
  RigidTrajectoryReader file_;
  ForceSet forces_;
  StepPipeline pipeline_;
  RigidGradeReport report_;
};

}  // namespace

bool RigidGradeReport::quantities_passed() const {
  for (bool correct : quantity_correct) {
    if (!correct) return false;
  }
  return true;
}

bool RigidGradeReport::passed() const {
  for (int r = 0; r < 4; ++r) {
    if (!accumulated_passed(r) || !maximum_passed(r)) return false;
  }
  return quantities_passed();
}

RigidGradeReport grade_rigid_trajectory(
    const Scene& scene, const std::string& path, const RigidGradingCriteria& criteria,
    const std::function<void(const RigidStepResiduals&)>& on_step) {
  return RigidGrader(scene, path, criteria, on_step).grade();
}

const char* rigid_residual_name(RigidResidual residual) { return kResidualNames[residual]; }
const char* rigid_quantity_name(RigidQuantity quantity) { return kQuantityNames[quantity]; }

void print_rigid_grade_report(std::ostream& out, const RigidGradeReport& report) {
  out << "Grading message: Simulation ran to completion.\n";
  for (int q = 0; q < kRigidQuantityCount; ++q) {
    std::string name = kQuantityNames[q];
    name.resize(6, ' ');
    out << name << (q == kQuantityU ? "Computation: " : "Computation(s): ")
        << (report.quantity_correct[q] ? "correct" : "incorrect") << "\n";
  }
  const auto old_precision = out.precision(17);
  for (const QuantityMismatch& m : report.mismatches) {
    out << kQuantityNames[m.quantity] << " not computed correctly";
    if (m.body >= 0) out << " for rigid body " << m.body;
    out << " in frame " << m.frame << "   Provided " << kQuantityNames[m.quantity] << " = "
        << m.provided << "   Expected " << kQuantityNames[m.quantity] << " = " << m.expected
        << "\n";
  }
  out.precision(old_precision);
  for (int r = 0; r < 4; ++r) {
    out << "Accumulated " << kResidualNames[r] << " Residual: " << report.accumulated[r] << " "
        << (report.accumulated_passed(r) ? "pass" : "fail") << "\n";
  }
  for (int r = 0; r < 4; ++r) {
    out << "Maximum " << kResidualNames[r] << " Residual: " << report.maximum[r] << " "
        << (report.maximum_passed(r) ? "pass" : "fail") << "\n";
  }
  if (report.first_failing_step > 0) {
    out << "First step over the limits: " << report.first_failing_step << "\n";
  }
  out << "Overall success: " << (report.passed() ? "Passed." : "Failed.") << "\n";
}

void write_rigid_residual_file(const std::string& path, const RigidGradeReport& report) {
  write_output_file(path, [&report](std::ostream& out) {
    auto line = [&out](bool passed, double value) {
      out << (passed ? 1 : 0) << "   " << value << "\n";
    };
    line(report.accumulated_passed(kResidualX) && report.accumulated_passed(kResidualTheta),
         report.accumulated[kResidualX] + report.accumulated[kResidualTheta]);
    line(report.accumulated_passed(kResidualV) && report.accumulated_passed(kResidualOmega),
         report.accumulated[kResidualV] + report.accumulated[kResidualOmega]);
    line(report.maximum_passed(kResidualX) && report.maximum_passed(kResidualTheta),
         report.maximum[kResidualX] + report.maximum[kResidualTheta]);
    line(report.maximum_passed(kResidualV) && report.maximum_passed(kResidualOmega),
         report.maximum[kResidualV] + report.maximum[kResidualOmega]);
    out << (report.quantities_passed() ? 1 : 0) << "\n";
  });
}

}  // namespace fosssim
