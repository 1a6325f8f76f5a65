#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "support/run_program.h"
#include "support/scratch_folder.h"

namespace fosssim {
namespace {

// 50 steps of dt = 0.01.
constexpr const char* kScene = R"(<scene>
  <duration time="0.5"/><integrator type="linearized-implicit-euler" dt="0.01"/>
  <particle m="1" px="0" py="0" vx="0" vy="0" fixed="1"/>
  <particle m="1" px="1" py="0" vx="0" vy="0" fixed="0"/>
  <edge i="0" j="1"/>
  <springforce edge="0" k="100" l0="1"/>
  <simplegravity fx="0" fy="-9.81"/>
  <particlepath i="1" duration="0.3" r="0.2" g="0.4" b="0.9"/>
</scene>)";

class CliMovie : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!testing::on_path("ffmpeg") || !testing::on_path("ffprobe")) {
      GTEST_SKIP() << "ffmpeg and ffprobe are not installed (tools/install-deps.sh installs them)";
    }
    folder_.write("scene.xml", kScene);
  }
  /// Runs FOSSSim without a display, as on a server.
  testing::ProgramResult fosssim(const std::string& arguments) {
    return testing::run_command(
        folder_, "env -u DISPLAY " + testing::quoted(testing::fosssim_program()) + " " + arguments);
  }
  /// "width,height,rate,frames," as ffprobe reads them.
  std::string probe(const std::string& movie) { return testing::probe_movie(folder_, movie); }
  testing::ScratchFolder folder_;
};

TEST_F(CliMovie, OneCommandWithoutADisplayMakesAMovieWithTheExpectedFrames) {
  const auto result =
      fosssim("-s scene.xml --movie out.mp4 --movie-stride 4 --size 320x240 --fps 25");
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_NE(result.out.find("Simulation complete at time 0.5"), std::string::npos);
  // Frames at steps 0, 4, ..., 48: 13.
  EXPECT_EQ(probe("out.mp4"), "320,240,25/1,13,");
  EXPECT_FALSE(std::filesystem::exists(folder_ / "out.mp4.partial"));
}

TEST_F(CliMovie, DefaultStridePlaysAboutRealTime) {
  const auto result = fosssim("-s scene.xml --movie out.mp4");
  ASSERT_EQ(result.status, 0) << result.err;
  // fps 30, dt 0.01: stride round(3.33) = 3; frames at steps 0, 3, ..., 48: 17.
  EXPECT_EQ(probe("out.mp4"), "512,512,30/1,17,");
}

TEST_F(CliMovie, SaysWhenFfmpegIsMissingAndWritesNothing) {
  const auto result = testing::run_command(
      folder_, "PATH=/nonexistent " + testing::quoted(testing::fosssim_program()) +
                   " -s scene.xml --movie out.mp4");
  EXPECT_EQ(result.status, 4);
  EXPECT_NE(result.err.find("needs the ffmpeg program"), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists(folder_ / "out.mp4"));
  EXPECT_FALSE(std::filesystem::exists(folder_ / "out.mp4.partial"));
}

TEST_F(CliMovie, RejectsOddSizesOtherFormatsAndTheWindow) {
  EXPECT_EQ(fosssim("-s scene.xml --movie out.mp4 --size 321x240").status, 2);
  EXPECT_EQ(fosssim("-s scene.xml --movie out.gif").status, 2);
  const auto windowed = fosssim("-s scene.xml --movie out.mp4 -d 1");
  EXPECT_EQ(windowed.status, 2);
  EXPECT_NE(windowed.err.find("headless"), std::string::npos);
}

TEST_F(CliMovie, AFailedRunKeepsTheMovieSoFarAsIncomplete) {
  // Explicit Euler on a very stiff spring blows up to infinity within a few hundred steps.
  folder_.write("unstable.xml", R"(<scene>
    <duration time="100"/><integrator type="explicit-euler" dt="0.01"/>
    <particle m="1" px="0" py="0" vx="0" vy="0" fixed="1"/>
    <particle m="1" px="1.5" py="0" vx="0" vy="0" fixed="0"/>
    <edge i="0" j="1"/><springforce edge="0" k="100000" l0="1"/></scene>)");
  const auto result = fosssim("-s unstable.xml --movie out.mp4 --movie-stride 1 --size 64x64");
  EXPECT_EQ(result.status, 3) << result.err;
  EXPECT_FALSE(std::filesystem::exists(folder_ / "out.mp4"));
  EXPECT_TRUE(std::filesystem::exists(folder_ / "out.mp4.incomplete")) << result.err;
  EXPECT_NE(result.err.find("out.mp4.incomplete"), std::string::npos);
}

}  // namespace
}  // namespace fosssim
