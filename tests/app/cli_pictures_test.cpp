#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <filesystem>

#include "pictures/cairo_painter.h"
#include "support/pixel_counts.h"
#include "support/run_program.h"
#include "support/scratch_folder.h"
#include "support/tiny_scenes.h"

namespace fosssim {
namespace {

class CliPictures : public ::testing::Test {
 protected:
  void SetUp() override { folder_.write("scene.xml", testing::kTinyScene); }
  testing::ProgramResult fosssim(const std::string& arguments) {
    return testing::run_command(folder_,
                                testing::quoted(testing::fosssim_program()) + " " + arguments);
  }
  std::vector<std::string> files_in(const std::string& directory) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(folder_ / directory)) {
      names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }
  testing::ScratchFolder folder_;
};

// A tiny viewport and a huge radius used to hang inside Cairo with over 1 GB, deaf to SIGTERM;
// the sizes are now brought within Cairo's reach before drawing (pictures/cairo_painter.cpp).
TEST_F(CliPictures, AbsurdDrawnSizesAreDrawnAtOnce) {
  folder_.write("huge.xml", R"(<scene>
  <duration time="0.02"/><integrator type="explicit-euler" dt="0.01"/>
  <particle m="1" px="0" py="0" vx="0" vy="0" fixed="1" radius="1e300"/>
  <particle m="1" px="1e-40" py="1e-45" vx="0" vy="0" fixed="1" radius="1e-300"/>
  <edge i="0" j="1" radius="1e200"/>
  <particlepath i="1" duration="1" r="1" g="1" b="0"/>
  <viewport cx="0" cy="0" size="1e-50"/>
</scene>)");
  const auto result = testing::run_command(
      folder_, "timeout -k 5 60 " + testing::quoted(testing::fosssim_program()) +
                   " -s huge.xml -d 0 -q -g 1 -m svg --size 64x64");
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_EQ(files_in("pngs").size(), 3u);
  EXPECT_EQ(files_in("svg").size(), 3u);
}

TEST_F(CliPictures, PngPerStepGoesIntoPngs) {
  const auto result = fosssim("-s scene.xml -d 0 -g 1");
  ASSERT_EQ(result.status, 0) << result.err;
  const auto names = files_in("pngs");
  ASSERT_EQ(names.size(), testing::kTinySteps + 1u);  // the initial state and every step
  EXPECT_EQ(names.front(), "frame_00000.png");
  EXPECT_EQ(names.back(), "frame_00030.png");
  const Image first = read_png(folder_ / "pngs/frame_00000.png");
  EXPECT_EQ(first.width, 512);
  EXPECT_LT(color_distance(first.color_at(128, 256), testing::kRed), 0.01);
  EXPECT_LT(color_distance(first.color_at(500, 500), testing::kBackground), 0.01);
  // The particle moves up, so the last picture differs from the first.
  const Image last = read_png(folder_ / "pngs/frame_00030.png");
  EXPECT_NE(last.pixels, first.pixels);
}

TEST_F(CliPictures, PngFolderAndSizeCanBeChosen) {
  const auto result = fosssim("-s scene.xml -d 0 -g 1 --png-dir out/frames --size 320x240");
  ASSERT_EQ(result.status, 0) << result.err;
  const Image image = read_png(folder_ / "out/frames/frame_00003.png");
  EXPECT_EQ(image.width, 320);
  EXPECT_EQ(image.height, 240);
  // Same camera, 240 pixels tall: 120 per unit, centre (160, 120); particle 0 at (100, 120).
  EXPECT_LT(color_distance(read_png(folder_ / "out/frames/frame_00000.png").color_at(100, 120),
                           testing::kRed),
            0.01);
}

TEST_F(CliPictures, ElasticTrianglesAreFilledAndColouredByStrainOnRequest) {
  // A triangle stretched 20% along x (rest corners (0,0), (1,0), (0,1)), viewport 2 units
  // tall on 512 pixels: its inside point (0.3, 0.3) is pixel (332.8, 179.2).
  folder_.write("triangle.xml", R"(<scene>
  <duration time="0.01"/><integrator type="symplectic-euler" dt="0.01"/>
  <viewport cx="0" cy="0" size="1"/>
  <particle m="1" px="0" py="0" vx="0" vy="0" fixed="1" radius="0.01"/>
  <particle m="1" px="1.2" py="0" vx="0" vy="0" fixed="1" radius="0.01"/>
  <particle m="1" px="0" py="1" vx="0" vy="0" fixed="1" radius="0.01"/>
  <elasticbodycstforce i1="0" i2="1" i3="2" youngsmodulus="10" poissonratio="0.3" xb2x="1"/>
</scene>)");
  const Color plain{0.62, 0.78, 0.93};      // kPlainTriangleColor
  const Color stretched{0.71, 0.02, 0.15};  // full red: 0.2 beyond the default scale 0.1
  ASSERT_EQ(fosssim("-s triangle.xml -d 0 -q -g 1 --png-dir plain").status, 0);
  EXPECT_LT(color_distance(read_png(folder_ / "plain/frame_00000.png").color_at(333, 179), plain),
            0.01);
  ASSERT_EQ(fosssim("-s triangle.xml -d 0 -q -g 1 --png-dir strain --color-by strain").status, 0);
  EXPECT_LT(
      color_distance(read_png(folder_ / "strain/frame_00000.png").color_at(333, 179), stretched),
      0.01);
  // With --color-scale 0.4 the stretch of 0.2 is half way from grey to red.
  ASSERT_EQ(
      fosssim("-s triangle.xml -d 0 -q -g 1 --png-dir half --color-by strain --color-scale 0.4")
          .status,
      0);
  const Color half{0.5 * (0.86 + 0.71), 0.5 * (0.86 + 0.02), 0.5 * (0.86 + 0.15)};
  EXPECT_LT(color_distance(read_png(folder_ / "half/frame_00000.png").color_at(333, 179), half),
            0.01);
  const auto bad = fosssim("-s triangle.xml -d 0 -q -g 1 --color-by stress");
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.err.find("--color-by"), std::string::npos) << bad.err;
}

TEST_F(CliPictures, SvgPerStepIsValidXml) {
  const auto result = fosssim("-s scene.xml -d 0 -m svgs");
  ASSERT_EQ(result.status, 0) << result.err;
  const auto names = files_in("svgs");
  ASSERT_EQ(names.size(), testing::kTinySteps + 1u);
  for (const auto& name : names) {
    tinyxml2::XMLDocument document;
    ASSERT_EQ(document.LoadFile((folder_ / ("svgs/" + name)).c_str()), tinyxml2::XML_SUCCESS)
        << name;
    EXPECT_STREQ(document.RootElement()->Name(), "svg");
  }
}

TEST_F(CliPictures, PicturesAndTrajectoryInOneRun) {
  const auto result = fosssim("-s scene.xml -d 0 -g 1 -m svgs -o run.bin");
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_EQ(std::filesystem::file_size(folder_ / "run.bin"),
            (testing::kTinySteps + 1u) * 2 * 4 * 8);
  EXPECT_EQ(files_in("pngs").size(), testing::kTinySteps + 1u);
}

TEST_F(CliPictures, PicturesCannotBeCombinedWithGrading) {
  const auto result = fosssim("-s scene.xml -d 0 -i run.bin -g 1");
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.err.find("cannot be combined with grading"), std::string::npos) << result.err;
}

TEST_F(CliPictures, BadSizeIsACommandLineError) {
  const auto result = fosssim("-s scene.xml -d 0 -g 1 --size 512by512");
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.err.find("--size"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(folder_ / "pngs"));
}

TEST_F(CliPictures, AnUnwritablePictureFolderIsAnIoError) {
  folder_.write("blocker", "a file where the folder should be");
  const auto result = fosssim("-s scene.xml -d 0 -g 1 --png-dir blocker/pngs");
  EXPECT_EQ(result.status, 4);
  EXPECT_NE(result.err.find("blocker/pngs"), std::string::npos) << result.err;
}

TEST_F(CliPictures, FountainRunsAreReproducibleAndGradeAsPassed) {
  folder_.write("fountain.xml", R"(<scene>
    <duration time="2.0"/><integrator type="explicit-euler" dt="0.01"/>
    <scenetag tag="ParticleFountain"/>
    <particle m="1" px="0" py="0" vx="0.3" vy="2" fixed="0" tag="teleport"/>
    <particle m="1" px="0.1" py="0" vx="-0.3" vy="3" fixed="0" tag="teleport"/>
    <simplegravity fx="0" fy="-9.81"/></scene>)");
  ASSERT_EQ(fosssim("-s fountain.xml -d 0 -o a.bin").status, 0);
  ASSERT_EQ(fosssim("-s fountain.xml -d 0 -o b.bin -g 1").status, 0);
  EXPECT_EQ(testing::read_file(folder_ / "a.bin"), testing::read_file(folder_ / "b.bin"));
  const auto graded = fosssim("-s fountain.xml -d 0 -i a.bin");
  EXPECT_EQ(graded.status, 0) << graded.out << graded.err;
  EXPECT_NE(graded.out.find("Overall success: Passed."), std::string::npos);
}

// A particle that leaves its first state's box: with no <viewport>, pictures frame what the
// whole run covers (--frame run, the default), so the last picture still shows it; fitted to the
// first state only (--frame first) it has left the picture.
TEST_F(CliPictures, PicturesFrameTheWholeRun) {
  folder_.write("leaving.xml", R"(<scene>
  <duration time="1"/><integrator type="explicit-euler" dt="0.1"/>
  <particle m="1" px="0" py="0" vx="0" vy="0" fixed="1" radius="0.05"/>
  <particle m="1" px="1" py="0" vx="2" vy="0" fixed="0" radius="0.05"/>
  <particlecolor i="1" r="1" g="0" b="0"/>
</scene>)");
  ASSERT_EQ(fosssim("-s leaving.xml -d 0 -g 1 --png-dir run").status, 0);
  ASSERT_EQ(fosssim("-s leaving.xml -d 0 -g 1 --png-dir first --frame first").status, 0);
  EXPECT_GT(testing::count_color(read_png(folder_ / "run/frame_00010.png"), testing::kRed), 20);
  EXPECT_EQ(testing::count_color(read_png(folder_ / "first/frame_00010.png"), testing::kRed), 0);
  // Both show the particle at the start.
  EXPECT_GT(testing::count_color(read_png(folder_ / "run/frame_00000.png"), testing::kRed), 20);
  EXPECT_GT(testing::count_color(read_png(folder_ / "first/frame_00000.png"), testing::kRed), 20);
  EXPECT_EQ(fosssim("-s leaving.xml -d 0 -g 1 --frame sometimes").status, 2);
}

}  // namespace
}  // namespace fosssim
