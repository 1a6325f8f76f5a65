#include "grading/grader.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "grading/step_grader.h"
#include "io/output_file.h"

namespace fosssim {

std::array<Criterion, 4> criteria_of(const GradeReport& r) {
  const GradingCriteria& c = r.criteria;
  return {
      {{"Accumulated Position Residual", r.accumulated_position, c.accumulated_limit,
        r.accumulated_position_passed()},
       {"Accumulated Velocity Residual", r.accumulated_velocity, c.accumulated_limit,
        r.accumulated_velocity_passed()},
       {"Maximum Position Residual", r.max_position, c.maximum_limit, r.max_position_passed()},
       {"Maximum Velocity Residual", r.max_velocity, c.maximum_velocity_limit,
        r.max_velocity_passed()}}};
}

bool GradeReport::accumulated_position_passed() const {
  return below_limit(accumulated_position, criteria.accumulated_limit);
}
bool GradeReport::accumulated_velocity_passed() const {
  return below_limit(accumulated_velocity, criteria.accumulated_limit);
}
bool GradeReport::max_position_passed() const {
  return below_limit(max_position, criteria.maximum_limit);
}
bool GradeReport::max_velocity_passed() const {
  return below_limit(max_velocity, criteria.maximum_velocity_limit);
}
bool GradeReport::passed() const {
  return !reference_failure && accumulated_position_passed() && accumulated_velocity_passed() &&
         max_position_passed() && max_velocity_passed() && (!collisions || collisions->passed());
}

GradingCriteria criteria_for(const Scene& scene) {
  return scene.grading_theme == 4 ? kTheme4Criteria : GradingCriteria{};
}

GradeReport grade_trajectory(const Scene& scene, TrajectoryReader& file,
                             const std::optional<GradingCriteria>& criteria,
                             const GradingProgress& progress) {
  StepGrader grader = StepGrader::open(scene, file, criteria);
  while (grader.grade_next_step()) {
    if (progress) progress(grader.steps_graded(), grader.report().steps);
  }
  return grader.report();
}

void print_grade_report(std::ostream& out, const GradeReport& report) {
  if (report.collisions) {
    for (const std::string& line : report.collisions->lines) out << line << "\n";
    if (report.collisions->lines_dropped > 0) {
      out << "  (" << report.collisions->lines_dropped << " more lines not kept)\n";
    }
  }
  for (const Criterion& c : criteria_of(report)) {
    out << c.name << ": " << c.value << "   " << (c.passed ? "Passed." : "Failed.") << "\n";
  }
  if (report.collisions) {
    out << "Collisions Passed: " << (report.collisions->passed() ? "Yes." : "No.") << "\n";
  }
  if (report.criteria.reports_hybrid_collisions) out << "Hybrid Collisions Passed: Yes.\n";
  out << "Overall success: " << (report.passed() ? "Passed." : "Failed.") << std::endl;
}

void write_residual_file(const std::string& path, const GradeReport& report) {
  write_output_file(path, [&report](std::ostream& out) {
    for (const Criterion& c : criteria_of(report)) {
      out << (c.passed ? 1 : 0) << "   " << c.value << "\n";
    }
    if (report.criteria.reports_hybrid_collisions) out << "1\n";
  });
}

std::string describe_failure(const GradeReport& report, int dim) {
  if (report.passed()) return "";
  std::ostringstream out;
  out.precision(17);
  const auto vec = [dim](const Vector& x) {
    std::ostringstream s;
    s.precision(17);
    s << "(";
    for (int c = 0; c < dim; ++c) s << (c ? ", " : "") << x[c];
    s << ")";
    return s.str();
  };
  if (report.reference_failure) out << *report.reference_failure << "\n";
  if (report.collisions && !report.collisions->passed()) {
    const CollisionGrade& c = *report.collisions;
    out << "Collisions failed from step " << c.first_failing_step << ": " << c.missed << " missed, "
        << c.superfluous << " superfluous, " << c.wrong_normal << " with a wrong normal; "
        << c.polynomial_failures << " step(s) with wrong polynomials; " << c.sync_failures
        << " sync record(s) differing from FOSSSim's (largest residual " << c.max_sync_residual
        << ")\n";
    const std::size_t shown = std::min<std::size_t>(c.lines.size(), 10);
    for (std::size_t k = 0; k < shown; ++k) out << c.lines[k] << "\n";
    const std::int64_t more = static_cast<std::int64_t>(c.lines.size() - shown) + c.lines_dropped;
    if (more > 0) out << "  (" << more << " more lines)\n";
  }
  if (const auto& d = report.first_divergence) {
    out << "First divergence at step " << d->step << ", particle " << d->particle
        << ": position residual " << d->position_residual << ", velocity residual "
        << d->velocity_residual << "\n"
        << "  start (file frame " << d->step - 1 << "):  x = " << vec(d->previous_position)
        << "  v = " << vec(d->previous_velocity) << "\n"
        << "  reference step:          x = " << vec(d->reference_position)
        << "  v = " << vec(d->reference_velocity) << "\n"
        << "  file frame " << d->step << ":           x = " << vec(d->file_position)
        << "  v = " << vec(d->file_velocity) << "\n";
  } else if (!report.accumulated_position_passed() || !report.accumulated_velocity_passed()) {
    out << "No single step exceeds the maximum limit, but the accumulated residual does.\n";
  }
  return out.str();
}

}  // namespace fosssim
