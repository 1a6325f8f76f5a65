#pragma once
// A whole grading run (or one shard of it): what every report is written from.

#include <string>
#include <vector>

#include "scene_list.h"
#include "scene_result.h"

namespace fosssim {

/// One scene of the full, unsharded list: enough to check that merged shards cover it.
struct SceneListing {
  std::string name;
  bool extra_credit = false;
  bool operator==(const SceneListing&) const = default;
};

struct GradingRun {
  std::string candidate;             ///< as given on the command line
  Shard shard;                       ///< 1/1 for a whole run and for merged shards
  std::vector<SceneListing> scenes;  ///< every scene of the whole run, in order
  std::vector<SceneResult> results;  ///< the graded scenes of this shard, in the same order
  double wall_seconds = 0.0;         ///< a merge adds up its shards' wall times
  /// False when the candidates ran without the sandbox (--no-sandbox; for a merge, in any
  /// shard): every report then says so.
  bool sandboxed = true;
};

/// Counts of scenes and passes, regular and extra credit apart.
struct Tally {
  int regular = 0, regular_passed = 0;
  int extra = 0, extra_passed = 0;
  bool all_passed() const { return regular_passed == regular && extra_passed == extra; }
};

Tally tally(const std::vector<SceneResult>& results);

/// The sentence every report carries when the candidates ran without the sandbox.
inline constexpr const char* kNoSandboxNote = "Candidates ran without a sandbox (--no-sandbox).";

/// The listing of a scene list.
std::vector<SceneListing> listing_of(const std::vector<SceneEntry>& scenes);

}  // namespace fosssim
