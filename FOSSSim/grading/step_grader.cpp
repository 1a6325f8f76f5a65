#include "grading/step_grader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "core/step_error.h"
#include "core/text.h"
#include "grading/collision_grading.h"
#include "scripting/step_hooks.h"

namespace fosssim {

namespace {
StepAdditions grading_additions(const Scene& scene, Cancellation cancellation) {
  StepAdditions additions = scripted_additions(scene);
  additions.cancellation = cancellation;
  return additions;
}
}  // namespace

StepGrader::StepGrader(const Scene& scene, TrajectoryReader& file, const GradingCriteria& criteria,
                       Cancellation cancellation)
    : scene_(&scene), file_(&file), pipeline_(scene.model, grading_additions(scene, cancellation)) {
  pipeline_.set_health_check(false);
  report_.criteria = criteria;
  report_.steps = scene.model.num_steps();
  report_.frames_after_last_step = std::max<std::int64_t>(0, file.num_frames() - (report_.steps + 1));
  if (file.layout() != TrajectoryLayout::kFrames) report_.collisions.emplace();
  file.read_frame(0, file_state_.q, file_state_.v);
}

namespace {

/// The time step the file's first steps show, when they show one: its integrators move
/// positions by h times a velocity (qᵏ⁺¹ = qᵏ + h vᵏ⁺¹, or h vᵏ for explicit Euler), so h is the
/// least-squares fit of qᵏ⁺¹ − qᵏ to either velocity, accepted only when it fits to round-off
/// (1e-9 relative). The first of the file's first 8 steps that moves something decides (a scene
/// that starts at rest moves nothing in explicit Euler's first step). Nothing for a file of one
/// frame, a scene at rest or other motion.
std::optional<double> step_size_of(TrajectoryReader& file) {
  Vector q0, v0, q1, v1;
  file.read_frame(0, q1, v1);
  for (std::int64_t k = 0; k + 1 < file.num_frames() && k < 8; ++k) {
    q0.swap(q1);
    v0.swap(v1);
    file.read_frame(k + 1, q1, v1);
    const Vector dq = q1 - q0;
    const double moved = dq.norm();
    if (!std::isfinite(moved)) return std::nullopt;
    if (moved == 0.0) continue;
    for (const Vector* v : {&v1, &v0}) {
      const double speed2 = v->squaredNorm();
      if (!(speed2 > 0.0) || !std::isfinite(speed2)) continue;
      const double h = dq.dot(*v) / speed2;
      if (h > 0.0 && (dq - h * *v).norm() <= 1e-9 * moved) return h;
    }
    return std::nullopt;
  }
  return std::nullopt;
}

/// "; ..." saying why the file's frame count is not the scene's, as far as the file tells.
std::string why_frames_differ(const Scene& scene, TrajectoryReader& file) {
  const double dt = scene.model.integrator.dt;
  if (const std::optional<double> h = step_size_of(file); h && std::abs(*h - dt) > 1e-6 * dt) {
    char text[32];  // six digits: h is measured to round-off, not exactly
    std::snprintf(text, sizeof(text), "%.6g", *h);
    const std::string file_dt = text;
    return "; its frames are " + file_dt + " s apart (its steps move the particles by " +
           "their velocities times " + file_dt + " s), not the scene's " + to_text(dt) +
           " s: it was made with another time step (grade with --dt " + file_dt +
           ", as it was run)";
  }
  return file.num_frames() < scene.model.num_steps() + 1
             ? "; the file was cut short, or made with another duration"
             : "; the file was made with another duration";
}

}  // namespace

StepGrader StepGrader::open(const Scene& scene, TrajectoryReader& file,
                            const std::optional<GradingCriteria>& criteria,
                            Cancellation cancellation) {
  const std::int64_t steps = scene.model.num_steps();
  const GradingCriteria chosen = criteria ? *criteria : criteria_for(scene);
  const bool extra_frames = file.num_frames() > steps + 1 && chosen.ignores_frames_after_last_step;
  if (file.num_frames() != steps + 1 && !extra_frames) {
    throw Error(ErrorKind::kBadInput, "the trajectory has " + std::to_string(file.num_frames()) +
                                          " frames, but the scene takes " + std::to_string(steps) +
                                          " steps and so needs " + std::to_string(steps + 1) +
                                          " (the initial state and one frame per step)" +
                                          why_frames_differ(scene, file));
  }
  return StepGrader(scene, file, chosen, cancellation);
}

bool StepGrader::finished() const {
  return report_.reference_failure || file_state_.step >= report_.steps;
}

bool StepGrader::grade_next_step() {
  if (finished()) return false;
  const SceneModel& model = scene_->model;
  const std::int64_t k = file_state_.step + 1;
  State reference;
  reference.q = file_state_.q;
  reference.v = file_state_.v;
  reference.step = k - 1;
  reference.time = static_cast<double>(k - 1) * model.integrator.dt;
  try {
    pipeline_.step(reference, &record_);
  } catch (const StepError& error) {
    report_.reference_failure = std::string("the reference integrator failed at ") + error.what();
    constexpr double kUndefined = std::numeric_limits<double>::quiet_NaN();
    StepResidual undefined;
    undefined.step = k;
    undefined.sum_position = undefined.sum_velocity = kUndefined;
    undefined.max_position = undefined.max_velocity = kUndefined;
    accumulate(undefined);
    return false;
  }
  Vector previous_q = std::move(file_state_.q), previous_v = std::move(file_state_.v);
  // The step's sync record precedes its end-of-step record: reading in file order keeps the
  // reader's walk through the records one step long (io/trajectory_file.h).
  // Each record's polynomials are read up to one more than the reference logged: enough to
  // fail a padded record without reading (or keeping) the padding.
  if (report_.collisions && file_->has_sync_records()) {
    file_->read_sync_record(k, sync_record_, static_cast<std::int64_t>(record_.polynomials.size()));
  }
  file_->read_frame(k, file_state_.q, file_state_.v);
  file_state_.step = k;
  file_state_.time = reference.time;
  compare(reference, previous_q, previous_v);
  if (report_.collisions) compare_records(k);
  return true;
}

void StepGrader::compare_records(std::int64_t step) {
  CollisionGrade& grade = *report_.collisions;
  const bool passed_before = grade.passed();
  TrajectoryRecord written;
  file_->read_record(step, written, static_cast<std::int64_t>(record_.polynomials.size()));
  compare_collisions(record_.collisions, written.collisions, grade);
  if (file_->layout() == TrajectoryLayout::kCollisionsAndPolynomials) {
    if (!compare_polynomials(record_.polynomials, written.polynomials, grade.lines)) {
      ++grade.polynomial_failures;
    }
    const TrajectoryRecord& sync = sync_record_;
    const int dim = scene_->model.dim;
    const Vector& q = record_.sync ? record_.sync->q : file_state_.q;
    const Vector& v = record_.sync ? record_.sync->v : file_state_.v;
    double worst = 0.0;
    for (int p = 0; p < scene_->model.num_particles(); ++p) {
      for (double r : {(sync.q.segment(dim * p, dim) - q.segment(dim * p, dim)).norm(),
                       (sync.v.segment(dim * p, dim) - v.segment(dim * p, dim)).norm()}) {
        if (replaces_maximum(r, worst)) worst = r;
      }
    }
    if (replaces_maximum(worst, grade.max_sync_residual)) grade.max_sync_residual = worst;
    const bool state_differs = !below_limit(worst, report_.criteria.maximum_limit);
    if (state_differs) {
      grade.lines.push_back("  Sync record of step " + std::to_string(step) +
                            " differs from FOSSSim's by " + to_text(worst));
    }
    const bool polynomials_differ = !compare_sync_polynomials(
        record_.polynomials,
        record_.sync ? record_.sync->polynomials_logged : record_.polynomials.size(),
        sync.polynomials, step, grade.lines);
    if (state_differs || polynomials_differ) ++grade.sync_failures;
  }
  if (passed_before && !grade.passed()) grade.first_failing_step = step;
  if (grade.lines.size() > CollisionGrade::kMaxLines) {
    grade.lines_dropped +=
        static_cast<std::int64_t>(grade.lines.size() - CollisionGrade::kMaxLines);
    grade.lines.resize(CollisionGrade::kMaxLines);
  }
}

void StepGrader::compare(const State& reference, const Vector& previous_q,
                         const Vector& previous_v) {
  const int dim = scene_->model.dim;
  const int n = scene_->model.num_particles();
  const GradingCriteria& criteria = report_.criteria;
  const Vector& file_q = file_state_.q;
  const Vector& file_v = file_state_.v;
  position_residuals_.assign(n, 0.0);
  velocity_residuals_.assign(n, 0.0);
  StepResidual residual;
  residual.step = file_state_.step;
  for (int p = 0; p < n; ++p) {
    const double rx = (reference.q.segment(dim * p, dim) - file_q.segment(dim * p, dim)).norm();
    const double rv = (reference.v.segment(dim * p, dim) - file_v.segment(dim * p, dim)).norm();
    position_residuals_[p] = rx;
    velocity_residuals_[p] = rv;
    residual.sum_position += rx;
    residual.sum_velocity += rv;
    if (residual.max_position_particle < 0 || replaces_maximum(rx, residual.max_position)) {
      residual.max_position = rx;
      residual.max_position_particle = p;
    }
    if (residual.max_velocity_particle < 0 || replaces_maximum(rv, residual.max_velocity)) {
      residual.max_velocity = rv;
      residual.max_velocity_particle = p;
    }
    if (!report_.first_divergence && !(below_limit(rx, criteria.maximum_limit) &&
                                       below_limit(rv, criteria.maximum_velocity_limit))) {
      FirstDivergence d;
      d.step = residual.step;
      d.particle = p;
      d.position_residual = rx;
      d.velocity_residual = rv;
      d.reference_position = reference.q.segment(dim * p, dim);
      d.reference_velocity = reference.v.segment(dim * p, dim);
      d.file_position = file_q.segment(dim * p, dim);
      d.file_velocity = file_v.segment(dim * p, dim);
      d.previous_position = previous_q.segment(dim * p, dim);
      d.previous_velocity = previous_v.segment(dim * p, dim);
      report_.first_divergence = std::move(d);
    }
  }
  accumulate(residual);
  report_.steps_graded = residual.step;
  report_.last_step = residual;
}

void StepGrader::accumulate(const StepResidual& residual) {
  report_.accumulated_position += residual.sum_position;
  report_.accumulated_velocity += residual.sum_velocity;
  if (replaces_maximum(residual.max_position, report_.max_position))
    report_.max_position = residual.max_position;
  if (replaces_maximum(residual.max_velocity, report_.max_velocity))
    report_.max_velocity = residual.max_velocity;
}

}  // namespace fosssim
