#include "render/drawing.h"

#include <gtest/gtest.h>

#include <limits>
#include <numbers>
#include <variant>

#include "io/scene_loader.h"
#include "render/scene_view.h"
#include "support/tiny_scenes.h"

namespace fosssim {
namespace {

using testing::tiny_scene;

TEST(ComposeDrawing, PlacesParticlesAndEdgesInPixels) {
  const Scene scene = tiny_scene();
  const PathHistory paths(scene);
  const Camera camera{0.0, 0.0, 1.0};
  const Drawing d = compose_drawing(scene, scene.initial, paths, camera, 512, 512);
  EXPECT_EQ(d.width, 512);
  EXPECT_EQ(d.background, (Color{0.1, 0.1, 0.2}));
  ASSERT_EQ(d.particles.size(), 2u);
  EXPECT_DOUBLE_EQ(d.particles[0].center.x, 128.0);
  EXPECT_DOUBLE_EQ(d.particles[0].center.y, 256.0);
  EXPECT_DOUBLE_EQ(d.particles[0].radius, 25.6);
  EXPECT_EQ(d.particles[0].color, (Color{1, 0, 0}));
  EXPECT_DOUBLE_EQ(d.particles[1].center.x, 384.0);
  EXPECT_DOUBLE_EQ(d.particles[1].center.y, 192.0);
  EXPECT_DOUBLE_EQ(d.particles[1].radius, 0.1 * 256);  // the default radius
  EXPECT_EQ(d.particles[1].color, Appearance::kDefaultParticleColor);
  ASSERT_EQ(d.edges.size(), 1u);
  EXPECT_DOUBLE_EQ(d.edges[0].a.x, 128.0);
  EXPECT_DOUBLE_EQ(d.edges[0].b.y, 192.0);
  EXPECT_DOUBLE_EQ(d.edges[0].radius, 12.8);
  EXPECT_EQ(d.edges[0].color, (Color{0, 1, 0}));
  EXPECT_TRUE(d.paths.empty());  // a trail needs two points
  ASSERT_EQ(d.text.size(), 1u);
  EXPECT_EQ(d.text[0], "t = 0.00");
  EXPECT_EQ(d.text_color, (Color{1, 1, 1}));  // light text on a dark background
}

TEST(ComposeDrawing, AddsMarksAndStatusAndCanHideTheTime) {
  const Scene scene = tiny_scene();
  Overlay overlay;
  overlay.show_time = false;
  overlay.status = {"paused"};
  overlay.marks = {{1, Color{1, 0, 0}}};
  const Drawing d =
      compose_drawing(scene, scene.initial, PathHistory(scene), Camera{0, 0, 1}, 512, 512, overlay);
  EXPECT_EQ(d.text, std::vector<std::string>{"paused"});
  ASSERT_EQ(d.marks.size(), 1u);
  EXPECT_DOUBLE_EQ(d.marks[0].center.x, 384.0);
  EXPECT_GT(d.marks[0].radius, d.particles[1].radius);
}

TEST(SceneView, RecordsTrailsAndRecentres) {
  const Scene scene = tiny_scene();
  SceneView view(scene, scene.initial, 512, 512);
  EXPECT_DOUBLE_EQ(view.camera().scale, 1.0);  // the viewport
  State state = scene.initial;
  for (int k = 1; k <= 60; ++k) {
    state.q[1] = 0.01 * k;
    state.step = k;
    view.record(state);
  }
  const Drawing d = view.compose(state);
  ASSERT_EQ(d.paths.size(), 1u);
  EXPECT_EQ(d.paths[0].points.size(), 50u);  // ceil(0.5 / 0.01)
  EXPECT_DOUBLE_EQ(d.paths[0].points.back().y, 256.0 - 0.6 * 256.0);
  EXPECT_EQ(d.paths[0].color, testing::kYellow);
  view.recenter(state);
  EXPECT_DOUBLE_EQ(view.camera().cx, 0.0);
  EXPECT_DOUBLE_EQ(view.camera().cy, 0.5 * (0.6 + 0.25));
  view.restart_trails(state);
  EXPECT_TRUE(view.compose(state).paths.empty());
}

TEST(ComposeDrawing, ProjectsThreeDimensionalScenesOntoXY) {
  auto scene = load_scene_text(R"(<scene dim="3">
    <duration time="1"/><integrator type="explicit-euler" dt="0.01"/>
    <particle m="1" px="1" py="2" pz="30" vx="0" vy="0" vz="0" fixed="0"/>
    <viewport cx="0" cy="0" size="4"/></scene>)",
                               "three.xml");
  const Drawing d =
      compose_drawing(scene, scene.initial, PathHistory(scene), Camera{0, 0, 4}, 512, 512);
  ASSERT_EQ(d.particles.size(), 1u);
  EXPECT_DOUBLE_EQ(d.particles[0].center.x, 256.0 + 64.0);
  EXPECT_DOUBLE_EQ(d.particles[0].center.y, 256.0 - 128.0);
}

TEST(ComposeDrawing, FillsTheSolidSideOfEachHalfPlaneInItsColour) {
  // y ≤ -0.5 (normal of length 2) in blue; the x ≥ 0.5 side of a normal (-1, 0) in default
  // black; and one with a zero normal, which is not drawn. 256 pixels per unit, y down.
  Scene scene = load_scene_text(R"(<scene>
    <duration time="0.1"/><integrator type="explicit-euler" dt="0.1"/>
    <particle m="1" px="0" py="0" vx="0" vy="0" fixed="0"/>
    <halfplane px="0" py="-0.5" nx="0" ny="2"/>
    <halfplane px="0.5" py="0" nx="-1" ny="0"/>
    <halfplane px="0" py="0" nx="0" ny="0"/>
    <halfplanecolor i="0" r="0" g="0" b="1"/>
  </scene>)",
                                "planes.xml");
  const Drawing d =
      compose_drawing(scene, scene.initial, PathHistory(scene), Camera{0, 0, 1}, 512, 512);
  ASSERT_EQ(d.regions.size(), 2u);
  EXPECT_EQ(d.regions[0].color, (Color{0, 0, 1}));
  EXPECT_EQ(d.regions[1].color, (Color{0, 0, 0}));
  // The floor covers pixel rows 384..512, the wall columns 384..512.
  for (const Point2& c : d.regions[0].corners) EXPECT_GE(c.y, 384.0 - 1e-9);
  for (const Point2& c : d.regions[1].corners) EXPECT_GE(c.x, 384.0 - 1e-9);
  EXPECT_EQ(d.regions[0].corners.size(), 4u);
}

/// A triangle stretched 20% along x (rest corners (0,0), (1,0), (0,1)) and a bent hinge
/// (θ = π/2 against θ0 = 0), 256 pixels per unit.
Scene elastic_scene() {
  return load_scene_text(R"(<scene>
    <duration time="0.1"/><integrator type="symplectic-euler" dt="0.1"/>
    <particle m="1" px="0" py="0" vx="0" vy="0" fixed="0"/>
    <particle m="1" px="1.2" py="0" vx="0" vy="0" fixed="0"/>
    <particle m="1" px="0" py="1" vx="0" vy="0" fixed="0"/>
    <particle m="1" px="-1" py="0" vx="0" vy="0" fixed="0"/>
    <particle m="1" px="-1" py="-1" vx="0" vy="0" fixed="0"/>
    <elasticbodycstforce i1="0" i2="1" i3="2" youngsmodulus="10" poissonratio="0.3"
                         xb2x="1.0"/>
    <elasticbodybendingforce i1="0" i2="3" i3="4" alpha="1" theta0="0"/>
  </scene>)",
                         "elastic.xml");
}

TEST(ComposeDrawing, FillsElasticTrianglesAndDrawsHingesPlainByDefault) {
  const Scene scene = elastic_scene();
  const Drawing d =
      compose_drawing(scene, scene.initial, PathHistory(scene), Camera{0, 0, 1}, 512, 512);
  // In the forces' summation order (bending before triangles): the hinge's two capsules and
  // the disc at its middle particle, then the triangle.
  ASSERT_EQ(d.shapes.size(), 4u);
  const auto* triangle = std::get_if<Triangle>(&d.shapes[3]);
  ASSERT_NE(triangle, nullptr);
  EXPECT_EQ(triangle->color, kPlainTriangleColor);
  EXPECT_DOUBLE_EQ(triangle->corners[1].x, 256.0 + 1.2 * 256.0);
  EXPECT_DOUBLE_EQ(triangle->corners[2].y, 256.0 - 256.0);
  EXPECT_GT(triangle->outline_width, 0.0);
  const auto* arm = std::get_if<Capsule>(&d.shapes[0]);
  ASSERT_NE(arm, nullptr);
  EXPECT_EQ(arm->color, kPlainHingeColor);
  EXPECT_DOUBLE_EQ(arm->a.x, 256.0);                // particle 0
  EXPECT_DOUBLE_EQ(arm->b.x, 256.0 - 256.0);        // the hinge, particle 3
  ASSERT_NE(std::get_if<Capsule>(&d.shapes[1]), nullptr);
  const auto* hinge = std::get_if<Disc>(&d.shapes[2]);
  ASSERT_NE(hinge, nullptr);
  EXPECT_DOUBLE_EQ(hinge->center.x, 0.0);
  EXPECT_EQ(d.text.size(), 1u);  // the time only: plain colours need no legend
}

TEST(ComposeDrawing, ColoursElasticElementsByStrainOrEnergyWithALegend) {
  const Scene scene = elastic_scene();
  Overlay overlay;
  overlay.elements.by = ElementColoring::kStrain;
  const Drawing d = compose_drawing(scene, scene.initial, PathHistory(scene), Camera{0, 0, 1},
                                    512, 512, overlay);
  ASSERT_EQ(d.shapes.size(), 4u);
  // Stretched by 0.2, beyond the default scale 0.1: full red. The hinge is bent by π/2 (the
  // turn from (-1, 0) to (0, -1) is counter-clockwise): full red too.
  EXPECT_EQ(std::get<Triangle>(d.shapes[3]).color, strain_color(1.0, 1.0));
  EXPECT_EQ(std::get<Capsule>(d.shapes[0]).color, strain_color(1.0, 1.0));
  ASSERT_EQ(d.text.size(), 2u);
  EXPECT_EQ(d.text[1], "strain: red +0.1, blue -0.1");
  // With a scale of 0.4 the triangle is half way to red.
  overlay.elements.scale = 0.4;
  const Drawing half = compose_drawing(scene, scene.initial, PathHistory(scene),
                                       Camera{0, 0, 1}, 512, 512, overlay);
  const Color shown = std::get<Triangle>(half.shapes[3]).color;
  const Color halfway = strain_color(0.5, 1.0);
  EXPECT_NEAR(shown.r, halfway.r, 1e-12);
  EXPECT_NEAR(shown.g, halfway.g, 1e-12);
  EXPECT_NEAR(shown.b, halfway.b, 1e-12);
  // By energy, scaled by the picture's largest density: the triangle's
  // E/(2(1 - ν²)) εxx² = 10/1.82 · 0.44² ≈ 1.064 J/m² beats the hinge's (π/2)²/(2·2²) ≈ 0.308 J/m.
  overlay.elements = {ElementColoring::kEnergy, 0.0};
  const Drawing energy = compose_drawing(scene, scene.initial, PathHistory(scene),
                                         Camera{0, 0, 1}, 512, 512, overlay);
  const double triangle_density = 10.0 / 1.82 * 0.44 * 0.44;
  const double hinge_density = (std::numbers::pi / 2) * (std::numbers::pi / 2) / 8.0;
  EXPECT_EQ(std::get<Triangle>(energy.shapes[3]).color, energy_color(1.0, 1.0));
  const Color hinge = std::get<Capsule>(energy.shapes[0]).color;
  const Color expected = energy_color(hinge_density / triangle_density, 1.0);
  EXPECT_NEAR(hinge.r, expected.r, 1e-12);
  EXPECT_NEAR(hinge.g, expected.g, 1e-12);
  EXPECT_EQ(energy.text[1], "energy density: dark red 1.06");
}

TEST(ElementColors, StrainRunsFromBlueThroughGreyToRedAndEnergyFromPaleToDark) {
  EXPECT_EQ(strain_color(0.0, 0.1), (Color{0.86, 0.86, 0.86}));
  EXPECT_EQ(strain_color(0.1, 0.1), (Color{0.71, 0.02, 0.15}));
  EXPECT_EQ(strain_color(5.0, 0.1), strain_color(0.1, 0.1));  // saturates
  EXPECT_EQ(strain_color(-0.1, 0.1), (Color{0.23, 0.30, 0.75}));
  const Color quarter = strain_color(0.025, 0.1);
  EXPECT_NEAR(quarter.r, 0.86 + 0.25 * (0.71 - 0.86), 1e-15);
  EXPECT_EQ(energy_color(0.0, 2.0), (Color{1.0, 0.97, 0.78}));
  EXPECT_EQ(energy_color(2.0, 2.0), (Color{0.50, 0.0, 0.15}));
  EXPECT_EQ(energy_color(0.5, 2.0), (Color{0.99, 0.55, 0.24}));  // sqrt(1/4) = 1/2: the middle
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(strain_color(nan, 0.1), (Color{0, 0, 0}));
  EXPECT_EQ(energy_color(nan, 0.1), (Color{0, 0, 0}));
}

TEST(FormatTime, ShowsEnoughDecimalsForTheTimeStep) {
  EXPECT_EQ(format_time(1.5, 0.01), "t = 1.50");
  EXPECT_EQ(format_time(1.5, 0.1), "t = 1.50");
  EXPECT_EQ(format_time(0.125, 0.005), "t = 0.125");
  EXPECT_EQ(format_time(0.0001, 1e-4), "t = 0.0001");
  EXPECT_EQ(format_time(2.0, 1e-9), "t = 2.000000");
}

TEST(TextColorFor, ContrastsWithTheBackground) {
  EXPECT_EQ(text_color_for({1, 1, 1}), (Color{0, 0, 0}));
  EXPECT_EQ(text_color_for({0, 0, 0}), (Color{1, 1, 1}));
  EXPECT_EQ(text_color_for({0.0, 0.0, 1.0}), (Color{1, 1, 1}));  // dark blue
  EXPECT_EQ(text_color_for({1.0, 1.0, 0.0}), (Color{0, 0, 0}));  // yellow
}

}  // namespace
}  // namespace fosssim

namespace fosssim::testing {
namespace {

// Rigid bodies (docs/rigid-bodies.md): a hull is a filled region in its body's colour with one
// capsule of the body's radius per edge; a spring is a thin capsule between its ends.
TEST(ComposeDrawing, RigidBodiesAreFilledHullsAndSpringsAreLines) {
  const Scene scene = load_scene_text(R"(<scene>
  <simtype type="rigid-body"/>
  <duration time="1"/>
  <rigidbodyintegrator type="explicit-euler" dt="0.1"/>
  <rigidbodyvertex x="-1" y="1" m="1"/>
  <rigidbodyvertex x="1" y="1" m="1"/>
  <rigidbodyvertex x="1" y="-1" m="1"/>
  <rigidbodyvertex x="-1" y="-1" m="1"/>
  <rigidbody p="0" p="1" p="2" p="3" vx="0" vy="0" omega="0" r="0.25"/>
  <rigidbodyspringforce i="0" pix="1" piy="1" j="-1" pjx="3" pjy="1" k="1" l0="1"/>
  <rigidbodycolor body="0" r="0" g="0" b="1"/>
  <rigidbodyspringcolor spring="0" r="1" g="0" b="0"/>
</scene>)", "rigid.xml");
  const PathHistory paths(scene);
  const Camera camera{0.0, 0.0, 4.0};  // 4 world units in 256 pixels: 64 pixels per unit
  const Drawing d = compose_drawing(scene, scene.initial, paths, camera, 512, 512);
  ASSERT_EQ(d.regions.size(), 1u);
  EXPECT_EQ(d.regions[0].color, (Color{0, 0, 1}));
  ASSERT_EQ(d.regions[0].corners.size(), 4u);
  EXPECT_NEAR(d.regions[0].corners[1].x, 256 + 64, 1e-9);
  EXPECT_NEAR(d.regions[0].corners[1].y, 256 - 64, 1e-9);
  ASSERT_EQ(d.edges.size(), 5u);  // four hull edges, one spring
  EXPECT_NEAR(d.edges[0].radius, 0.25 * 64, 1e-9);
  EXPECT_EQ(d.edges[4].color, (Color{1, 0, 0}));
  EXPECT_NEAR(d.edges[4].b.x, 256 + 3 * 64, 1e-9);
  EXPECT_TRUE(d.particles.empty());
}

// Contact (a scene with <rigidbodycollisionhandling>): each contact's two points as small dark
// red dots and its normal as a short line from between them, pointing from body i0 to i1.
TEST(ComposeDrawing, RigidBodyContactsAreDotsWithNormals) {
  const std::string text = R"(<scene>
  <simtype type="rigid-body"/>
  <duration time="1"/>
  <rigidbodyintegrator type="explicit-euler" dt="0.1"/>
  <rigidbodyvertex x="-3" y="0" m="1"/>
  <rigidbodyvertex x="3" y="0" m="1"/>
  <rigidbodyvertex x="3" y="-1" m="1"/>
  <rigidbodyvertex x="-3" y="-1" m="1"/>
  <rigidbodyvertex x="-1" y="2.15" m="1"/>
  <rigidbodyvertex x="1" y="2.15" m="1"/>
  <rigidbodyvertex x="1" y="0.15" m="1"/>
  <rigidbodyvertex x="-1" y="0.15" m="1"/>
  <rigidbody p="0" p="1" p="2" p="3" vx="0" vy="0" omega="0" r="0.1" fixed="1"/>
  <rigidbody p="4" p="5" p="6" p="7" vx="0" vy="0" omega="0" r="0.1"/>
  <!--contact-->
</scene>)";
  const auto drawing_of = [&](const std::string& handling) {
    std::string scene_text = text;
    scene_text.replace(scene_text.find("<!--contact-->"), 14, handling);
    const Scene scene = load_scene_text(scene_text, "contact.xml");
    const PathHistory paths(scene);
    return compose_drawing(scene, scene.initial, paths, Camera{0.0, 0.0, 4.0}, 512, 512);
  };
  EXPECT_TRUE(drawing_of("").particles.empty());
  const Drawing d =
      drawing_of(R"(<rigidbodycollisionhandling detection="all-pairs" response="lcp"/>)");
  // Two contacts (the box's bottom corners, 0.15 above the floor): two dots and a normal each.
  ASSERT_EQ(d.particles.size(), 4u);
  ASSERT_EQ(d.edges.size(), 8u + 2u);  // the hulls' edges, then the normals
  // The box's bottom-right corner (1, 0.15): the dot on the floor at (1, 0.1) (64 pixels per
  // unit), the normal pointing up (from the floor, body 0, to the box) on the picture.
  EXPECT_NEAR(d.particles[2].center.x, 256 + 64 * 1.0, 1e-9);
  EXPECT_NEAR(d.particles[2].center.y, 256 - 64 * 0.1, 1e-9);
  const Capsule& normal = d.edges[9];
  EXPECT_NEAR(normal.a.x, normal.b.x, 1e-9);
  EXPECT_LT(normal.b.y, normal.a.y);
}

}  // namespace
}  // namespace fosssim::testing
