// The window under a virtual X server: it opens, shows the scene, and shows exactly what the
// headless pictures show.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>

#include "io/scene_loader.h"
#include "io/trajectory_file.h"
#include "pictures/cairo_painter.h"
#include "support/run_program.h"
#include "support/scratch_folder.h"
#include "support/tiny_scenes.h"
#include "support/xvfb_server.h"

namespace fosssim {
namespace {

using testing::kTinyScene;

class WindowTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!testing::on_path("Xvfb")) {
      GTEST_SKIP() << "Xvfb is not installed (tools/install-deps.sh installs it)";
    }
    server_ = testing::XvfbServer::start();
    ASSERT_TRUE(server_.has_value()) << "Xvfb is installed but did not start";
    scene_ = folder_.write("scene.xml", kTinyScene);
  }

  testing::ProgramResult fosssim(const std::string& arguments) {
    return testing::run_command(folder_, "DISPLAY=" + server_->display() + " " +
                                             testing::quoted(testing::fosssim_program()) + " " +
                                             arguments);
  }

  testing::ScratchFolder folder_;
  std::optional<testing::XvfbServer> server_;
  std::string scene_;
};

TEST_F(WindowTest, OpensAndShowsTheScene) {
  const auto result =
      fosssim("-s scene.xml --window-screenshot shot.png --window-screenshot-step 10");
  ASSERT_EQ(result.status, 0) << result.err;
  const Image shot = read_png(folder_ / "shot.png");
  ASSERT_EQ(shot.width, 512);
  ASSERT_EQ(shot.height, 512);
  std::set<std::uint32_t> colors(shot.pixels.begin(), shot.pixels.end());
  EXPECT_GT(colors.size(), 10u) << "the screenshot is blank";
  // Particle 1 is fixed at pixel (384, 192) and has the default colour; far corners show the
  // background.
  EXPECT_LT(color_distance(shot.color_at(384, 192), Appearance::kDefaultParticleColor), 0.01);
  EXPECT_LT(color_distance(shot.color_at(500, 500), testing::kBackground), 0.01);
}

TEST_F(WindowTest, ShowsExactlyWhatTheHeadlessPicturesShow) {
  const auto window =
      fosssim("-s scene.xml --window-screenshot shot.png --window-screenshot-step 17");
  ASSERT_EQ(window.status, 0) << window.err;
  const auto headless = fosssim("-s scene.xml -d 0 -g 1");
  ASSERT_EQ(headless.status, 0) << headless.err;
  const Image shot = read_png(folder_ / "shot.png");
  const Image picture = read_png(folder_ / "pngs/frame_00017.png");
  EXPECT_EQ(shot.pixels, picture.pixels);
  EXPECT_NE(shot.pixels, read_png(folder_ / "pngs/frame_00016.png").pixels);
}

TEST_F(WindowTest, ShowsA3DSceneExactlyAsTheHeadlessPictures) {
  folder_.write("cloth.xml", testing::kTinyScene3D);
  const auto window = fosssim(
      "-s cloth.xml -o window.bin --window-screenshot shot.png --window-screenshot-step 17");
  ASSERT_EQ(window.status, 0) << window.err;
  // The window fits its camera to the first state, as headless pictures do with --frame first
  // (by default they frame the whole run).
  const auto headless = fosssim("-s cloth.xml -d 0 -g 1 --frame first -o headless.bin");
  ASSERT_EQ(headless.status, 0) << headless.err;
  const Image shot = read_png(folder_ / "shot.png");
  std::set<std::uint32_t> colors(shot.pixels.begin(), shot.pixels.end());
  EXPECT_GT(colors.size(), 10u) << "the screenshot is blank";
  EXPECT_EQ(shot.pixels, read_png(folder_ / "pngs/frame_00017.png").pixels);
  // The window's run, with its idle drag spring, steps exactly as the headless one: its 18
  // frames (kept as .incomplete, since the screenshot closed the window) are the same bytes.
  const std::string kept = testing::read_file(folder_ / "window.bin.incomplete");
  const std::string full = testing::read_file(folder_ / "headless.bin");
  ASSERT_EQ(kept.size(), 18u * 2u * 36u * 3u * 8u);
  EXPECT_EQ(kept, full.substr(0, kept.size()));
  EXPECT_NE(shot.pixels, read_png(folder_ / "pngs/frame_00016.png").pixels);
}

TEST_F(WindowTest, GradingModeRingsTheParticleTheFileGotWrong) {
  ASSERT_EQ(fosssim("-s scene.xml -d 0 -o run.bin").status, 0);
  auto scene = load_scene_text(kTinyScene, "scene.xml");
  {  // Move particle 0 by 0.01 (2.56 pixels) at step 12.
    auto reader = TrajectoryReader::open(folder_ / "run.bin", scene.model.num_dofs());
    auto writer = TrajectoryWriter::open(folder_ / "bad.bin");
    State frame;
    for (std::int64_t k = 0; k < reader.num_frames(); ++k) {
      reader.read_frame(k, frame.q, frame.v);
      if (k == 12) frame.q[0] += 0.01;
      writer.write_frame(frame);
    }
    writer.commit();
  }
  const auto result =
      fosssim("-s scene.xml -i bad.bin --window-screenshot shot.png --window-screenshot-step 12");
  EXPECT_EQ(result.status, 130) << result.err;  // closed by the screenshot before the end
  const Image shot = read_png(folder_ / "shot.png");
  // The red ring around particle 0: radius 25.6 + 3 pixels around its centre, 2 pixels wide.
  Vector q, v;
  auto reader = TrajectoryReader::open(folder_ / "bad.bin", scene.model.num_dofs());
  reader.read_frame(12, q, v);
  const PixelMapping mapping(Camera{0, 0, 1}, 512, 512);
  const Point2 centre = mapping.to_pixel(q[0], q[1]);
  int red = 0;
  for (int a = 0; a < 360; a += 10) {
    const double angle = a * 3.14159265358979 / 180.0;
    const int x = static_cast<int>(centre.x + 28.6 * std::cos(angle));
    const int y = static_cast<int>(centre.y + 28.6 * std::sin(angle));
    red += color_distance(shot.color_at(x, y), Color{0.9, 0.0, 0.0}) < 0.25;
  }
  EXPECT_GE(red, 25) << "of 36 points on the ring";
  // Particle 1 agrees with the reference and has no ring.
  EXPECT_LT(color_distance(shot.color_at(384 + 29, 192), testing::kBackground), 0.01);
}

// Issue 24: the window used to look at signals between frames only, so a step that never ends
// kept it open. One step here is a million local/global iterations of a 40x40 cloth (minutes);
// SIGTERM must close the window within 2 s with the interrupted status.
TEST_F(WindowTest, SigtermEndsTheWindowInsideAStepThatWouldTakeMinutes) {
  folder_.write("long.xml", R"(<scene dim="3">
  <duration time="1"/>
  <integrator type="local-global" dt="0.01" iterations="1000000" tolerance="0"/>
  <generate type="cloth" nx="40" ny="40" plane="xz" pin="corners" k="1000" m="0.001"/>
  <simplegravity fx="0" fy="-9.8" fz="0"/>
</scene>)");
  const auto result = fosssim(
      "-s long.xml --paused 0 & pid=$!; sleep 1.5; start=$(date +%s%N); kill -s TERM $pid; "
      "wait $pid; status=$?; echo \"ms $(( ($(date +%s%N) - start) / 1000000 ))\"; "
      "exit $status");
  EXPECT_EQ(result.status, 130) << result.err;
  // The headless run's line, although no output was open (it used to say nothing).
  EXPECT_NE(result.err.find("FOSSSim: interrupted by signal 15 (Terminated) at step 0"),
            std::string::npos)
      << result.err;
  const std::size_t at = result.out.find("ms ");
  ASSERT_NE(at, std::string::npos) << result.out;
  EXPECT_LT(std::stol(result.out.substr(at + 3)), 2000) << result.out;
}

TEST(WindowWithoutDisplay, SaysHowToRunHeadless) {
  const testing::ScratchFolder folder;
  folder.write("scene.xml", kTinyScene);
  const auto result =
      testing::run_command(folder, "env -u DISPLAY " + testing::quoted(testing::fosssim_program()) +
                                       " -s scene.xml -o never.bin");
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.err.find("no display"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("-d 0"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(folder / "never.bin"));
  EXPECT_FALSE(std::filesystem::exists(folder / "never.bin.incomplete"));
}

}  // namespace
}  // namespace fosssim
