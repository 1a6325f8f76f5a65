#pragma once
// Grading one scene end to end: load it, run the candidate, check the file, replay it with the
// course's exact criteria (fosssim_grading), explain a failure.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "candidate_run.h"
#include "grading/grader.h"
#include "io/trajectory_file.h"
#include "residual_history.h"
#include "scene_list.h"
#include "scene_result.h"

namespace fosssim {

struct GradingOptions {
  CandidateRunOptions run;
  std::string work_dir;      ///< parent of the per-scene temporary folders; empty: system default
  bool keep_work = false;    ///< keep each scene's folder (with the candidate's out.bin)
  std::string diagnose_dir;  ///< where failing scenes' diagnosis files go; empty: none
};

/// Loads every scene once and keeps a copy of each file it reads in SceneEntry::files (or the
/// loader's message in SceneEntry::load_error), so that grading never depends on files a
/// candidate could have changed. Call it before any candidate runs.
void read_scene_files(std::vector<SceneEntry>& scenes);

/// Grades one scene. Never throws for a problem of the candidate: every such problem becomes
/// the scene's verdict with a reason. A scene file that cannot be loaded is kSceneError.
SceneResult grade_scene(const SceneEntry& entry, const GradingOptions& options);

/// Where a trajectory first holds a NaN or infinite value, from frame `first_frame` on, as
/// "frame 12, particle 3: velocity (nan, 0)"; nothing when every value is finite.
std::optional<std::string> find_non_finite(TrajectoryReader& file, int dim,
                                           std::int64_t first_frame = 0);

/// One line naming the criteria a graded trajectory misses, with the first divergence:
/// "Maximum Position Residual 1e-09 (limit 1e-10); first divergence at step 17, particle 2".
std::string failure_reason(const GradeReport& report);

/// Several lines for a graded failure: describe_failure() of the grading library, then how many
/// steps exceed the maximum limit and which step is worst (from the steps' `history`).
std::string failure_details(const GradeReport& report, const ResidualHistory& history, int dim);

}  // namespace fosssim
