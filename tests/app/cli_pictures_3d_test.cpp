// Pictures and movies of 3D scenes from the command line, and the --view option.

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <filesystem>
#include <set>
#include <string>

#include "pictures/cairo_painter.h"
#include "support/run_program.h"
#include "support/scratch_folder.h"
#include "support/tiny_scenes.h"

namespace fosssim {
namespace {

class CliPictures3D : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_.write("cloth.xml", testing::kTinyScene3D);
    folder_.write("flat.xml", testing::kTinyScene);
  }
  testing::ProgramResult fosssim(const std::string& arguments) {
    return testing::run_command(
        folder_, "env -u DISPLAY " + testing::quoted(testing::fosssim_program()) + " " + arguments);
  }
  testing::ScratchFolder folder_;
};

/// True for the shaded cloth's colours: blue above red, unlike the background or white.
bool is_cloth(const Color& c) { return c.b > c.r + 0.15 && c.b > 0.3; }

TEST_F(CliPictures3D, PngsShowTheShadedCloth) {
  const auto result = fosssim("-s cloth.xml -d 0 -g 1");
  ASSERT_EQ(result.status, 0) << result.err;
  const Image first = read_png(folder_ / "pngs/frame_00000.png");
  const std::set<std::uint32_t> colours(first.pixels.begin(), first.pixels.end());
  EXPECT_GT(colours.size(), 10u) << "the picture is blank";
  // The cloth's centre, at the fitted camera's target, is in the middle of the picture.
  EXPECT_TRUE(is_cloth(first.color_at(256, 256)));
  EXPECT_LT(color_distance(first.color_at(5, 500), testing::kBackground), 0.01);
  EXPECT_NE(read_png(folder_ / "pngs/frame_00030.png").pixels, first.pixels) << "it falls";
}

// A camera 1e-308 from its target put the cloth at absurd pixel coordinates, which hung Cairo;
// they are now clipped before drawing (pictures/cairo_painter.cpp), and the run ends at once.
TEST_F(CliPictures3D, ACameraAtAnAbsurdDistanceStillDrawsAtOnce) {
  const auto result = testing::run_command(
      folder_, "env -u DISPLAY timeout -k 5 60 " + testing::quoted(testing::fosssim_program()) +
                   " -s cloth.xml -d 0 -q --duration 0 -g 1 -m svgs --view 0,0,1e-308");
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_TRUE(folder_.exists("pngs/frame_00000.png"));
  EXPECT_TRUE(folder_.exists("svgs/frame_00000.svg"));
}

TEST_F(CliPictures3D, ViewSetsTheAnglesAndProjection) {
  ASSERT_EQ(fosssim("-s cloth.xml -d 0 --duration 0 -g 1").status, 0);
  const auto side = fosssim("-s cloth.xml -d 0 --duration 0 -g 1 --png-dir side --view 90,0");
  ASSERT_EQ(side.status, 0) << side.err;
  // Seen edge-on from +x, the cloth is a thin line down the middle: the picture's left and
  // right thirds are background only.
  const Image edge_on = read_png(folder_ / "side/frame_00000.png");
  for (int y = 0; y < 512; y += 4) {
    ASSERT_LT(color_distance(edge_on.color_at(100, y), testing::kBackground), 0.01) << y;
    ASSERT_LT(color_distance(edge_on.color_at(412, y), testing::kBackground), 0.01) << y;
  }
  // Square-on in parallel projection, the fitted cloth spans 1 / 1.3 of the half picture.
  const auto front =
      fosssim("-s cloth.xml -d 0 --duration 0 -g 1 --png-dir front --view 0,0 --orthographic");
  ASSERT_EQ(front.status, 0) << front.err;
  const Image square = read_png(folder_ / "front/frame_00000.png");
  EXPECT_TRUE(is_cloth(square.color_at(256 - 190, 256)));
  EXPECT_TRUE(is_cloth(square.color_at(256 + 190, 256 + 190)));
  EXPECT_LT(color_distance(square.color_at(256 - 205, 256), testing::kBackground), 0.01);
}

TEST_F(CliPictures3D, RejectsAMalformedViewAndAViewOfA2DScene) {
  for (const char* view : {"30", "30,x", "30,20,0", "1,2,3,4", "30,,2"}) {
    const auto result = fosssim(std::string("-s cloth.xml -d 0 -g 1 --view ") + view);
    EXPECT_EQ(result.status, 2) << view;
    EXPECT_NE(result.err.find("--view must be YAW,PITCH"), std::string::npos) << result.err;
  }
  const auto flat = fosssim("-s flat.xml -d 0 -g 1 --view 30,20");
  EXPECT_EQ(flat.status, 2);
  EXPECT_NE(flat.err.find("3D scenes"), std::string::npos) << flat.err;
  EXPECT_FALSE(std::filesystem::exists(folder_ / "pngs"));
}

TEST_F(CliPictures3D, SvgsOfA3DSceneAreValidXml) {
  const auto result = fosssim("-s cloth.xml -d 0 --duration 0.02 -m svgs");
  ASSERT_EQ(result.status, 0) << result.err;
  tinyxml2::XMLDocument document;
  ASSERT_EQ(document.LoadFile((folder_ / "svgs/frame_00002.svg").c_str()), tinyxml2::XML_SUCCESS)
      << document.ErrorStr();
  EXPECT_STREQ(document.RootElement()->Name(), "svg");
}

TEST_F(CliPictures3D, MembranesAreLightBlueOrColouredByStrainOnRequest) {
  // The two membrane triangles of testing::kMembraneScene seen by the front camera (eye at
  // z = 5, 90° field of view): the stretched one's centroid at pixel (179, 273), the
  // compressed one's at (307, 273).
  std::string scene = testing::kMembraneScene;
  scene.insert(scene.rfind("</scene>"),
               R"(<camera3d yaw="0" pitch="0" distance="5" tx="0" ty="0" tz="0" fov="90"/>)");
  folder_.write("membranes.xml", scene);
  ASSERT_EQ(fosssim("-s membranes.xml -d 0 -q -g 1 --png-dir plain").status, 0);
  const Image plain = read_png(folder_ / "plain/frame_00000.png");
  for (int x : {179, 307}) {  // light blue (kPlainTriangleColor 0.62, 0.78, 0.93), shaded
    const Color c = plain.color_at(x, 273);
    EXPECT_TRUE(c.b > c.g && c.g > c.r && c.r > 0.3 && c.b < 0.98) << x;
  }
  const auto result = fosssim("-s membranes.xml -d 0 -q -g 1 --png-dir strain --color-by strain");
  ASSERT_EQ(result.status, 0) << result.err;
  const Image strain = read_png(folder_ / "strain/frame_00000.png");
  const Color red = strain.color_at(179, 273), blue = strain.color_at(307, 273);
  EXPECT_TRUE(red.r > 3.0 * red.g && red.r > 3.0 * red.b) << red.r << " " << red.g << " " << red.b;
  EXPECT_TRUE(blue.b > 2.0 * blue.r && blue.b > 2.0 * blue.g)
      << blue.r << " " << blue.g << " " << blue.b;
}

TEST_F(CliPictures3D, MoviesOfA3DSceneRenderHeadless) {
  if (!testing::on_path("ffmpeg")) GTEST_SKIP() << "ffmpeg is not installed";
  const auto result = fosssim("-s cloth.xml --movie cloth.mp4 --movie-stride 5");
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_GT(std::filesystem::file_size(folder_ / "cloth.mp4"), 1000u);
  if (!testing::on_path("ffprobe")) GTEST_SKIP() << "ffprobe is not installed";
  // The default 512x512 at 30 frames per second; 30 steps of 0.01 s, frames at steps 0, 5,
  // ..., 30: 7.
  EXPECT_EQ(testing::probe_movie(folder_, "cloth.mp4"), "512,512,30/1,7,");
}

}  // namespace
}  // namespace fosssim
