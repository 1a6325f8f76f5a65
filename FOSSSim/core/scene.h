#pragma once
// A loaded scene: its model, its initial state and how it looks.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/scene_model.h"
#include "core/state.h"

namespace fosssim {

/// An RGB colour with components in [0, 1].
struct Color {
  double r = 0.0, g = 0.0, b = 0.0;
  bool operator==(const Color&) const = default;
};

/// A trail behind particle `particle` of its last ceil(duration/dt) positions.
struct ParticlePath {
  int particle = 0;
  double duration = 0.0;
  Color color;
};

/// A fixed camera: centre, and `size` = half the visible height in world units (the course's
/// display "scale factor"; the visible width follows from the picture's aspect).
struct Viewport {
  double cx = 0.0, cy = 0.0, size = 1.0;
};

/// A scene's <camera3d>: how pictures of a 3D scene look at it first (docs/viewing.md). Values
/// left unset are chosen by the picture: the default angles and field of view, and a target
/// and distance fitted to the particles.
struct OrbitViewSettings {
  std::optional<double> yaw;       ///< degrees about +y; 0 looks along -z, 90 along -x
  std::optional<double> pitch;     ///< degrees above the horizontal; positive looks down
  std::optional<double> distance;  ///< from the eye to the target, world units (> 0)
  std::optional<std::array<double, 3>> target;  ///< the point looked at, world units
  std::optional<double> fov;                    ///< vertical field of view, degrees, in (0, 180)
  bool orthographic = false;                    ///< parallel projection instead of perspective
};

/// How a scene is drawn; no physics depends on it.
struct Appearance {
  static constexpr Color kDefaultParticleColor{0.651, 0.294, 0.0};
  /// Vertices of meshes, and so the surfaces drawn over them (3D pictures shade a triangle in
  /// the mean colour of its corners).
  static constexpr Color kDefaultMeshColor{0.25, 0.5, 0.8};
  static constexpr Color kDefaultEdgeColor{0.0, 0.388, 0.388};
  static constexpr Color kDefaultHalfPlaneColor{0.0, 0.0, 0.0};
  static constexpr Color kDefaultSphereColor{0.6, 0.6, 0.6};

  // Radii are physics: SceneModel::particle_radius and SceneModel::edge_radius.
  std::vector<Color> particle_color;
  std::vector<Color> edge_color;
  std::vector<Color> half_plane_color;  ///< per half-plane, default black
  std::vector<Color> sphere_color;      ///< per sphere, default grey
  Color background{1.0, 1.0, 1.0};
  std::vector<ParticlePath> paths;
  std::optional<Viewport> viewport;
  /// Surface triangles to shade (particle indices): the faces of cloth meshes and the boundary
  /// of tet meshes. Empty for particle scenes.
  std::vector<std::array<int, 3>> triangles;
  /// Particles inside a closed surface of `triangles` (the interior vertices of tet meshes):
  /// 3D pictures draw the surface and not them, nor the edges between them and the surface.
  std::vector<int> interior_particles;
  /// The scene's <camera3d>, or the command line's --view; 3D scenes only.
  std::optional<OrbitViewSettings> camera3d;
};

/// Everything a scene file declares.
struct Scene {
  std::string source;  ///< the file it was read from, for messages
  /// Every file it was read from: the scene file, then the mesh files it names (empty for a
  /// scene built in memory). No output of a run may replace one of them.
  std::vector<std::string> files;
  SceneModel model;
  State initial;
  Appearance appearance;
  std::string description;
  std::string tag;                         ///< scenetag, selects scripted behaviour
  std::vector<std::string> particle_tags;  ///< per particle, empty when untagged
  double max_sim_frequency = 100.0;        ///< window throttle, steps per wall second
  std::vector<std::string> warnings;       ///< things that were accepted but look wrong
  /// The course theme whose grading program this scene belongs to: 4 when it declares a
  /// Theme 4 elastic force (its program allows larger velocity residuals), else 1. Grading
  /// chooses its criteria by it (grading/grader.h, criteria_for).
  int grading_theme = 1;
};

}  // namespace fosssim
