#include "pictures/cairo_painter.h"

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include "support/pixel_counts.h"
#include "support/scratch_folder.h"
#include "support/tiny_scenes.h"

namespace fosssim {
namespace {

using testing::kBackground;
using testing::kGreen;
using testing::kRed;

/// One 8-bit step: how far a correctly painted pixel may be from the exact colour.
constexpr double kOneLevel = 1.0 / 255.0 + 1e-9;

TEST(RenderImage, PutsTheExpectedColoursAtTheExpectedPixels) {
  const Scene scene = testing::tiny_scene();
  const Image image = render_image(testing::tiny_drawing(scene));
  ASSERT_EQ(image.width, 512);
  ASSERT_EQ(image.height, 512);
  EXPECT_LE(color_distance(image.color_at(128, 256), kRed), kOneLevel);
  EXPECT_LE(color_distance(image.color_at(384, 192), Appearance::kDefaultParticleColor), kOneLevel);
  EXPECT_LE(color_distance(image.color_at(256, 224), kGreen), kOneLevel);
  EXPECT_LE(color_distance(image.color_at(500, 500), kBackground), kOneLevel);
  EXPECT_LE(color_distance(image.color_at(5, 5), kBackground), kOneLevel);
  // Just outside particle 0 (40 pixels above its centre) and 39 pixels from the edge's axis.
  EXPECT_LE(color_distance(image.color_at(128, 216), kBackground), kOneLevel);
  // Every pixel is opaque.
  for (std::uint32_t pixel : image.pixels) ASSERT_EQ(pixel >> 24, 0xffu);
}

// Sizes that made Cairo loop for minutes over gigabytes (a radius of 1e300 pixels, points at
// 1e12) are brought within its reach: each picture below is drawn at once, and right.
TEST(RenderImage, DrawsAbsurdSizesQuicklyAndRight) {
  const Color kBlue{0, 0, 1};
  const auto picture = [](const auto& fill) {
    Drawing drawing;
    drawing.width = 64;
    drawing.height = 64;
    drawing.background = Color{0, 0, 0};
    fill(drawing);
    return render_image(drawing);
  };
  // A disc of radius 1e300 around the picture covers it.
  Image image = picture([&](Drawing& d) { d.particles.push_back({{32, 32}, 1e300, kRed}); });
  EXPECT_EQ(testing::count_color(image, kRed), 64 * 64);
  // One around a point 1e9 pixels to the left, reaching 20 pixels into the picture, covers the
  // left 20 columns: its rim there is a straight line at x = 20.
  image = picture([&](Drawing& d) { d.particles.push_back({{-1e9, 32}, 1e9 + 20, kRed}); });
  EXPECT_LE(color_distance(image.color_at(18, 10), kRed), kOneLevel);
  EXPECT_LE(color_distance(image.color_at(21, 50), Color{0, 0, 0}), kOneLevel);
  // A ring of radius 1e300 whose stroke misses the picture draws nothing; non-finite shapes too.
  image = picture([&](Drawing& d) {
    d.marks.push_back({{32, 32}, 1e300, 2.0, kRed});
    d.particles.push_back({{std::nan(""), 3}, 5, kRed});
    d.edges.push_back({{0, 0}, {std::numeric_limits<double>::infinity(), 3}, 2, kRed});
  });
  EXPECT_EQ(testing::count_color(image, Color{0, 0, 0}), 64 * 64);
  // An edge from far away (1e12 pixels) crossing the picture, and a huge triangle and path.
  image = picture([&](Drawing& d) {
    d.edges.push_back({{-1e12, 32}, {1e12, 32}, 4, kGreen});
    d.shapes.push_back(
        Triangle{{Point2{-1e15, -1e15}, Point2{1e15, -1e15}, Point2{0, 20}}, kBlue, 0.0, kBlue});
    d.paths.push_back({{{32, -1e200}, {32, 1e200}}, 2.0, kRed});
  });
  EXPECT_LE(color_distance(image.color_at(5, 10), kBlue), kOneLevel);
  EXPECT_LE(color_distance(image.color_at(5, 32), kGreen), kOneLevel);
  EXPECT_LE(color_distance(image.color_at(32, 50), kRed), kOneLevel);
  EXPECT_LE(color_distance(image.color_at(5, 50), Color{0, 0, 0}), kOneLevel);
}

TEST(RenderImage, AntiAliasesTheOutlines) {
  const Scene scene = testing::tiny_scene();
  const Image image = render_image(testing::tiny_drawing(scene));
  // Particle 0's left edge is at x = 102.4: pixel 102 is 60 % covered.
  const Color mixed = image.color_at(102, 255);
  EXPECT_GT(color_distance(mixed, kRed), 0.2);
  EXPECT_GT(color_distance(mixed, kBackground), 0.2);
  EXPECT_GT(mixed.r, kBackground.r);
  EXPECT_LT(mixed.r, kRed.r);
}

TEST(RenderImage, DrawsParticlesOverEdgesAndMarksOverParticles) {
  const Scene scene = testing::tiny_scene();
  Overlay overlay;
  overlay.show_time = false;
  overlay.marks = {{0, Color{0, 0, 1}}};
  const Drawing drawing =
      compose_drawing(scene, scene.initial, PathHistory(scene), Camera{0, 0, 1}, 512, 512, overlay);
  const Image image = render_image(drawing);
  // The edge starts at particle 0's centre, but the particle is painted over it.
  EXPECT_LE(color_distance(image.color_at(140, 253), kRed), kOneLevel);
  // The ring: radius 25.6 + 3 pixels around (128, 256), 2 pixels wide.
  EXPECT_LE(color_distance(image.color_at(128, 256 + 28), Color{0, 0, 1}), 0.3);
}

TEST(WritePng, WritesWhatRenderImagePaintsAndNoTemporaryFile) {
  const testing::ScratchFolder folder;
  const Scene scene = testing::tiny_scene();
  const Drawing drawing = testing::tiny_drawing(scene);
  write_png(drawing, folder / "tiny.png");
  EXPECT_FALSE(std::filesystem::exists(folder / "tiny.png.partial"));
  const Image read = read_png(folder / "tiny.png");
  const Image painted = render_image(drawing);
  EXPECT_EQ(read.width, 512);
  EXPECT_EQ(read.height, 512);
  EXPECT_EQ(read.pixels, painted.pixels);
}

TEST(WritePng, ReportsAnUnwritablePath) {
  const Scene scene = testing::tiny_scene();
  try {
    write_png(testing::tiny_drawing(scene), "/nonexistent-folder/x.png");
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::kCannotWrite);
    EXPECT_NE(std::string(error.what()).find("/nonexistent-folder/x.png"), std::string::npos);
  }
}

/// The elements named `name` anywhere under `element`.
void collect(const tinyxml2::XMLElement* element, const std::string& name,
             std::vector<const tinyxml2::XMLElement*>& found) {
  for (const auto* child = element->FirstChildElement(); child;
       child = child->NextSiblingElement()) {
    if (name == child->Name()) found.push_back(child);
    collect(child, name, found);
  }
}

TEST(WriteSvg, IsValidXmlWithTheExpectedShapes) {
  const testing::ScratchFolder folder;
  const Scene scene = testing::tiny_scene();
  write_svg(testing::tiny_drawing(scene), folder / "tiny.svg");
  tinyxml2::XMLDocument document;
  ASSERT_EQ(document.LoadFile((folder / "tiny.svg").c_str()), tinyxml2::XML_SUCCESS)
      << document.ErrorStr();
  const tinyxml2::XMLElement* svg = document.RootElement();
  ASSERT_STREQ(svg->Name(), "svg");
  EXPECT_STREQ(svg->Attribute("width"), "512px");
  EXPECT_STREQ(svg->Attribute("height"), "512px");

  std::vector<const tinyxml2::XMLElement*> rects, paths;
  collect(svg, "rect", rects);
  collect(svg, "path", paths);
  ASSERT_EQ(rects.size(), 1u);  // the background
  EXPECT_NE(std::string(rects[0]->Attribute("style")).find("fill:rgb(10%,10%,20%)"),
            std::string::npos);
  int red_discs = 0, orange_discs = 0, green_capsules = 0;
  for (const auto* path : paths) {
    const char* style = path->Attribute("style");
    if (style == nullptr) continue;
    const std::string s = style;
    if (s.find("fill:rgb(100%,0%,0%)") != std::string::npos) ++red_discs;
    if (s.find("fill:rgb(65.1%,29.4%,0%)") != std::string::npos) ++orange_discs;
    if (s.find("stroke:rgb(0%,100%,0%)") != std::string::npos &&
        s.find("stroke-width:25.6") != std::string::npos &&
        s.find("stroke-linecap:round") != std::string::npos) {
      ++green_capsules;
    }
  }
  EXPECT_EQ(red_discs, 1);
  EXPECT_EQ(orange_discs, 1);
  EXPECT_EQ(green_capsules, 1);
}

TEST(PictureFormatFor, ChoosesSvgByExtension) {
  EXPECT_EQ(picture_format_for("a/b.svg"), PictureFormat::kSvg);
  EXPECT_EQ(picture_format_for("B.SVG"), PictureFormat::kSvg);
  EXPECT_EQ(picture_format_for("b.png"), PictureFormat::kPng);
  EXPECT_EQ(picture_format_for("svg"), PictureFormat::kPng);
}

}  // namespace
}  // namespace fosssim
