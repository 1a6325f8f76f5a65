#include "scene_grading.h"

#include <chrono>
#include <sstream>
#include <stdexcept>

#include "core/limits.h"
#include "core/text.h"
#include "diagnosis.h"
#include "grading/step_grader.h"
#include "io/input_files.h"
#include "io/scene_loader.h"
#include "printable_text.h"
#include "seconds_since.h"

namespace fosssim {

namespace {

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

/// Grades the checked trajectory of a run, each step's residuals into `history`; fills verdict,
/// residuals and explanation. Returns the report when the trajectory could be graded.
std::optional<GradeReport> grade_file(const Scene& scene, const std::string& path,
                                      ResidualHistory& history, SceneResult& result) {
  const int dim = scene.model.dim;
  if (scene.model.rigid_bodies) {  // FOSSSim -i grades these (grading/rigid_grader.h)
    result.verdict = Verdict::kCannotRun;
    result.reason = "the oracle does not grade rigid-body (Theme 3) scenes yet; grade them with "
                    "FOSSSim -i";
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
  ResidualHistory history(result.steps, result.dt, criteria_for(scene),
                          !options.diagnose_dir.empty());
  try {
    WorkFolder work(options.work_dir);
    if (options.keep_work) work.keep();
    CandidateRunOptions run_options = options.run;
    if (entry.timeout_seconds) run_options.timeout_seconds = *entry.timeout_seconds;
    const CandidateRun run = run_candidate(entry.path, expected_bytes, run_options, work,
                                           trajectory_size_is_exact(model), scene_files);
    result.run_seconds = run.seconds;
    result.stderr_tail = run.stderr_tail;
    if (run.problem) {
      result.verdict = *run.problem;
      result.reason = run.reason;
    } else {
      const auto start = std::chrono::steady_clock::now();
      report = grade_file(scene, run.trajectory_path, history, result);
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
      write_diagnosis(options.diagnose_dir, result, report ? &*report : nullptr, history);
    } catch (const Error& error) {
      result.details +=
          std::string("(could not write the diagnosis files: ") + error.what() + ")\n";
    }
  }
  return result;
}

}  // namespace fosssim
