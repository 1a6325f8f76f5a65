#include "grading/grader.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/integrators/integrator.h"
#include "core/step_error.h"

namespace fosssim {

namespace {

bool below(double value, double limit) { return value < limit; }  // false for NaN

struct Criterion {
  const char* name;
  double value;
  bool passed;
};

std::vector<Criterion> criteria_of(const GradeReport& r) {
  return {{"Accumulated Position Residual", r.accumulated_position, r.accumulated_position_passed()},
          {"Accumulated Velocity Residual", r.accumulated_velocity, r.accumulated_velocity_passed()},
          {"Maximum Position Residual", r.max_position, r.max_position_passed()},
          {"Maximum Velocity Residual", r.max_velocity, r.max_velocity_passed()}};
}

/// True when candidate should replace current as a maximum; a NaN beats every number, so that a
/// NaN residual cannot hide behind a finite one.
bool exceeds(double candidate, double current) {
  return std::isnan(candidate) ? !std::isnan(current) : candidate > current;
}

}  // namespace

bool GradeReport::accumulated_position_passed() const {
  return below(accumulated_position, criteria.accumulated_limit);
}
bool GradeReport::accumulated_velocity_passed() const {
  return below(accumulated_velocity, criteria.accumulated_limit);
}
bool GradeReport::max_position_passed() const { return below(max_position, criteria.maximum_limit); }
bool GradeReport::max_velocity_passed() const { return below(max_velocity, criteria.maximum_limit); }
bool GradeReport::passed() const {
  return !reference_failure && accumulated_position_passed() && accumulated_velocity_passed() &&
         max_position_passed() && max_velocity_passed();
}

Expected<GradeReport, std::string> grade_trajectory(const Scene& scene, TrajectoryReader& file,
                                                    const GradingCriteria& criteria,
                                                    const GradingProgress& progress) {
  const SceneModel& model = scene.model;
  const std::int64_t steps = model.num_steps();
  if (file.num_frames() != steps + 1) {
    return "the trajectory has " + std::to_string(file.num_frames()) + " frames, but the scene takes " +
           std::to_string(steps) + " steps and so needs " + std::to_string(steps + 1) +
           " (the initial state and one frame per step)" +
           (file.num_frames() < steps + 1 ? "; the file was cut short" : "");
  }
  GradeReport report;
  report.criteria = criteria;
  report.steps = steps;
  report.per_step.reserve(static_cast<std::size_t>(steps));

  const int dim = model.dim;
  auto integrator = make_integrator(model);
  State state;
  Vector previous_q, previous_v, file_q, file_v;
  file.read_frame(0, file_q, file_v);
  for (std::int64_t k = 1; k <= steps; ++k) {
    previous_q.swap(file_q);
    previous_v.swap(file_v);
    state.q = previous_q;
    state.v = previous_v;
    state.step = k - 1;
    state.time = static_cast<double>(k - 1) * model.integrator.dt;
    try {
      integrator->step(model, state);
    } catch (const StepError& error) {
      report.reference_failure = std::string("the reference integrator failed at ") + error.what();
      break;
    }
    file.read_frame(k, file_q, file_v);

    StepResidual residual;
    residual.step = k;
    for (int p = 0; p < model.num_particles(); ++p) {
      const double rx = (state.q.segment(dim * p, dim) - file_q.segment(dim * p, dim)).norm();
      const double rv = (state.v.segment(dim * p, dim) - file_v.segment(dim * p, dim)).norm();
      residual.sum_position += rx;
      residual.sum_velocity += rv;
      if (residual.max_position_particle < 0 || exceeds(rx, residual.max_position)) {
        residual.max_position = rx;
        residual.max_position_particle = p;
      }
      if (residual.max_velocity_particle < 0 || exceeds(rv, residual.max_velocity)) {
        residual.max_velocity = rv;
        residual.max_velocity_particle = p;
      }
      if (!report.first_divergence &&
          !(below(rx, criteria.maximum_limit) && below(rv, criteria.maximum_limit))) {
        FirstDivergence d;
        d.step = k;
        d.particle = p;
        d.position_residual = rx;
        d.velocity_residual = rv;
        d.reference_position = state.q.segment(dim * p, dim);
        d.reference_velocity = state.v.segment(dim * p, dim);
        d.file_position = file_q.segment(dim * p, dim);
        d.file_velocity = file_v.segment(dim * p, dim);
        d.previous_position = previous_q.segment(dim * p, dim);
        d.previous_velocity = previous_v.segment(dim * p, dim);
        report.first_divergence = std::move(d);
      }
    }
    report.accumulated_position += residual.sum_position;
    report.accumulated_velocity += residual.sum_velocity;
    if (exceeds(residual.max_position, report.max_position)) report.max_position = residual.max_position;
    if (exceeds(residual.max_velocity, report.max_velocity)) report.max_velocity = residual.max_velocity;
    report.per_step.push_back(residual);
    if (progress) progress(k, steps);
  }
  return report;
}

void print_grade_report(std::ostream& out, const GradeReport& report) {
  for (const Criterion& c : criteria_of(report)) {
    out << c.name << ": " << c.value << "   " << (c.passed ? "Passed." : "Failed.") << "\n";
  }
  out << "Overall success: " << (report.passed() ? "Passed." : "Failed.") << std::endl;
}

void write_residual_file(const std::string& path, const GradeReport& report) {
  const std::string temporary = path + ".partial";
  {
    std::ofstream out(temporary);
    for (const Criterion& c : criteria_of(report)) {
      out << (c.passed ? 1 : 0) << "   " << c.value << "\n";
    }
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + temporary);
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) throw std::runtime_error("cannot rename " + temporary + " to " + path + ": " + error.message());
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
  if (const auto& d = report.first_divergence) {
    out << "First divergence at step " << d->step << ", particle "
        << d->particle << ": position residual " << d->position_residual
        << ", velocity residual " << d->velocity_residual << "\n"
        << "  start (file frame " << d->step - 1 << "):  x = " << vec(d->previous_position)
        << "  v = " << vec(d->previous_velocity) << "\n"
        << "  reference step:          x = " << vec(d->reference_position)
        << "  v = " << vec(d->reference_velocity) << "\n"
        << "  file frame " << d->step << ":           x = " << vec(d->file_position)
        << "  v = " << vec(d->file_velocity) << "\n";
  } else if (!report.reference_failure) {
    out << "No single step exceeds the maximum limit, but the accumulated residual does.\n";
  }
  return out.str();
}

}  // namespace fosssim
