// FOSSSim and FOSSSim-generate on 3D scenes, run as a user would.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

namespace {

struct Outcome {
  int status = -1;
  std::string output;  // stdout and stderr
};

Outcome run(const std::string& command) {
  Outcome result;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen((command + " 2>&1").c_str(), "r"), pclose);
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), buffer.size(), pipe.get())) result.output += buffer.data();
  const int status = pclose(pipe.release());
  result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

class CommandLine3D : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           (std::string("fosssim-app3d-") +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string write(const std::string& name, const std::string& content) const {
    std::ofstream(path(name)) << content;
    return path(name);
  }
  static std::string asset(const std::string& name) {
    return std::string(FOSSSIM_SOURCE_DIR) + "/assets3d/" + name;
  }

  std::filesystem::path dir_;
};

const std::string kFosssim = FOSSSIM_BIN;
const std::string kGenerate = FOSSSIM_GENERATE_BIN;

TEST_F(CommandLine3D, WritesAndGradesTheTrajectoryOfAMeshScene) {
  const std::string scene = asset("scenes/tet_box.xml");
  const Outcome simulate =
      run(kFosssim + " -s " + scene + " -d 0 -q --duration 0.05 -o " + path("out.bin"));
  ASSERT_EQ(simulate.status, 0) << simulate.output;
  EXPECT_NE(simulate.output.find("Simulation complete"), std::string::npos);
  const Outcome grade = run(kFosssim + " -s " + scene + " -d 0 -q --duration 0.05 -i " +
                            path("out.bin") + " --residual-file " + path("residual.txt"));
  EXPECT_EQ(grade.status, 0) << grade.output;
  EXPECT_NE(grade.output.find("Overall success: Passed."), std::string::npos) << grade.output;
}

TEST_F(CommandLine3D, RunsTheAssignmentsJsonScenes) {
  const Outcome json = run(kFosssim + " -s " + asset("json/cloth_9x9.json") +
                           " -d 0 -q --duration 0.2 -o " + path("j.bin"));
  EXPECT_EQ(json.status, 0) << json.output;
  EXPECT_EQ(std::filesystem::file_size(path("j.bin")), 7u * 2u * 81u * 3u * 8u);
}

TEST_F(CommandLine3D, RejectsAMalformedMeshWithItsLineAndStatus2) {
  write("broken.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 4\n");
  const std::string scene = write("scene.xml", R"(<scene dim="3">
  <duration time="1"/>
  <integrator type="local-global" dt="0.01"/>
  <clothmesh file="broken.obj" k="1" m="1"/>
</scene>)");
  const Outcome result = run(kFosssim + " -s " + scene + " -d 0 -o " + path("out.bin"));
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(
      result.output.find(path("broken.obj") + ":4: error: vertex index 4 is past the last vertex"),
      std::string::npos)
      << result.output;
  EXPECT_FALSE(std::filesystem::exists(path("out.bin")));
}

TEST_F(CommandLine3D, GeneratesMeshesAndJsonScenesThatRun) {
  const Outcome cloth = run(kGenerate + " -o " + path("c.obj") + " --json " + path("c.json") +
                            " --k 5000 cloth --nx 6 --ny 4");
  ASSERT_EQ(cloth.status, 0) << cloth.output;
  EXPECT_NE(cloth.output.find("24 vertices"), std::string::npos) << cloth.output;
  const Outcome json = run(kFosssim + " -s " + path("c.json") + " -d 0 -q --duration 0.1");
  EXPECT_EQ(json.status, 0) << json.output;
  const Outcome ball = run(kGenerate + " -o " + path("b.mesh") + " tetball --cells 4");
  ASSERT_EQ(ball.status, 0) << ball.output;
  write("ball.xml", R"(<scene dim="3">
  <duration time="0.05"/>
  <integrator type="linearly-implicit-euler" dt="0.01"/>
  <tetmesh file="b.mesh" k="100" mass="volume" density="10"><pin axis="y" side="highest" within="0.01"/></tetmesh>
  <simplegravity fx="0" fy="-9.8" fz="0"/>
</scene>)");
  const Outcome ball_run = run(kFosssim + " -s " + path("ball.xml") + " -d 0 -q");
  EXPECT_EQ(ball_run.status, 0) << ball_run.output;
  const Outcome wrong = run(kGenerate + " -o " + path("b.obj") + " tetbox");
  EXPECT_EQ(wrong.status, 2);
  EXPECT_NE(wrong.output.find("MEDIT (.mesh)"), std::string::npos) << wrong.output;
  const Outcome bad_pins = run(kGenerate + " -o " + path("c2.obj") + " --json " + path("c2.json") +
                               " --pins middle cloth");
  EXPECT_EQ(bad_pins.status, 2);
  // Sizes over the limit are refused before anything is generated, and the limit can be set.
  const Outcome huge =
      run(kGenerate + " -o " + path("h.mesh") + " tetbox --nx 2000 --ny 2000 --nz 2000");
  EXPECT_EQ(huge.status, 2);
  EXPECT_NE(huge.output.find("FOSSSim-generate: error: a tetbox of 2000 × 2000 × 2000 cubes has "
                             "8012006001 vertices, more than the limit of 1000000 particles"),
            std::string::npos)
      << huge.output;
  EXPECT_FALSE(std::filesystem::exists(path("h.mesh")));
  EXPECT_EQ(
      run(kGenerate + " -o " + path("c3.obj") + " --max-particles 23 cloth --nx 6 --ny 4").status,
      2);
}

}  // namespace
