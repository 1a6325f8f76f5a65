#pragma once
// Reads the fast mass-springs assignment's JSON scenes (docs/scenes-3d.md, 'JSON scenes').

#include <string>
#include <string_view>

#include "core/scene.h"
#include "io/input_files.h"
#include "io/scene_error.h"

namespace fosssim {

/// The assignment's defaults, which its data files rely on.
struct JsonSceneDefaults {
  static constexpr double kTimeStep = 1.0 / 30.0;  ///< h, s
  static constexpr int kIterations = 50;           ///< local/global iterations per step
  static constexpr double kGravity = -9.8;         ///< y force on every vertex, N (not m·g)
  static constexpr double kPenalty = 1e10;         ///< w of the pins' w·CᵀC, N/m
  static constexpr double kAreaDensity = 1.0;      ///< kg/m², for masses from areas
  static constexpr double kDuration = 10.0;        ///< s; the assignment ran until closed
  /// Each step's iterations start at the current positions pⁿ, as the assignment's do.
  static constexpr std::string_view kStart = "current";
};

/// Reads a JSON scene of the fast mass-springs assignment:
///   { "obj": "cloth.obj", "k": 1000, "b": [1, 81], "m": 0.01 }
/// obj: the OBJ mesh (relative to the JSON file), whose faces and "f i j" lines give the
/// springs (rest lengths: the initial lengths); k: every spring's stiffness (N/m); b: the
/// pinned vertices, 1-based (optional, default none); m: every vertex's mass (optional;
/// without it the masses are the mixed Voronoi areas of the faces, fanned into triangles, at
/// 1 kg/m²: MassRule::kVoronoi, libigl's default mass matrix, which the assignment uses). The
/// scene is 3D, runs the local/global integrator with the assignment's defaults
/// (JsonSceneDefaults: h = 1/30 s, 50 iterations starting at the current positions, pins by
/// penalty w = 1e10) and applies a force of -9.8 N along y to every vertex, pinned ones
/// included (a constant force, not m·g, as in the assignment). Optional keys of ours: "h",
/// "iterations", "start" (the local/global option), "duration". Other keys become warnings,
/// except one within two edits of a known key, an error with a did-you-mean. Every problem is
/// reported at once (SceneErrors, at most SceneErrorList::kMaxReported), each naming the file,
/// its line (the key's, a "b" entry's, or the object's for a missing key) and the problem. The
/// files are read through `files` (io/input_files.h), and Scene::files lists them.
Scene load_json_scene_file(const std::string& path, InputFiles& files);
/// The same with the default limits.
Scene load_json_scene_file(const std::string& path);

/// Reads JSON text; `name` stands for the file in messages and its directory is where a
/// relative "obj" path starts; the mesh is read through `files`.
Scene load_json_scene_text(std::string_view text, const std::string& name, InputFiles& files);
/// The same with the default limits, the mesh read from the file system.
Scene load_json_scene_text(std::string_view text, const std::string& name);

}  // namespace fosssim
