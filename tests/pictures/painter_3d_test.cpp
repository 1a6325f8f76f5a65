// Pictures of small 3D scenes: the painted pixels where the drawing says, nearer shapes over
// farther ones, no seams between the triangles of a surface, and SVG files that are valid XML.

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <utility>
#include <vector>

#include "pictures/cairo_painter.h"
#include "render/drawing_3d.h"
#include "support/scene_builder.h"
#include "support/scratch_folder.h"
#include "support/tiny_scenes.h"

namespace fosssim {
namespace {

constexpr double kOneColourLevel = 1.0 / 255.0 + 1e-9;
constexpr Color kWhite{1, 1, 1};

/// One triangle facing the camera, (-1, -1, 0), (1, -1, 0), (0, 1, 0): pixels (204.8, 307.2),
/// (307.2, 307.2), (256, 204.8); a particle just in front of it at (0, -0.5, 0.5) and one just
/// behind at (0.5, 0, -0.5), both of radius 0.1.
Scene triangle_scene() {
  Scene scene =
      testing::particles_at({{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}, {0, -0.5, 0.5}, {0.5, 0, -0.5}});
  scene.appearance.triangles = {{0, 1, 2}};
  scene.appearance.particle_color = {
      {0.2, 0.4, 0.8}, {0.2, 0.4, 0.8}, {0.2, 0.4, 0.8}, {1, 0, 0}, {0, 1, 0}};
  scene.model.particle_radius = {0.05, 0.05, 0.05, 0.1, 0.1};
  return scene;
}

Drawing draw(const Scene& scene, const OrbitCamera& camera) {
  Overlay overlay;
  overlay.show_time = false;
  return compose_drawing_3d(scene, compute_scene_parts_3d(scene), scene.initial, PathHistory(scene),
                            camera, 512, 512, overlay);
}

TEST(Render3D, PaintsTheShadedTriangleAtItsCentroid) {
  const Drawing drawing = draw(triangle_scene(), testing::front_camera());
  const Triangle* triangle = nullptr;
  for (const Shape& shape : drawing.shapes) {
    if (const auto* t = std::get_if<Triangle>(&shape)) triangle = t;
  }
  ASSERT_NE(triangle, nullptr);
  const Image image = render_image(drawing);
  // The centroid (0, -1/3, 0) is at pixel (256, 273.07); pixel (256, 273) holds it.
  EXPECT_LE(color_distance(image.color_at(256, 273), triangle->color), kOneColourLevel);
  EXPECT_GT(color_distance(triangle->color, kWhite), 0.3);
  EXPECT_LE(color_distance(image.color_at(20, 20), kWhite), kOneColourLevel);
  EXPECT_LE(color_distance(image.color_at(400, 300), kWhite), kOneColourLevel);
}

TEST(Render3D, PaintsNearerShapesOverFartherOnes) {
  const Image image = render_image(draw(triangle_scene(), testing::front_camera()));
  // The red particle in front of the triangle, at pixel (256, 256 + 0.5 · 256 / 4.5).
  EXPECT_LE(color_distance(image.color_at(256, 284), Color{1, 0, 0}), kOneColourLevel);
  // The green one behind it, at (256 + 0.5 · 256 / 5.5, 256), is hidden by the triangle...
  EXPECT_GT(color_distance(image.color_at(279, 256), Color{0, 1, 0}), 0.3);
  // ...but shows where the triangle does not cover it: 0.1 · 256 / 5.5 = 4.65 pixels right.
  EXPECT_LE(color_distance(image.color_at(283, 256), Color{0, 1, 0}), 0.2);
}

TEST(Render3D, LeavesNoSeamsBetweenTheTrianglesOfASurface) {
  // A square from -1 to 1 of 20 × 20 quads, each two triangles, seen square-on in parallel
  // projection (51.2 pixels per unit): sides of 5 and 7 pixels, so no outlines, and one colour.
  constexpr int kQuads = 20;
  std::vector<Eigen::Vector3d> points;
  for (int r = 0; r <= kQuads; ++r)
    for (int c = 0; c <= kQuads; ++c)
      points.emplace_back(-1.0 + 2.0 * c / kQuads, -1.0 + 2.0 * r / kQuads, 0.0);
  Scene scene = testing::particles_at(points);
  scene.appearance.particle_color.assign(points.size(), Color{0.2, 0.4, 0.8});
  for (int r = 0; r < kQuads; ++r) {
    for (int c = 0; c < kQuads; ++c) {
      const int a = r * (kQuads + 1) + c, b = a + 1, d = a + kQuads + 1, e = d + 1;
      scene.appearance.triangles.push_back({a, b, e});
      scene.appearance.triangles.push_back({a, e, d});
    }
  }
  OrbitCamera camera = testing::front_camera();
  camera.projection = Projection::kOrthographic;
  const Drawing drawing = draw(scene, camera);
  ASSERT_EQ(drawing.shapes.size(), 2u * kQuads * kQuads);
  const Color face = std::get<Triangle>(drawing.shapes[0]).color;
  for (const Shape& shape : drawing.shapes) {
    ASSERT_EQ(std::get<Triangle>(shape).color, face);
    ASSERT_EQ(std::get<Triangle>(shape).outline_width, 0.0);
  }
  // Every pixel inside the square (204.8 to 307.2) shows the face: no background between.
  // Where several triangles overlap a pixel partly, 8-bit compositing of the same colour over
  // itself may round by a level or two; a seam lets white through by up to a quarter (painted
  // without growing the triangles, 5783 of these pixels are off by up to 0.28).
  constexpr double kTwoLevels = 2.0 / 255.0 + 1e-9;
  const Image image = render_image(drawing);
  for (int y = 206; y <= 306; ++y) {
    for (int x = 206; x <= 306; ++x) {
      ASSERT_LE(color_distance(image.color_at(x, y), face), kTwoLevels) << x << ", " << y;
    }
  }
}

/// The membrane scene (support/tiny_scenes.h) drawn through the front camera, coloured `by`.
Drawing draw_membranes(ElementColoring by) {
  const Scene scene = testing::membrane_scene();
  Overlay overlay;
  overlay.show_time = false;
  overlay.elements.by = by;
  return compose_drawing_3d(scene, compute_scene_parts_3d(scene), scene.initial, PathHistory(scene),
                            testing::front_camera(), 512, 512, overlay);
}

/// The first two triangles of a drawing: the membrane scene's stretched and compressed ones.
std::pair<Color, Color> membrane_colors(const Drawing& drawing) {
  std::vector<Color> colors;
  for (const Shape& shape : drawing.shapes) {
    if (const auto* t = std::get_if<Triangle>(&shape)) colors.push_back(t->color);
  }
  EXPECT_EQ(colors.size(), 2u);
  return {colors.at(0), colors.at(1)};
}

TEST(Render3D, PaintsMembranesLightBlueByDefault) {
  const Drawing drawing = draw_membranes(ElementColoring::kPlain);
  const auto [left, right] = membrane_colors(drawing);
  const Image image = render_image(drawing);
  // The centroids' pixels, (179, 273) and (307, 273), show each triangle's shaded colour: the
  // light blue, bluest of its components, and never the background.
  for (const auto& [x, color] : {std::pair{179, left}, std::pair{307, right}}) {
    const Color shown = image.color_at(x, 273);
    EXPECT_LE(color_distance(shown, color), kOneColourLevel) << x;
    EXPECT_GT(shown.b, shown.g) << x;
    EXPECT_GT(shown.g, shown.r) << x;
    EXPECT_GT(color_distance(shown, kWhite), 0.2) << x;
  }
  // Between the two triangles (x = 0, pixel 256) is background.
  EXPECT_LE(color_distance(image.color_at(256, 273), kWhite), kOneColourLevel);
}

TEST(Render3D, PaintsStretchedMembranesRedAndCompressedOnesBlue) {
  const Drawing drawing = draw_membranes(ElementColoring::kStrain);
  const auto [stretched, compressed] = membrane_colors(drawing);
  const Image image = render_image(drawing);
  const Color red = image.color_at(179, 273), blue = image.color_at(307, 273);
  EXPECT_LE(color_distance(red, stretched), kOneColourLevel);
  EXPECT_LE(color_distance(blue, compressed), kOneColourLevel);
  EXPECT_GT(red.r, 3.0 * red.b);
  EXPECT_GT(red.r, 3.0 * red.g);
  EXPECT_GT(blue.b, 2.0 * blue.r);
  EXPECT_GT(blue.b, 2.0 * blue.g);
}

/// The elements named `name` anywhere under `element`.
int count(const tinyxml2::XMLElement* element, const std::string& name) {
  int found = 0;
  for (const auto* child = element->FirstChildElement(); child;
       child = child->NextSiblingElement()) {
    found += (name == child->Name()) + count(child, name);
  }
  return found;
}

TEST(WriteSvg, OfA3DSceneIsValidXml) {
  const testing::ScratchFolder folder;
  const Drawing drawing = draw(triangle_scene(), testing::front_camera());
  write_svg(drawing, folder / "three.svg");
  tinyxml2::XMLDocument document;
  ASSERT_EQ(document.LoadFile((folder / "three.svg").c_str()), tinyxml2::XML_SUCCESS)
      << document.ErrorStr();
  const tinyxml2::XMLElement* svg = document.RootElement();
  ASSERT_STREQ(svg->Name(), "svg");
  // The triangle (filled, then outlined) and the two particles, at least.
  EXPECT_GE(count(svg, "path"), 4);
}

}  // namespace
}  // namespace fosssim
