#pragma once
// Which scenes a run grades: the scene files under the given folders, named so that the name is
// the same on every machine, sorted, and split into shards.

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace fosssim {

/// One scene to grade.
struct SceneEntry {
  SceneEntry() = default;
  SceneEntry(std::string name_, std::string path_, bool extra_credit_ = false)
      : name(std::move(name_)), path(std::move(path_)), extra_credit(extra_credit_) {}

  /// The folder's own name followed by the path inside it, with '/' separators:
  /// "assets/t1m1/springs_single.xml". Independent of where the folder lies, so that shards run
  /// on different machines name scenes alike.
  std::string name;
  std::string path;           ///< where the file is on this machine (absolute)
  bool extra_credit = false;  ///< found under an --extra-credit folder
  /// The oracle's own copy of every file the scene reads (the scene file and its meshes), by
  /// the path the loader asks for, taken by read_scene_files() before any candidate runs;
  /// grading loads the scene from it, whatever happens to the files afterwards. Empty: the
  /// scene is read from disk when it is graded.
  std::map<std::string, std::string> files;
  /// Set when read_scene_files() could not load the scene: the loader's message.
  std::optional<std::string> load_error;
  /// This scene's wall-time limit in seconds, when `grade --timeouts` names it; otherwise the
  /// run's --timeout applies.
  std::optional<double> timeout_seconds;
  /// The report group: the name of the folder that holds the file ("assets/t1m1").
  std::string suite() const;
};

/// Finds every "*.xml" file under `folders` (searched recursively; a file argument is taken as
/// one scene) and under `extra_credit_folders`, sorted by name with regular scenes first.
/// Throws Error (kBadInput) when a folder does not exist (unless `missing_folders_are_empty`)
/// or when two scenes would get the same name.
std::vector<SceneEntry> discover_scenes(const std::vector<std::string>& folders,
                                        const std::vector<std::string>& extra_credit_folders,
                                        bool missing_folders_are_empty = false);

/// Shard K of N (1 <= K <= N): the scenes at positions i (0-based, in the sorted list) with
/// i mod N == K - 1. Round robin spreads long scenes of one folder over all shards.
struct Shard {
  int index = 1;
  int count = 1;
  /// The shard of `count` that holds the scene at `position`.
  static Shard holding(std::size_t position, int count) {
    return {static_cast<int>(position % static_cast<std::size_t>(count)) + 1, count};
  }
  bool contains(std::size_t position) const { return holding(position, count).index == index; }
};

/// Parses "K/N"; throws Error (kBadInput) saying what is wrong.
Shard parse_shard(const std::string& text);

/// The entries of `all` that belong to `shard`, in order.
std::vector<SceneEntry> select_shard(const std::vector<SceneEntry>& all, const Shard& shard);

}  // namespace fosssim
