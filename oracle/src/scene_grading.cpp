#include "scene_grading.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <vector>
#include <sstream>
#include <stdexcept>

#include "core/limits.h"
#include "core/text.h"
#include "diagnosis.h"
#include "grading/rigid_grader.h"
#include "grading/step_grader.h"
#include "io/input_files.h"
#include "io/rigid_trajectory.h"
#include "io/scene_loader.h"
#include "printable_text.h"
#include "seconds_since.h"

namespace fosssim {

namespace {

/// The per-step history's limits for a Theme 3 scene: the course's (RigidGradingCriteria), the
/// same for positions (X, θ) and velocities (V, ω).
GradingCriteria rigid_history_criteria() {
  const RigidGradingCriteria rigid;
  GradingCriteria criteria;
  criteria.accumulated_limit = rigid.accumulated_limit;
  criteria.maximum_limit = rigid.maximum_limit;
  criteria.maximum_velocity_limit = rigid.maximum_limit;
  return criteria;
}

std::string vector_text(const Vector& x, int begin, int dim) {
  std::string text = "(";
  for (int c = 0; c < dim; ++c) text += (c ? ", " : "") + to_text(x[begin + c]);
  return text + ")";
}

void take_grade(const GradeReport& report, const ResidualHistory& history, int dim,
                SceneResult& result) {
  result.residuals = Residuals{report.accumulated_position, report.accumulated_velocity,
                               report.max_position, report.max_velocity};
  if (const auto& d = report.first_divergence) {
    result.first_divergence =
        DivergencePoint{d->step, d->particle, d->position_residual, d->velocity_residual};
  }
  result.verdict = report.passed() ? Verdict::kPassed : Verdict::kFailed;
  if (!report.passed()) {
    result.reason = failure_reason(report);
    result.details = failure_details(report, history, dim);
  }
}

/// Where frame `k` first holds a NaN or infinite value, as "frame 12, particle 3: velocity
/// (nan, 0)"; nothing when every value is finite.
std::optional<std::string> non_finite_in_frame(std::int64_t k, const Vector& q, const Vector& v,
                                               int dim) {
  if (q.allFinite() && v.allFinite()) return std::nullopt;
  for (int p = 0; p * dim < q.size(); ++p) {
    const bool bad_q = !q.segment(dim * p, dim).allFinite();
    if (bad_q || !v.segment(dim * p, dim).allFinite()) {
      return "frame " + std::to_string(k) + ", particle " + std::to_string(p) + ": " +
             (bad_q ? "position " + vector_text(q, dim * p, dim)
                    : "velocity " + vector_text(v, dim * p, dim));
    }
  }
  return std::nullopt;
}

/// Replays the file with `grader`, reading every frame once and checking it as it is read, so
/// that the reference integrator never starts from a non-finite frame, and hands each step's
/// residuals to `history`. Returns where the file first holds a non-finite value, if it does.
std::optional<std::string> replay_checking_frames(StepGrader& grader, TrajectoryReader& file,
                                                  int dim, ResidualHistory& history) {
  const auto check_last_frame = [&grader, dim] {
    const State& frame = grader.file_state();
    return non_finite_in_frame(frame.step, frame.q, frame.v, dim);
  };
  if (auto bad = check_last_frame()) return bad;
  while (grader.grade_next_step()) {
    history.add(*grader.report().last_step);
    if (auto bad = check_last_frame()) return bad;
  }
  // A reference failure stops the replay early; a non-finite value after it is still the
  // verdict, so the frames not yet read are checked too.
  return find_non_finite(file, dim, grader.file_state().step + 1);
}

/// Where a Theme 3 trajectory first holds a NaN or infinite value, as "frame 12, body 1:
/// state (X_x X_y θ V_x V_y ω) (nan, 0, 0, 0, 0, 0)"; nothing when every value is finite.
std::optional<std::string> rigid_non_finite(const SceneModel& model, const std::string& path) {
  const int bodies = model.num_particles();
  RigidTrajectoryReader file = RigidTrajectoryReader::open(path, bodies, model.num_steps());
  for (std::int64_t k = 0; k <= model.num_steps(); ++k) {
    const RigidFrame frame = file.read_frame(k);
    for (int b = 0; b < bodies; ++b) {
      if (!frame.state.segment<6>(6 * b).allFinite()) {
        return "frame " + std::to_string(k) + ", body " + std::to_string(b) +
               ": state (X_x, X_y, theta, V_x, V_y, omega) " + vector_text(frame.state, 6 * b, 6);
      }
    }
    if (!frame.start.allFinite()) return "frame 0: the start block (M, X(0), I)";
    if (!frame.quantities.allFinite()) {
      return "frame " + std::to_string(k) + ": the quantities (P, L, T, U)";
    }
  }
  return std::nullopt;
}

/// One line naming what a graded Theme 3 trajectory misses: "Maximum X Residual 1e-07 (limit
/// 1e-08), P computation incorrect (first in frame 3, body 0); first step over the limits 17".
std::string rigid_failure_reason(const RigidGradeReport& report) {
  static constexpr const char* kResiduals[] = {"X", "Theta", "V", "Omega"};
  static constexpr const char* kQuantities[] = {"M", "X(0)", "I", "P", "L_cm",
                                                "L_spin", "T_cm", "T_spin", "U"};
  std::string reason;
  const auto add = [&reason](const std::string& part) {
    reason += (reason.empty() ? "" : ", ") + part;
  };
  for (int r = 0; r < 4; ++r) {
    if (!report.accumulated_passed(r)) {
      add(std::string("Accumulated ") + kResiduals[r] + " Residual " +
          to_text(report.accumulated[r]) + " (limit " +
          to_text(report.criteria.accumulated_limit) + ")");
    }
  }
  for (int r = 0; r < 4; ++r) {
    if (!report.maximum_passed(r)) {
      add(std::string("Maximum ") + kResiduals[r] + " Residual " + to_text(report.maximum[r]) +
          " (limit " + to_text(report.criteria.maximum_limit) + ")");
    }
  }
  for (int q = 0; q < kRigidQuantityCount; ++q) {
    if (report.quantity_correct[q]) continue;
    std::string part = std::string(kQuantities[q]) + " computation incorrect";
    for (const QuantityMismatch& m : report.mismatches) {
      if (m.quantity != q) continue;
      part += " (first in frame " + std::to_string(m.frame) +
              (m.body >= 0 ? ", body " + std::to_string(m.body) : std::string()) + ")";
      break;
    }
    add(part);
  }
  if (report.first_failing_step > 0) {
    reason += "; first step over the limits " + std::to_string(report.first_failing_step);
  }
  return reason;
}

/// The first divergence of a Theme 3 file as a line, and its step's residuals with those of the
/// steps just before it, as a table (the full table of every step is the diagnosis's TSV).
std::string rigid_divergence_details(const RigidGradeReport& report,
                                     const std::vector<RigidStepResiduals>& recent) {
  std::ostringstream out;
  const RigidDivergence& d = *report.first_divergence;
  out << "First divergence: step " << d.step;
  if (d.body >= 0) out << ", body " << d.body;
  out << ", " << d.quantity << " (residual " << to_text(d.residual) << ", limit "
      << to_text(report.criteria.maximum_limit) << ")\n";
  if (recent.empty()) return out.str();
  out << "Residuals per step, largest over bodies (body):\n"
      << "  step  X  Theta  V  Omega  quantities\n";
  for (const RigidStepResiduals& s : recent) {
    out << "  " << s.step;
    for (int k = 0; k < 4; ++k) out << "  " << to_text(s.maximum[k]) << " (" << s.body[k] << ")";
    out << "  " << (s.quantities_correct ? "correct" : "WRONG") << "\n";
  }
  return out.str();
}

/// Grades the checked Theme 3 trajectory of a run with the course's rigid-body criteria
/// (grading/rigid_grader.h), as FOSSSim -i does; fills verdict, residuals and explanation, and
/// hands each step's residuals to `history` (position: the larger of the X and θ residuals,
/// velocity: of V and ω, with their bodies). The residuals are the four figures of the course's
/// residual file: accumulated X + θ and V + ω, maximum X + θ and V + ω. A failing file's
/// details name the first divergence (step, body, quantity) and the residuals of the steps up
/// to it.
std::optional<RigidGradeReport> grade_rigid_file(const Scene& scene, const std::string& path,
                                                 ResidualHistory& history, SceneResult& result) {
  std::optional<RigidGradeReport> report;
  constexpr std::size_t kRecentSteps = 5;
  std::vector<RigidStepResiduals> recent;  // the last kRecentSteps steps up to the divergence
  bool diverged = false;
  const auto on_step = [&](const RigidStepResiduals& s) {
    StepResidual step;
    step.step = s.step;
    step.sum_position = s.sum[kResidualX] + s.sum[kResidualTheta];
    step.sum_velocity = s.sum[kResidualV] + s.sum[kResidualOmega];
    const auto larger = [&s](int a, int b) {
      return std::isnan(s.maximum[b]) || s.maximum[b] > s.maximum[a] ? b : a;
    };
    const int position = larger(kResidualX, kResidualTheta);
    const int velocity = larger(kResidualV, kResidualOmega);
    step.max_position = s.maximum[position];
    step.max_position_particle = s.body[position];
    step.max_velocity = s.maximum[velocity];
    step.max_velocity_particle = s.body[velocity];
    history.add(step);
    if (diverged) return;
    recent.push_back(s);
    if (recent.size() > kRecentSteps) recent.erase(recent.begin());
    bool over = !s.quantities_correct;
    for (int k = 0; k < 4; ++k) {
      over = over || !(s.maximum[k] < RigidGradingCriteria{}.maximum_limit);
    }
    diverged = over;
  };
  try {
    if (auto bad = rigid_non_finite(scene.model, path)) {
      result.verdict = Verdict::kGarbage;
      result.reason = "the trajectory holds a non-finite value: " + *bad;
      return std::nullopt;
    }
    report = grade_rigid_trajectory(scene, path, {}, on_step);
  } catch (const Error& error) {
    result.verdict = Verdict::kShort;
    result.reason = error.what();
    return std::nullopt;
  }
  const auto sum = [](const std::array<double, 4>& r, int a, int b) { return r[a] + r[b]; };
  result.residuals = Residuals{sum(report->accumulated, kResidualX, kResidualTheta),
                               sum(report->accumulated, kResidualV, kResidualOmega),
                               sum(report->maximum, kResidualX, kResidualTheta),
                               sum(report->maximum, kResidualV, kResidualOmega)};
  result.verdict = report->passed() ? Verdict::kPassed : Verdict::kFailed;
  if (!report->passed()) {
    result.reason = rigid_failure_reason(*report);
    std::ostringstream details;
    if (const auto& d = report->first_divergence) {
      details << rigid_divergence_details(*report,
                                          d->step > 0 ? recent : std::vector<RigidStepResiduals>{});
      DivergencePoint point;
      point.step = d->step;
      point.particle = d->body;
      point.rigid_body = true;
      for (const RigidStepResiduals& s : recent) {
        if (s.step != d->step) continue;
        point.position_residual = std::max(s.maximum[kResidualX], s.maximum[kResidualTheta]);
        point.velocity_residual = std::max(s.maximum[kResidualV], s.maximum[kResidualOmega]);
      }
      result.first_divergence = point;
    }
    print_rigid_grade_report(details, *report);
    result.details = details.str();
  }
  return report;
}

/// Grades the checked trajectory of a run, each step's residuals into `history`; fills verdict,
/// residuals and explanation. Returns the report when the trajectory could be graded (a
/// particle scene's; Theme 3 scenes are graded by grade_rigid_file, without one).
std::optional<GradeReport> grade_file(const Scene& scene, const std::string& path,
                                      ResidualHistory& history, SceneResult& result,
                                      std::optional<RigidGradeReport>& rigid_report) {
  const int dim = scene.model.dim;
  if (scene.model.rigid_bodies) {
    rigid_report = grade_rigid_file(scene, path, history, result);
    return std::nullopt;
  }
  std::optional<TrajectoryReader> file;
  try {
    file.emplace(open_trajectory(path, scene.model));
  } catch (const Error& error) {
    result.verdict = Verdict::kNoOutput;
    result.reason = error.what();
    return std::nullopt;
  }
  std::optional<StepGrader> grader;
  std::string cannot_grade;
  try {
    grader.emplace(StepGrader::open(scene, *file));
  } catch (const Error& error) {
    cannot_grade = error.what();
  }
  auto bad =
      grader ? replay_checking_frames(*grader, *file, dim, history) : find_non_finite(*file, dim);
  if (bad) {
    result.verdict = Verdict::kGarbage;
    result.reason = "the trajectory holds a non-finite value: " + *bad;
    return std::nullopt;
  }
  if (!grader) {
    result.verdict = Verdict::kShort;
    result.reason = cannot_grade;
    return std::nullopt;
  }
  take_grade(grader->report(), history, dim, result);
  if (const std::int64_t extra = grader->report().frames_after_last_step; extra > 0) {
    result.details += "The trajectory holds " + std::to_string(extra) +
                      " frames after the scene's last step; they were not read (the course's "
                      "Theme 4 program ignores them).\n";
  }
  return grader->report();
}

}  // namespace

std::optional<std::string> find_non_finite(TrajectoryReader& file, int dim,
                                           std::int64_t first_frame) {
  Vector q, v;
  for (std::int64_t k = first_frame; k < file.num_frames(); ++k) {
    file.read_frame(k, q, v);
    if (auto bad = non_finite_in_frame(k, q, v, dim)) return bad;
  }
  return std::nullopt;
}

std::string failure_reason(const GradeReport& report) {
  if (report.reference_failure) return *report.reference_failure;
  std::string reason;
  for (const Criterion& c : criteria_of(report)) {
    if (c.passed) continue;
    reason += (reason.empty() ? "" : ", ") + std::string(c.name) + " " + to_text(c.value) +
              " (limit " + to_text(c.limit) + ")";
  }
  if (report.collisions && !report.collisions->passed()) {
    const CollisionGrade& c = *report.collisions;
    reason += (reason.empty() ? "" : ", ") + std::string("Collisions from step ") +
              std::to_string(c.first_failing_step) + " (" + std::to_string(c.missed) + " missed, " +
              std::to_string(c.superfluous) + " superfluous, " + std::to_string(c.wrong_normal) +
              " wrong normals, " + std::to_string(c.polynomial_failures) +
              " steps with wrong polynomials, " + std::to_string(c.sync_failures) +
              " wrong sync records)";
  }
  if (const auto& d = report.first_divergence) {
    reason += "; first divergence at step " + std::to_string(d->step) + ", particle " +
              std::to_string(d->particle);
  }
  return reason;
}

std::string failure_details(const GradeReport& report, const ResidualHistory& history, int dim) {
  std::ostringstream out;
  out << describe_failure(report, dim);
  if (history.steps_over_limit() > 0) {
    out << "Steps at or above a maximum limit: " << history.steps_over_limit() << " of "
        << report.steps << " (from step " << history.first_step_over_limit() << " to step "
        << history.last_step_over_limit() << ")\n";
  }
  if (history.worst_step() > 0) {
    out << "Largest single residual: " << to_text(history.worst_residual()) << " at step "
        << history.worst_step() << "\n";
  }
  return out.str();
}

void read_scene_files(std::vector<SceneEntry>& scenes) {
  for (SceneEntry& entry : scenes) {
    entry.files.clear();
    entry.load_error.reset();
    try {
      InputFiles files;
      load_scene_file(entry.path, files);
      InputFiles copy;  // the same size limits as the loader's
      for (const std::string& path : files.paths()) {
        if (!entry.files.count(path)) entry.files.emplace(path, copy.read(path));
      }
    } catch (const Error& error) {
      entry.files.clear();
      entry.load_error = error.what();
    }
  }
}

SceneResult grade_scene(const SceneEntry& entry, const GradingOptions& options) {
  SceneResult result;
  result.name = entry.name;
  result.extra_credit = entry.extra_credit;
  std::optional<Scene> loaded;
  std::vector<std::string> scene_files;
  try {
    if (entry.load_error) throw Error(ErrorKind::kBadInput, *entry.load_error);
    InputFiles files = entry.files.empty() ? InputFiles() : InputFiles::in_memory(entry.files);
    loaded.emplace(load_scene_file(entry.path, files));
    scene_files = files.paths();
    check_step_count(loaded->model, Limits{});
  } catch (const Error& error) {
    result.verdict = Verdict::kSceneError;
    result.details = printable_text(error.what());
    result.reason = first_line(result.details);
    return result;
  }
  const Scene& scene = *loaded;
  const SceneModel& model = scene.model;
  result.integrator = model.integrator.method->name;
  result.dim = model.dim;
  result.particles = model.num_particles();
  result.steps = model.num_steps();
  result.dt = model.integrator.dt;
  const std::int64_t expected_bytes = expected_trajectory_bytes(model);

  std::optional<GradeReport> report;
  std::optional<RigidGradeReport> rigid_report;
  ResidualHistory history(result.steps, result.dt,
                          model.rigid_bodies ? rigid_history_criteria() : criteria_for(scene),
                          !options.diagnose_dir.empty());
  try {
    WorkFolder work(options.work_dir);
    if (options.keep_work) work.keep();
    CandidateRunOptions run_options = options.run;
    if (entry.timeout_seconds) run_options.timeout_seconds = *entry.timeout_seconds;
    const CandidateRun run = run_candidate(entry.path, expected_bytes, run_options, work,
                                           trajectory_size_rule(model, criteria_for(scene)),
                                           scene_files);
    result.run_seconds = run.seconds;
    result.stderr_tail = run.stderr_tail;
    if (run.problem) {
      result.verdict = *run.problem;
      result.reason = run.reason;
    } else {
      const auto start = std::chrono::steady_clock::now();
      report = grade_file(scene, run.trajectory_path, history, result, rigid_report);
      result.grade_seconds = seconds_since(start);
    }
    if (options.keep_work)
      result.details += "The candidate's folder was kept: " + work.path() + "\n";
  } catch (const std::exception& error) {
    result.verdict = Verdict::kCannotRun;
    result.reason = std::string("the oracle could not run this scene: ") + error.what();
  }
  if (!result.passed() && !options.diagnose_dir.empty()) {
    try {
      if (rigid_report) {
        write_rigid_diagnosis(options.diagnose_dir, result, *rigid_report, history);
      } else {
        write_diagnosis(options.diagnose_dir, result, report ? &*report : nullptr, history);
      }
    } catch (const Error& error) {
      result.details +=
          std::string("(could not write the diagnosis files: ") + error.what() + ")\n";
    }
  }
  return result;
}

}  // namespace fosssim
