#include "render/drawing_3d.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include "io/scene_loader.h"
#include "render/scene_view.h"
#include "render/shading.h"
#include "support/scene_builder.h"
#include "support/tiny_scenes.h"

namespace fosssim {
namespace {

using testing::front_camera;
using testing::membrane_scene;
using testing::particles_at;

Drawing draw(const Scene& scene, const OrbitCamera& camera, const Overlay& overlay = {}) {
  return compose_drawing_3d(scene, compute_scene_parts_3d(scene), scene.initial, PathHistory(scene),
                            camera, 512, 512, overlay);
}

TEST(ComposeDrawing3D, SortsShapesFarthestFirstAndScalesThemByDepth) {
  // Listed near, far, middle: drawn far, middle, near.
  const Scene scene = particles_at({{0.5, 0, 1}, {-0.5, 0, -1}, {0, 0.5, 0}});
  const Drawing d = draw(scene, front_camera());
  ASSERT_EQ(d.shapes.size(), 3u);
  const Disc& far = std::get<Disc>(d.shapes[0]);
  const Disc& middle = std::get<Disc>(d.shapes[1]);
  const Disc& near = std::get<Disc>(d.shapes[2]);
  EXPECT_NEAR(far.center.x, 256.0 - 0.5 * 256.0 / 6.0, 1e-9);
  EXPECT_NEAR(middle.center.y, 256.0 - 0.5 * 256.0 / 5.0, 1e-9);
  EXPECT_NEAR(near.center.x, 256.0 + 0.5 * 256.0 / 4.0, 1e-9);
  EXPECT_NEAR(far.radius, 0.05 * 256.0 / 6.0, 1e-9);
  EXPECT_NEAR(near.radius, 0.05 * 256.0 / 4.0, 1e-9);
  EXPECT_TRUE(d.edges.empty());
  EXPECT_TRUE(d.particles.empty());
  EXPECT_TRUE(d.paths.empty());
}

TEST(ComposeDrawing3D, ShadesTrianglesAndSortsThemByTheirCentres) {
  Scene scene = particles_at({{0, 0, -1},
                              {1, 0, -1},
                              {0, 1, -1},  // far, facing the eye
                              {0, 0, 1},
                              {1, 0, 1},
                              {0, 1, 1}});  // near
  scene.appearance.triangles = {{3, 4, 5}, {0, 1, 2}};
  scene.appearance.particle_color.assign(6, Color{0.2, 0.4, 0.6});
  const Drawing d = draw(scene, front_camera());
  ASSERT_EQ(d.shapes.size(), 2u) << "surface particles are not drawn";
  const Triangle& far = std::get<Triangle>(d.shapes[0]);
  const Triangle& near = std::get<Triangle>(d.shapes[1]);
  EXPECT_NEAR(far.corners[1].x, 256.0 + 256.0 / 6.0, 1e-9);
  EXPECT_NEAR(near.corners[1].x, 256.0 + 256.0 / 4.0, 1e-9);
  const OrbitProjection view(front_camera(), 512, 512);
  const Lighting light = camera_lighting(view.right(), view.up(), view.forward());
  const Eigen::Vector3d a(0, 0, 1), b(1, 0, 1), c(0, 1, 1);
  const Color expected =
      shade_triangle({0.2, 0.4, 0.6}, a, b, c, (a + b + c) / 3.0 - view.eye(), light);
  EXPECT_NEAR(near.color.r, expected.r, 1e-12);
  EXPECT_NEAR(near.color.g, expected.g, 1e-12);
  EXPECT_NEAR(near.color.b, expected.b, 1e-12);
  // Sides of 43 to 85 pixels: a coarse surface, outlined in a darker colour.
  EXPECT_GT(near.outline_width, 0.0);
  EXPECT_LT(near.outline_color.b, near.color.b);
}

TEST(ComposeDrawing3D, OutlinesOnlyCoarseSurfaces) {
  Scene scene = particles_at({{0, 0, 0}, {0.01, 0, 0}, {0, 0.01, 0}});
  scene.appearance.triangles = {{0, 1, 2}};
  const Drawing d = draw(scene, front_camera());
  ASSERT_EQ(d.shapes.size(), 1u);
  EXPECT_EQ(std::get<Triangle>(d.shapes[0]).outline_width, 0.0);
}

TEST(ComposeDrawing3D, LeavesOutShapesBehindTheEye) {
  testing::TestScene scene = particles_at({{0, 0, 0}, {0, 0, 7}, {1, 0, 7}, {0, 1, 7}});
  scene.appearance.triangles = {{1, 2, 3}};
  scene.add_edge(0, 1, 0.02);
  const Drawing d = draw(scene, front_camera());
  ASSERT_EQ(d.shapes.size(), 1u);
  EXPECT_TRUE(std::holds_alternative<Disc>(d.shapes[0]));
}

TEST(SceneParts3D, SurfacesStandForTheirMeshesAndPinsAreMarked) {
  testing::TestScene scene(load_scene_text(R"(<scene dim="3">
    <duration time="1"/><integrator type="local-global" dt="0.01"/>
    <particle m="1" px="0" py="3" pz="0" vx="0" vy="0" vz="0" fixed="1"/>
    <particle m="1" px="0" py="2" pz="0" vx="0" vy="0" vz="0" fixed="0"/>
    <edge i="0" j="1"/>
    <generate type="tetbox" nx="2" ny="2" nz="2" pin="bottom" k="10" m="0.1"/>
  </scene>)",
                                           "parts.xml"));
  scene.add_edge(1, 2, 0.02);  // from a loose particle to the box's first vertex
  ASSERT_EQ(scene.appearance.interior_particles.size(), 1u);  // the box's centre
  const SceneParts3D parts = compute_scene_parts_3d(scene);
  EXPECT_EQ(parts.particles, (std::vector<int>{0, 1}));
  // The box's bottom vertices (9 of its 27) are pinned and all on its surface.
  ASSERT_EQ(parts.pins.size(), 9u);
  for (int p : parts.pins) EXPECT_TRUE(scene.model.fixed[p]);
  // Edges: 0-1 and 1-2 (to a surface vertex) are drawn; the box's springs are not.
  ASSERT_EQ(parts.edges.size(), 2u);
  for (int e : parts.edges) {
    const Edge& edge = scene.model.edges[e];
    EXPECT_TRUE(edge.i <= 1 || edge.j <= 1);
  }
}

TEST(ComposeDrawing3D, RingsFixedParticlesAndDrawsPinsAsDots) {
  Scene scene = particles_at({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, -1, 0}});
  scene.appearance.triangles = {{0, 1, 2}};
  scene.model.fixed = {true, false, false, true};
  scene.model.particle_radius[3] = 1e-4;  // tiny: drawn at kPinMinPixels
  const Drawing d = draw(scene, front_camera());
  int rings = 0, dots = 0;
  for (const Shape& shape : d.shapes) {
    if (const auto* ring = std::get_if<Ring>(&shape)) {
      ++rings;
      EXPECT_EQ(ring->color, d.text_color);
      EXPECT_DOUBLE_EQ(ring->radius, kPinMinPixels);
    }
    if (const auto* disc = std::get_if<Disc>(&shape); disc && disc->color == d.text_color) ++dots;
  }
  EXPECT_EQ(d.text_color, (Color{0, 0, 0}));  // on white
  EXPECT_EQ(rings, 1);                        // the loose fixed particle 3
  EXPECT_EQ(dots, 1);                         // the pin on the surface, particle 0
}

TEST(ComposeDrawing3D, AddsMarksTheDragGuideAndTheTime) {
  Scene scene = particles_at({{1, 0, 0}});
  Overlay overlay;
  overlay.marks = {{0, Color{1, 0, 0}}};
  overlay.drag = DragGuide{0, Eigen::Vector3d(0, 1, 0), std::nullopt};
  overlay.status = {"paused"};
  const Drawing d = draw(scene, front_camera(), overlay);
  ASSERT_EQ(d.marks.size(), 2u);  // the mark and the guide's ring
  EXPECT_NEAR(d.marks[0].center.x, 256.0 + 256.0 / 5.0, 1e-9);
  EXPECT_NEAR(d.marks[0].radius, 0.05 * 256.0 / 5.0 + kMarkGap, 1e-9);
  ASSERT_EQ(d.guides.size(), 1u);
  ASSERT_EQ(d.guides[0].points.size(), 2u);
  EXPECT_NEAR(d.guides[0].points[1].y, 256.0 - 256.0 / 5.0, 1e-9);
  EXPECT_EQ(d.text, (std::vector<std::string>{"t = 0.00", "paused"}));
}

TEST(ComposeDrawing3D, DrawsTrailsAsSegmentsAmongTheShapes) {
  Scene scene = particles_at({{0, 0, 0}});
  scene.appearance.paths = {{0, 1.0, Color{1, 1, 0}}};
  PathHistory paths(scene);
  State state = scene.initial;
  for (int k = 0; k < 3; ++k) {
    state.q[2] = -1.0 * k;  // moving away
    paths.record(state.q, 3);
  }
  const Drawing d = compose_drawing_3d(scene, compute_scene_parts_3d(scene), scene.initial, paths,
                                       front_camera(), 512, 512);
  ASSERT_EQ(d.shapes.size(), 3u);
  EXPECT_TRUE(std::holds_alternative<Capsule>(d.shapes[0]));  // z from -2 to -1: farthest
  EXPECT_TRUE(std::holds_alternative<Capsule>(d.shapes[1]));
  EXPECT_TRUE(std::holds_alternative<Disc>(d.shapes[2]));
}

/// The triangles of a drawing, in painting order.
std::vector<Triangle> triangles_of(const Drawing& d) {
  std::vector<Triangle> found;
  for (const Shape& shape : d.shapes) {
    if (const auto* t = std::get_if<Triangle>(&shape)) found.push_back(*t);
  }
  return found;
}

/// The colour triangle (a, b, c) of `scene` takes in colour `base` seen through `camera`.
Color shaded(const Scene& scene, const OrbitCamera& camera, int a, int b, int c, const Color& base,
             BackSide back) {
  const OrbitProjection view(camera, 512, 512);
  const Lighting light = camera_lighting(view.right(), view.up(), view.forward());
  const Eigen::Vector3d pa = scene.initial.q.segment<3>(3 * a),
                        pb = scene.initial.q.segment<3>(3 * b),
                        pc = scene.initial.q.segment<3>(3 * c);
  return shade_triangle(base, pa, pb, pc, (pa + pb + pc) / 3.0 - view.eye(), light, back);
}

void expect_color_near(const Color& shown, const Color& expected) {
  EXPECT_NEAR(shown.r, expected.r, 1e-12);
  EXPECT_NEAR(shown.g, expected.g, 1e-12);
  EXPECT_NEAR(shown.b, expected.b, 1e-12);
}

TEST(ComposeDrawing3D, DrawsMembraneTrianglesShadedInThePlainColour) {
  const Scene scene = membrane_scene();
  const Drawing d = draw(scene, front_camera());
  const std::vector<Triangle> triangles = triangles_of(d);
  ASSERT_EQ(triangles.size(), 2u);  // one per element the forces show
  std::vector<ForceElement> elements;
  for (const auto& force : scene.model.forces) force->append_elements(scene.initial.q, elements);
  EXPECT_EQ(elements.size(), triangles.size());
  // Equal depths keep the forces' order: the stretched triangle first.
  EXPECT_NEAR(triangles[0].corners[1].x, 256.0 - 0.5 * 51.2, 1e-9);
  EXPECT_NEAR(triangles[1].corners[1].x, 256.0 + 2.0 * 51.2, 1e-9);
  for (int k = 0; k < 2; ++k) {
    // Light blue, shaded as a mesh face is (seen along the ray to its centre).
    EXPECT_EQ(triangles[k].color, shaded(scene, front_camera(), 3 * k, 3 * k + 1, 3 * k + 2,
                                         kPlainTriangleColor, BackSide::kTinted));
    EXPECT_GT(triangles[k].outline_width, 0.0);  // sides of 77 to 128 pixels: coarse
  }
  EXPECT_EQ(d.text.size(), 1u);  // the time only: plain colours need no legend
}

TEST(ComposeDrawing3D, MembraneParticlesAreDrawnAsSurfaceVertices) {
  const Scene scene = membrane_scene();
  const SceneParts3D parts = compute_scene_parts_3d(scene);
  EXPECT_EQ(parts.particles, (std::vector<int>{6}));  // the loose one only
  EXPECT_EQ(parts.pins, (std::vector<int>{0}));       // the fixed corner
  EXPECT_EQ(parts.edges, (std::vector<int>{1}));      // 5-6; 4-5 lies in the membrane
  EXPECT_EQ(parts.element_forces, (std::vector<int>{0, 1}));
  const Drawing d = draw(scene, front_camera());
  int pins = 0, discs = 0, capsules = 0;
  for (const Shape& shape : d.shapes) {
    if (const auto* disc = std::get_if<Disc>(&shape)) {
      (disc->color == d.text_color ? pins : discs) += 1;
    }
    capsules += std::holds_alternative<Capsule>(shape);
  }
  EXPECT_EQ(pins, 1);
  EXPECT_EQ(discs, 1);
  EXPECT_EQ(capsules, 1);
}

TEST(ComposeDrawing3D, ColoursMembranesByStrainOrEnergyWithTheLegendOf2D) {
  const Scene scene = membrane_scene();
  Overlay overlay;
  overlay.elements.by = ElementColoring::kStrain;
  const Drawing d = draw(scene, front_camera(), overlay);
  std::vector<Triangle> triangles = triangles_of(d);
  ASSERT_EQ(triangles.size(), 2u);
  // +0.5 and -0.25 are beyond the default scale 0.1: full red and full blue, shaded.
  expect_color_near(triangles[0].color, shaded(scene, front_camera(), 0, 1, 2,
                                               strain_color(1.0, 1.0), BackSide::kSame));
  expect_color_near(triangles[1].color, shaded(scene, front_camera(), 3, 4, 5,
                                               strain_color(-1.0, 1.0), BackSide::kSame));
  ASSERT_EQ(d.text.size(), 2u);
  EXPECT_EQ(d.text[1], "strain: red +0.1, blue -0.1");
  // At the scale 0.5 the compressed one is half way to blue.
  overlay.elements.scale = 0.5;
  triangles = triangles_of(draw(scene, front_camera(), overlay));
  expect_color_near(triangles[1].color, shaded(scene, front_camera(), 3, 4, 5,
                                               strain_color(-0.5, 1.0), BackSide::kSame));
  // By energy, scaled by the largest density, the stretched triangle's E/(2(1 - ν²)) εxx² with
  // the course's εxx = 1.5² - 1 = 1.25 (no ½): 10/1.82 · 1.25² ≈ 8.585 J/m²; the compressed
  // one's εxx = 0.75² - 1 = -0.4375 gives (0.4375/1.25)² of it.
  overlay.elements = {ElementColoring::kEnergy, 0.0};
  const Drawing energy = draw(scene, front_camera(), overlay);
  triangles = triangles_of(energy);
  expect_color_near(triangles[0].color, shaded(scene, front_camera(), 0, 1, 2,
                                               energy_color(1.0, 1.0), BackSide::kSame));
  const double ratio = (0.4375 / 1.25) * (0.4375 / 1.25);
  expect_color_near(triangles[1].color, shaded(scene, front_camera(), 3, 4, 5,
                                               energy_color(ratio, 1.0), BackSide::kSame));
  ASSERT_EQ(energy.text.size(), 2u);
  EXPECT_EQ(energy.text[1], "energy density: dark red 8.59");
}

TEST(ComposeDrawing3D, ColouredMembranesLookTheSameFromBehindPlainOnesAreTinted) {
  const Scene scene = membrane_scene();
  OrbitCamera behind = front_camera();
  behind.yaw = std::numbers::pi;  // the eye at z = -5, looking along +z
  Overlay overlay;
  overlay.elements.by = ElementColoring::kStrain;
  const Color red = strain_color(1.0, 1.0);
  // The two triangles are at the same depth: they keep the forces' order.
  const Color stretched = triangles_of(draw(scene, behind, overlay)).at(0).color;
  expect_color_near(stretched, shaded(scene, behind, 0, 1, 2, red, BackSide::kSame));
  EXPECT_NE(stretched, shaded(scene, behind, 0, 1, 2, red, BackSide::kTinted));
  const Color plain = triangles_of(draw(scene, behind)).at(0).color;
  expect_color_near(plain, shaded(scene, behind, 0, 1, 2, kPlainTriangleColor, BackSide::kTinted));
  EXPECT_NE(plain, shaded(scene, behind, 0, 1, 2, kPlainTriangleColor, BackSide::kSame));
}

TEST(SceneParts3D, AMeshFaceThatIsAMembraneIsDrawnOnceAsTheMembrane) {
  Scene scene = membrane_scene();
  scene.appearance.triangles = {{1, 2, 0}, {0, 1, 6}};  // the first is membrane 0-1-2
  const SceneParts3D parts = compute_scene_parts_3d(scene);
  EXPECT_EQ(parts.faces, (std::vector<int>{1}));
  EXPECT_TRUE(parts.particles.empty());  // 6 is on a face now
  Overlay overlay;
  overlay.elements.by = ElementColoring::kStrain;
  EXPECT_EQ(triangles_of(draw(scene, front_camera(), overlay)).size(), 3u);
}

/// A force that shows one hinge (particles 0, 1, 2) and has no energy: elements of a kind the
/// 3D forces do not have yet.
class HingeShowingForce final : public Force {
 public:
  void add_energy(const ForceInput&, double&) const override {}
  void add_gradient(const ForceInput&, Vector&) const override {}
  void add_hessian_x(const ForceInput&, HessianBuilder&) const override {}
  void add_hessian_v(const ForceInput&, HessianBuilder&) const override {}
  bool is_conservative() const override { return true; }
  std::string label() const override { return "hinge"; }
  void append_elements(const Vector&, std::vector<ForceElement>& elements) const override {
    ForceElement hinge;
    hinge.kind = ForceElement::Kind::kHinge;
    hinge.particles = {0, 1, 2};
    hinge.strain = -0.05;
    elements.push_back(hinge);
  }
};

TEST(ComposeDrawing3D, DrawsHingesAsTwoCapsulesAndADiscAmongTheShapes) {
  testing::TestScene scene = particles_at({{-1, 0, 0}, {0, 0, 0}, {0, 1, 0}});
  scene.add_force(std::make_unique<HingeShowingForce>());
  Overlay overlay;
  overlay.elements.by = ElementColoring::kStrain;
  const Drawing d = draw(scene, front_camera(), overlay);
  // The hinge does not stand for its particles: the three discs are drawn too.
  int capsules = 0, discs = 0;
  for (const Shape& shape : d.shapes) {
    if (const auto* capsule = std::get_if<Capsule>(&shape)) {
      ++capsules;
      EXPECT_EQ(capsule->color, strain_color(-0.5, 1.0));
    }
    discs += std::holds_alternative<Disc>(shape);
  }
  EXPECT_EQ(capsules, 2);
  EXPECT_EQ(discs, 4);
}

TEST(SceneView, ColoursThreeDimensionalMembranesAsItIsTold) {
  const Scene scene = membrane_scene();
  SceneView view(scene, scene.initial, 512, 512);
  view.set_element_colors({ElementColoring::kStrain, 0.2});
  const Drawing d = view.compose(scene.initial);
  const std::vector<Triangle> triangles = triangles_of(d);
  ASSERT_EQ(triangles.size(), 2u);
  EXPECT_GT(triangles[0].color.r, 2.0 * triangles[0].color.b);  // stretched: red
  EXPECT_GT(triangles[1].color.b, 2.0 * triangles[1].color.r);  // compressed: blue
  EXPECT_EQ(d.text.back(), "strain: red +0.2, blue -0.2");
}

TEST(SceneView, UsesTheOrbitCameraForThreeDimensionalScenes) {
  Scene scene = particles_at({{0, 0, 0}, {2, 1, -1}});
  SceneView view(scene, scene.initial, 512, 512);
  ASSERT_TRUE(view.is_3d());
  EXPECT_EQ(view.compose(scene.initial).shapes.size(), 2u);
  State moved = scene.initial;
  moved.q.segment<3>(3) = Eigen::Vector3d(4, 1, -1);
  view.recenter(moved);
  EXPECT_TRUE(view.orbit_camera().target.isApprox(Eigen::Vector3d(2.0, 0.5, -0.5)));
  // The ray through the target's pixel runs along the view direction.
  const Ray ray = view.ray_through(256.0, 256.0);
  EXPECT_TRUE(ray.direction.normalized().isApprox(view.view_direction()));
  const double before = view.orbit_camera().distance;
  view.zoom(2.0);
  EXPECT_DOUBLE_EQ(view.orbit_camera().distance, 2.0 * before);
  const double yaw = view.orbit_camera().yaw;
  view.orbit(10.0, 0.0);
  EXPECT_LT(view.orbit_camera().yaw, yaw);
}

TEST(SceneView, KeepsTheTwoDimensionalCameraFor2DScenes) {
  auto scene = load_scene_text(R"(<scene>
    <duration time="1"/><integrator type="explicit-euler" dt="0.01"/>
    <particle m="1" px="0" py="0" vx="0" vy="0" fixed="0"/>
    <viewport cx="0" cy="0" size="1"/></scene>)",
                               "flat.xml");
  SceneView view(scene, scene.initial, 512, 512);
  EXPECT_FALSE(view.is_3d());
  EXPECT_TRUE(view.compose(scene.initial).shapes.empty());
  const Ray ray = view.ray_through(384.0, 128.0);  // world (0.5, 0.5)
  EXPECT_EQ(ray.origin, Eigen::Vector3d(0.5, 0.5, 1.0));
  EXPECT_EQ(ray.direction, -Eigen::Vector3d::UnitZ());
  EXPECT_DOUBLE_EQ(view.units_per_pixel_at(Eigen::Vector3d::Zero()), 1.0 / 256.0);
  view.pan(256.0, 0.0);
  EXPECT_DOUBLE_EQ(view.camera().cx, -1.0);
  view.orbit(100.0, 100.0);  // nothing in 2D
  EXPECT_DOUBLE_EQ(view.camera().cx, -1.0);
}

TEST(ComposeDrawing3D, HalfSpacesAreCheckeredPatchesSeenOnlyFromTheirFreeSide) {
  // The eye at (0, 0, 5) looks along -z. The floor y ≤ -1 is seen from above: a patch of
  // 16 × 16 tiles of half-width 2 around the particle, all below the horizon (the picture's
  // middle row), in two shades. The wall z ≥ 1 has the eye inside its solid: not drawn.
  Scene scene = particles_at({{0, 0, 0}});
  scene.model.half_planes.push_back({testing::vec({0, -1, 0}), testing::vec({0, 1, 0})});
  scene.appearance.half_plane_color.assign(1, Color{0.8, 0.8, 0.8});
  const Drawing floor = draw(scene, front_camera());
  ASSERT_EQ(floor.regions.size(), static_cast<std::size_t>(kTiles * kTiles));
  std::vector<Color> colors;
  for (const Region& region : floor.regions) {
    for (const Point2& corner : region.corners) EXPECT_GT(corner.y, 256.0);
    if (std::find(colors.begin(), colors.end(), region.color) == colors.end()) {
      colors.push_back(region.color);
    }
  }
  EXPECT_EQ(colors.size(), 2u);
  Scene walled = particles_at({{0, 0, 0}});
  walled.model.half_planes.push_back({testing::vec({0, 0, 1}), testing::vec({0, 0, -1})});
  walled.appearance.half_plane_color.assign(1, Color{0.5, 0.5, 0.5});
  EXPECT_TRUE(draw(walled, front_camera()).regions.empty());
  // With both, the floor is cut at the wall: the 12 rows of tiles with z ≤ 1 remain.
  scene.model.half_planes.push_back(walled.model.half_planes[0]);
  scene.appearance.half_plane_color.push_back(Color{0.5, 0.5, 0.5});
  EXPECT_EQ(draw(scene, front_camera()).regions.size(), static_cast<std::size_t>(kTiles * 12));
}

TEST(ComposeDrawing3D, SpheresAreShadedFacetsOfTheirNearSide) {
  // A sphere of radius 0.5 at the origin, 5 units in front of the eye (focal length 256 pixels):
  // its outline has a radius of about 0.5 · 256 / √(5² - 0.5²) ≈ 25.7 pixels.
  Scene scene = particles_at({{3, 0, 0}});
  scene.model.spheres.push_back({testing::vec({0, 0, 0}), 0.5});
  scene.appearance.sphere_color.assign(1, Color{0.9, 0.5, 0.1});
  const Drawing d = draw(scene, front_camera());
  int facets = 0;
  for (const Shape& shape : d.shapes) {
    const Triangle* t = std::get_if<Triangle>(&shape);
    if (t == nullptr) continue;
    ++facets;
    for (const Point2& c : t->corners) {
      EXPECT_LT(std::hypot(c.x - 256.0, c.y - 256.0), 25.8);
    }
  }
  // About half of the 32 × (2 · 16 - 2) facets face the eye.
  EXPECT_GT(facets, 32 * 12);
  EXPECT_LT(facets, 32 * 17);
}

}  // namespace
}  // namespace fosssim
