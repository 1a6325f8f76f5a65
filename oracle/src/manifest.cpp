#include "manifest.h"

#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "atomic_file.h"
#include "batch.h"
#include "core/limits.h"
#include "core/text.h"
#include "diagnosis.h"
#include "io/rigid_trajectory.h"
#include "io/scene_loader.h"
#include "io/text_lines.h"
#include "io/trajectory_file.h"
#include "sha256.h"

namespace fosssim {

namespace fs = std::filesystem;

namespace {

constexpr const char* kTableName = "golden.tsv";
constexpr const char* kFinalFolder = "final";

std::string final_state_path(const std::string& folder, const std::string& scene) {
  return diagnosis_stem(folder + "/" + kFinalFolder, scene) + ".txt";
}

ManifestEntry compute_entry(const SceneEntry& scene, const CandidateRunOptions& options,
                            const std::string& work_dir) {
  ManifestEntry entry;
  entry.scene = scene.name;
  std::optional<Scene> loaded;
  try {
    loaded.emplace(load_scene_file(scene.path));
    check_step_count(loaded->model, Limits{});
  } catch (const Error&) {
    entry.status = "scene-error";
    return entry;
  }
  const SceneModel& model = loaded->model;
  const std::int64_t expected = expected_trajectory_bytes(model);
  try {
    WorkFolder work(work_dir);
    const CandidateRun run =
        run_candidate(scene.path, expected, options, work,
                      trajectory_size_is_exact(model) ? TrajectorySize::kExact
                                                      : TrajectorySize::kAtLeastRecords);
    if (run.problem) {
      entry.status = verdict_id(*run.problem);
      if (*run.problem == Verdict::kExitStatus)
        entry.status += ":" + std::to_string(run.exit_status);
      return entry;
    }
    if (model.rigid_bodies) {  // Theme 3's layout (io/rigid_trajectory.h)
      std::optional<RigidTrajectoryReader> file;
      try {
        file.emplace(RigidTrajectoryReader::open(run.trajectory_path, model.num_particles(),
                                                 model.num_steps()));
      } catch (const Error&) {
      }
      const std::string digest = file ? sha256_file_hex(run.trajectory_path) : "";
      if (digest.empty()) {
        entry.status = "unreadable";
        return entry;
      }
      entry.frames = model.num_steps() + 1;
      entry.bytes = static_cast<std::int64_t>(std::filesystem::file_size(run.trajectory_path));
      entry.sha256 = digest;
      const State last = rigid_state_from_block(model, file->read_frame(entry.frames - 1).state);
      entry.final_state = final_state_text(last.q, last.v, model.dim);
      return entry;
    }
    // A trajectory that cannot be opened, or read through for its digest, is "unreadable": an
    // empty digest must never pass for "ok".
    std::optional<TrajectoryReader> file;
    try {
      file.emplace(open_trajectory(run.trajectory_path, model));
    } catch (const Error&) {
    }
    const std::string digest = file ? sha256_file_hex(run.trajectory_path) : "";
    if (digest.empty()) {
      entry.status = "unreadable";
      return entry;
    }
    entry.frames = file->num_frames();
    entry.bytes = static_cast<std::int64_t>(std::filesystem::file_size(run.trajectory_path));
    entry.sha256 = digest;
    Vector q, v;
    file->read_frame(entry.frames - 1, q, v);
    entry.final_state = final_state_text(q, v, model.dim);
  } catch (const std::exception&) {
    entry.status = "oracle-error";
  }
  return entry;
}

/// The first line where two texts differ, as "particle line `a` here, `b` in the manifest".
std::string first_difference(const std::string& now, const std::string& golden) {
  std::istringstream a(now), b(golden);
  std::string line_a, line_b;
  while (true) {
    const bool got_a = static_cast<bool>(std::getline(a, line_a));
    const bool got_b = static_cast<bool>(std::getline(b, line_b));
    if (!got_a && !got_b) return "";
    if (!got_a || !got_b || line_a != line_b) {
      return "final state now \"" + (got_a ? line_a : "(none)") + "\", manifest \"" +
             (got_b ? line_b : "(none)") + "\"";
    }
  }
}

}  // namespace

std::string final_state_text(const Vector& q, const Vector& v, int dim) {
  std::string text;
  for (int p = 0; p * dim < q.size(); ++p) {
    text += std::to_string(p);
    for (const Vector* x : {&q, &v}) {
      for (int c = 0; c < dim; ++c) {
        text += '\t';
        text += to_text((*x)[dim * p + c]);
      }
    }
    text += "\n";
  }
  return text;
}

std::vector<ManifestEntry> compute_manifest(const std::vector<SceneEntry>& scenes,
                                            const CandidateRunOptions& options,
                                            const std::string& work_dir, int jobs) {
  std::vector<ManifestEntry> entries(scenes.size());
  for_each_in_parallel(scenes.size(), jobs, [&](std::size_t i) {
    entries[i] = compute_entry(scenes[i], options, work_dir);
  });
  return entries;
}

void write_manifest(const std::string& folder, const std::vector<ManifestEntry>& entries,
                    const std::string& regenerate_command) {
  std::ostringstream table;
  table << "# FOSSSim regression manifest: SHA-256 of FOSSSim's trajectory of every scene.\n"
        << "# Generated; do not edit. Regenerate after an intended change with:\n"
        << "#   " << regenerate_command << "\n"
        << "# scene\tstatus\tframes\tbytes\tsha256\n";
  std::set<std::string> kept;
  for (const ManifestEntry& e : entries) {
    table << e.scene << '\t' << e.status << '\t' << e.frames << '\t' << e.bytes << '\t'
          << (e.sha256.empty() ? "-" : e.sha256) << '\n';
    if (e.status != "ok") continue;
    const std::string path = final_state_path(folder, e.scene);
    const std::string header = "# final state (frame " + std::to_string(e.frames - 1) + ") of " +
                               e.scene + ": particle, position, velocity\n";
    write_file_atomically(path, header + e.final_state);
    kept.insert(fs::path(path).lexically_normal().string());
  }
  write_file_atomically(folder + "/" + kTableName, table.str());
  std::error_code error;
  const fs::path final_folder = fs::path(folder) / kFinalFolder;
  std::vector<fs::path> stale;
  for (fs::recursive_directory_iterator it(final_folder, error), end; !error && it != end;
       it.increment(error)) {
    if (it->is_regular_file() && !kept.count(it->path().lexically_normal().string())) {
      stale.push_back(it->path());
    }
  }
  for (const fs::path& path : stale) fs::remove(path, error);
}

std::vector<ManifestEntry> read_manifest(const std::string& folder) {
  const auto fail = [](const std::string& problem) { throw Error(ErrorKind::kBadInput, problem); };
  const std::string table_path = folder + "/" + kTableName;
  std::string table;
  try {
    table = read_text_file(table_path);
  } catch (const Error&) {
    fail("cannot read the manifest " + table_path);
  }
  std::vector<ManifestEntry> entries;
  std::istringstream lines(table);
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    ManifestEntry e;
    std::string digest;
    if (!std::getline(fields, e.scene, '\t') || !std::getline(fields, e.status, '\t') ||
        !(fields >> e.frames >> e.bytes >> digest)) {
      fail(table_path + ":" + std::to_string(number) +
           ": expected scene, status, frames, bytes and sha256 separated by tabs");
    }
    if (digest != "-") e.sha256 = digest;
    if (e.status == "ok") {
      const std::string path = final_state_path(folder, e.scene);
      std::string text;
      try {
        text = read_text_file(path);
      } catch (const Error&) {
        fail("the manifest lists " + e.scene + " but " + path + " is missing");
      }
      const std::size_t header_end = text.find('\n');
      e.final_state = !text.empty() && text[0] == '#' && header_end != std::string::npos
                          ? text.substr(header_end + 1)
                          : text;
    }
    entries.push_back(std::move(e));
  }
  return entries;
}

std::vector<std::string> compare_manifest(const std::vector<ManifestEntry>& golden,
                                          const std::vector<ManifestEntry>& current,
                                          const std::string& regenerate_command) {
  std::map<std::string, const ManifestEntry*> golden_by_scene;
  for (const ManifestEntry& e : golden) golden_by_scene[e.scene] = &e;
  std::vector<std::string> problems;
  std::set<std::string> seen;
  for (const ManifestEntry& now : current) {
    seen.insert(now.scene);
    const auto it = golden_by_scene.find(now.scene);
    if (it == golden_by_scene.end()) {
      problems.push_back(now.scene + ": not in the manifest (a new scene?); run `" +
                         regenerate_command + "` and commit oracle/manifest");
      continue;
    }
    const ManifestEntry& old = *it->second;
    if (now.status != old.status) {
      problems.push_back(now.scene + ": FOSSSim's run now ends with status \"" + now.status +
                         "\", the manifest says \"" + old.status + "\"");
    } else if (now.sha256 != old.sha256 || now.frames != old.frames || now.bytes != old.bytes) {
      std::string where = first_difference(now.final_state, old.final_state);
      if (where.empty()) where = "the final state is unchanged, so an earlier frame differs";
      problems.push_back(now.scene + ": the trajectory changed (sha256 " + now.sha256 + ", " +
                         std::to_string(now.frames) + " frames; manifest " + old.sha256 + ", " +
                         std::to_string(old.frames) + " frames); " + where);
    } else if (now.final_state != old.final_state) {
      problems.push_back(now.scene + ": the digest matches but the manifest's final state does " +
                         "not (" + first_difference(now.final_state, old.final_state) +
                         "); was the manifest edited by hand?");
    }
  }
  for (const ManifestEntry& old : golden) {
    if (!seen.count(old.scene)) {
      problems.push_back(old.scene + ": in the manifest, but the scene was not found");
    }
  }
  if (!problems.empty()) {
    problems.push_back("If these changes are intended, regenerate the manifest with `" +
                       regenerate_command + "` and commit it with the change.");
  }
  return problems;
}

}  // namespace fosssim
