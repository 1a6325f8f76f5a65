#pragma once
// The regression store: golden digests of FOSSSim's own trajectories for every scene of the
// suite, so that a change of a single bit in any trajectory is noticed.
//
// A manifest folder holds golden.tsv (one line per scene: name, status, frames, bytes, SHA-256
// of the trajectory file) and final/<scene without .xml>.txt (the last frame as text, one line
// per particle), small enough for git; raw trajectories are never stored.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "candidate_run.h"
#include "core/types.h"
#include "scene_list.h"

namespace fosssim {

struct ManifestEntry {
  std::string scene;  ///< SceneEntry::name
  std::string status =
      "ok";  ///< "ok", or why there is no trajectory ("exit-status:3", "crashed", ...)
  std::int64_t frames = 0;
  std::int64_t bytes = 0;
  std::string sha256;       ///< of the trajectory's bytes; empty unless status is "ok"
  std::string final_state;  ///< the last frame as text; empty unless status is "ok"
  bool operator==(const ManifestEntry&) const = default;
};

/// The last frame of a trajectory as text: one line "p  x y [z]  vx vy [vz]" per particle,
/// tab-separated, every number the shortest text that reads back to the same double.
std::string final_state_text(const Vector& q, const Vector& v, int dim);

/// Runs the candidate (FOSSSim) on every scene with `jobs` workers and digests each trajectory.
std::vector<ManifestEntry> compute_manifest(const std::vector<SceneEntry>& scenes,
                                            const CandidateRunOptions& options,
                                            const std::string& work_dir, int jobs);

/// Writes golden.tsv and final/ under `folder` (each file atomically) and deletes final-state
/// files of scenes no longer listed. `regenerate_command` goes into the header comment. Throws
/// Error (kCannotWrite).
void write_manifest(const std::string& folder, const std::vector<ManifestEntry>& entries,
                    const std::string& regenerate_command);

/// Reads a manifest folder; throws Error (kBadInput) naming a missing or malformed file.
std::vector<ManifestEntry> read_manifest(const std::string& folder);

/// Every difference between the manifest and a fresh computation, one message per scene:
/// changed digests (with the first particle whose final state differs), changed status, scenes
/// missing from the manifest and manifest entries whose scene is gone. Empty when they agree.
/// `regenerate_command` is named in the messages about new or intended changes.
std::vector<std::string> compare_manifest(const std::vector<ManifestEntry>& golden,
                                          const std::vector<ManifestEntry>& current,
                                          const std::string& regenerate_command);

}  // namespace fosssim
