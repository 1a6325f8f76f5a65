#pragma once
// What to draw of a 3D scene: shaded surfaces, edges, particles and trails, seen through an
// orbit camera and sorted by depth (the painter's algorithm).

#include <vector>

#include "core/scene.h"
#include "core/state.h"
#include "render/drawing.h"
#include "render/obstacles_3d.h"
#include "render/orbit_camera.h"
#include "render/path_history.h"

namespace fosssim {

/// Surfaces whose triangles' projected sides are on average at least this many pixels long are
/// outlined (coarse meshes show their triangles; dense ones are shaded only).
inline constexpr double kOutlineMinPixels = 10.0;
/// Fixed particles are drawn at least this large and ringed in the pin colour; fixed particles
/// on a surface as dots of the pin colour, half their radius. The pin colour is the text's:
/// black or white, whichever reads on the background (text_color_for).
inline constexpr double kPinMinPixels = 3.0;

/// Which parts of a 3D scene are drawn besides its surfaces. Surfaces are the mesh faces
/// (Appearance::triangles) and the membranes: the triangles the model's forces show
/// (Force::append_elements, the elastic bodies' constant strain triangles). A surface stands
/// for its mesh: the particles on it or inside it (Appearance::interior_particles) and the
/// edges between them are not drawn; the fixed ones on it are marked as pins.
struct SceneParts3D {
  std::vector<int> particles;  ///< drawn as discs: on no surface and inside none
  std::vector<int> pins;       ///< fixed particles on a surface: drawn as dots
  std::vector<int> edges;      ///< drawn as capsules: with an end on no surface and inside none
  /// The model's forces (indices into SceneModel::forces) that show elements: asked for them
  /// at every picture.
  std::vector<int> element_forces;
  /// The mesh faces drawn (indices into Appearance::triangles): those that are not also a
  /// membrane triangle (same corners), which is drawn instead so that it can be coloured.
  std::vector<int> faces;
  ObstacleFrame obstacles;  ///< where half-spaces are drawn (render/obstacles_3d.h)
};

/// Works out SceneParts3D once for a scene (its topology does not change while it runs; the
/// forces' elements are asked for at the initial state).
SceneParts3D compute_scene_parts_3d(const Scene& scene);

/// The drawing of `state` of a 3D scene seen through `camera` on a width × height picture,
/// every shape sorted farthest first by the depth of its point nearest the eye:
/// - each mesh face filled with the mean colour of its corners' particles, shaded by
///   shade_triangle under camera_lighting, outlined in a darker colour when the faces are coarse
///   (kOutlineMinPixels);
/// - each membrane triangle (the triangles of `parts.element_forces` at `state`) the same way,
///   filled with kPlainTriangleColor, or with the colour of its strain or energy density when
///   overlay.elements asks (element_color, the 2D colour maps), then shaded alike on both sides
///   (BackSide::kSame: the hue keeps its value, the brightness shows the shape), outlined when
///   the membranes are coarse; a legend line (element_legend) when coloured by a value;
/// - hinges the forces show, as two capsules and a disc on the hinge particle, in their colour;
/// - `parts.edges` as capsules and `parts.particles` as discs, their radii scaled by the
///   perspective at their depth; fixed particles at least kPinMinPixels and ringed in the pin
///   colour; `parts.pins` as dots;
/// - the trails as thin segments;
/// - the spheres as shaded facets;
/// and, painted before all of them as regions, the half-spaces as tiled patches of their
/// boundaries (add_half_space_regions).
/// Shapes with a corner behind the near plane are left out. The overlay's marks ring their
/// particles and its drag guide is drawn over everything, as in 2D.
Drawing compose_drawing_3d(const Scene& scene, const SceneParts3D& parts, const State& state,
                           const PathHistory& paths, const OrbitCamera& camera, int width,
                           int height, const Overlay& overlay = {});

}  // namespace fosssim
