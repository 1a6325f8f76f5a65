// FOSSSim's behaviour on careless and hostile input (docs/limits-and-failures.md), run as a user
// runs it: every case ends with one clear message and the documented exit status, no output
// ever replaces an input, and no *.partial file is left behind.
//
// Checked: each output option (-o, --residual-file, --energy-csv, --energy-plot, --movie, -g,
// -m, --window-screenshot) refuses to write over the scene, its mesh files or the graded
// trajectory, under any name for them (hard and symbolic links, "./x", the output's own
// .partial and .incomplete names), and the inputs keep their bytes; absurd sizes (a JSON number
// beyond double range, huge generators, a MEDIT count of 2^31-1, step counts that overflow) are
// exit 2 with a message naming the limit and its option; a FIFO or a device as the scene or a
// mesh is refused at once; the limits' options raise them; an all-zero trajectory's residual
// file agrees with the printed report; scenes with no particles, or only fixed ones, run under
// every integrator (in the Debug build they once tripped Eigen's assertions on 0×0 matrices).

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "core/integrators/integrator_registry.h"
#include "support/run_program.h"
#include "support/tiny_scenes.h"
#include "core/sanitizers.h"

namespace fosssim {
namespace {

namespace fs = std::filesystem;
using fosssim::testing::kFixedSpringScene;
using fosssim::testing::ProgramResult;

constexpr const char* kClothScene = R"(<scene dim="3">
  <duration time="0.1"/>
  <integrator type="linearly-implicit-euler" dt="0.01"/>
  <clothmesh file="cloth.obj" k="100" m="0.1"/>
</scene>)";

constexpr const char* kCloth = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";

class LimitsAndFailures : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("fosssim_limits_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    write("spring.xml", kFixedSpringScene);
    write("cloth.xml", kClothScene);
    write("cloth.obj", kCloth);
  }
  void TearDown() override { fs::remove_all(dir_); }

  void write(const std::string& name, const std::string& content) {
    fs::create_directories((dir_ / name).parent_path());
    std::ofstream(dir_ / name, std::ios::binary) << content;
  }
  std::string read(const std::string& name) const {
    std::ifstream in(dir_ / name, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  ProgramResult fosssim(std::vector<std::string> args) {
    args.insert(args.begin(), fosssim::testing::fosssim_program());
    return fosssim::testing::run_program(args, dir_.string());
  }

  /// Every file under the test's folder, relative, with its bytes.
  std::map<std::string, std::string> snapshot() const {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(dir_)) {
      if (entry.is_regular_file() || entry.is_symlink())
        files[fs::relative(entry.path(), dir_).string()] = read(fs::relative(entry.path(), dir_));
    }
    return files;
  }

  /// Runs FOSSSim, which must fail with exit status 2 and a message holding `expected`, and
  /// leave every file as it was: no input changed, no output or *.partial created.
  void expect_refused(const std::vector<std::string>& args, const std::string& expected) {
    const auto before = snapshot();
    const ProgramResult r = fosssim(args);
    std::string command;
    for (const std::string& a : args) command += a + " ";
    EXPECT_EQ(r.status, 2) << command << "\n" << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << command << "\n" << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
    EXPECT_EQ(snapshot(), before) << command;
  }

  fs::path dir_;
};

// A face of many corners (n (n - 1) / 2 springs) and an element of many attributes (quadratic
// in tinyxml2) are refused at once, naming the limit; each limit can be raised.
TEST_F(LimitsAndFailures, FaceCornersAndAttributesAreBounded) {
  std::string polygon;
  std::string face = "f";
  for (int k = 0; k < 3000; ++k) {
    const double angle = 2.0 * 3.141592653589793 * k / 3000;
    polygon +=
        "v " + std::to_string(std::cos(angle)) + " " + std::to_string(std::sin(angle)) + " 0\n";
    face += " " + std::to_string(k + 1);
  }
  write("cloth.obj", polygon + face + "\n");
  expect_refused({"-s", "cloth.xml", "-d", "0", "-o", "out.bin"},
                 "a face of 3000 corners (it would make 4498500 springs), more than the limit of "
                 "64 corners (raise it with --max-face-corners N)");
  write("cloth.obj", kCloth);
  expect_refused({"-s", "cloth.xml", "-d", "0", "--max-face-corners", "3"},
                 "a face of 4 corners (it would make 6 springs), more than the limit of 3 corners");
  std::string attributes;
  for (int k = 0; k < 60000; ++k) attributes += " a" + std::to_string(k) + "=\"0\"";
  const std::string edge = "<edge i=\"0\" j=\"1\"";
  std::string scene = kFixedSpringScene;
  scene.replace(scene.find(edge), edge.size(), edge + attributes);
  write("many.xml", scene);
  expect_refused({"-s", "many.xml", "-d", "0"},
                 "many.xml:6: error: an element with more than the limit of 100 attributes (raise "
                 "it with --max-attributes N)");
  scene = kFixedSpringScene;
  scene.replace(scene.find(edge), edge.size(), edge + " a=\"0\"");
  write("three.xml", scene);
  expect_refused({"-s", "three.xml", "-d", "0", "--max-attributes", "2"},
                 "more than the limit of 2 attributes");
  EXPECT_EQ(fosssim({"-s", "three.xml", "-d", "0", "-q", "--max-attributes", "6"}).status, 0);
}

TEST_F(LimitsAndFailures, NoOutputOptionReplacesTheSceneOrItsMeshes) {
  const std::string refused = "an output must never replace an input";
  expect_refused({"-s", "spring.xml", "-d", "0", "-o", "spring.xml"},
                 "-o spring.xml is the scene file spring.xml: " + refused);
  expect_refused({"-s", "spring.xml", "-d", "0", "-o", "./spring.xml"},
                 "-o ./spring.xml is the scene file spring.xml");
  expect_refused({"-s", "cloth.xml", "-d", "0", "-o", "cloth.obj"},
                 "-o cloth.obj is the mesh file cloth.obj");
  expect_refused({"-s", "spring.xml", "-d", "0", "--energy-csv", "spring.xml"},
                 "--energy-csv spring.xml is the scene file spring.xml");
  write("plot.svg", kFixedSpringScene);
  expect_refused({"-s", "plot.svg", "-d", "0", "--energy-plot", "plot.svg"},
                 "--energy-plot plot.svg is the scene file plot.svg");
  write("movie.mp4", kFixedSpringScene);
  expect_refused({"-s", "movie.mp4", "--movie", "movie.mp4"},
                 "--movie movie.mp4 is the scene file movie.mp4");
  write("shot.png", kFixedSpringScene);
  expect_refused({"-s", "shot.png", "-d", "1", "--window-screenshot", "shot.png"},
                 "--window-screenshot shot.png is the scene file shot.png");
  write("pngs/frame_00000.png", kFixedSpringScene);
  expect_refused({"-s", "pngs/frame_00000.png", "-d", "0", "-g", "1", "--png-dir", "pngs"},
                 "-g pngs (written as pngs/frame_00000.png) is the scene file");
  write("svgs/frame_00042.svg", kFixedSpringScene);
  expect_refused({"-s", "svgs/frame_00042.svg", "-d", "0", "-m", "svgs"},
                 "-m svgs (written as svgs/frame_00042.svg) is the scene file");
}

TEST_F(LimitsAndFailures, InputsAreComparedByIdentityNotByName) {
  ASSERT_EQ(::link(path("spring.xml").c_str(), path("hard.bin").c_str()), 0);
  expect_refused({"-s", "spring.xml", "-d", "0", "-o", "hard.bin"},
                 "-o hard.bin is the scene file spring.xml");
  fs::create_symlink("cloth.obj", dir_ / "soft.bin");
  expect_refused({"-s", "cloth.xml", "-d", "0", "-o", "soft.bin"},
                 "-o soft.bin is the mesh file cloth.obj");
  expect_refused({"-s", "cloth.xml", "-d", "0", "-o", path("cloth.obj")},
                 "is the mesh file cloth.obj");
}

TEST_F(LimitsAndFailures, NoOutputIsWrittenOverAnInputOnTheWay) {
  // An output is written as NAME.partial and a stopped run keeps NAME.incomplete.
  write("out.bin.partial", kFixedSpringScene);
  expect_refused({"-s", "out.bin.partial", "-d", "0", "-o", "out.bin"},
                 "-o out.bin (written as out.bin.partial) is the scene file out.bin.partial");
  write("e.csv.incomplete", kFixedSpringScene);
  expect_refused({"-s", "e.csv.incomplete", "-d", "0", "--energy-csv", "e.csv"},
                 "--energy-csv e.csv (written as e.csv.incomplete) is the scene file");
  write("pics/frame_00001.png.partial", kFixedSpringScene);
  expect_refused({"-s", "pics/frame_00001.png.partial", "-d", "0", "-g", "1", "--png-dir", "pics"},
                 "-g pics (written as pics/frame_00001.png.partial) is the scene file");
}

TEST_F(LimitsAndFailures, GradingNeverReplacesTheTrajectoryOrTheScene) {
  ASSERT_EQ(fosssim({"-s", "spring.xml", "-d", "0", "-o", "run.bin"}).status, 0);
  expect_refused({"-s", "spring.xml", "-d", "0", "-i", "run.bin", "--residual-file", "run.bin"},
                 "--residual-file run.bin is the trajectory to grade (-i) run.bin");
  expect_refused({"-s", "spring.xml", "-d", "0", "-i", "run.bin", "--residual-file", "spring.xml"},
                 "--residual-file spring.xml is the scene file spring.xml");
  write("residual.txt", kFixedSpringScene);  // the default residual file's name
  expect_refused({"-s", "residual.txt", "-d", "0", "-i", "run.bin"},
                 "--residual-file residual.txt is the scene file residual.txt");
}

TEST_F(LimitsAndFailures, AbsurdSizesAreRefusedNamingTheLimit) {
  const auto scene = [](const std::string& element) {
    return std::string(R"(<scene dim="3"><duration time="1"/>
<integrator type="linearly-implicit-euler" dt="0.01"/>
)") + element +
           "</scene>";
  };
  write("box.xml", scene(R"(<generate type="tetbox" nx="2000" ny="2000" nz="2000" k="1" m="1"/>)"));
  expect_refused({"-s", "box.xml", "-d", "0", "-o", "out.bin"},
                 "box.xml:3: error: <generate> 0: a tetbox of 2000 × 2000 × 2000 cubes has "
                 "8012006001 vertices, more than the limit of 1000000 particles (raise it with "
                 "--max-particles N)");
  write("cloth100k.xml", scene(R"(<generate type="cloth" nx="100000" ny="100000" k="1" m="1"/>)"));
  expect_refused({"-s", "cloth100k.xml", "-d", "0", "-o", "out.bin"},
                 "a cloth of 100000 × 100000 vertices has 10000000000 vertices");
  write("huge.mesh", "MeshVersionFormatted 1\nDimension 3\nVertices 2147483647\n0 0 0 0\n");
  write("huge.xml", scene(R"(<tetmesh file="huge.mesh" k="1" m="1"/>)"));
  expect_refused({"-s", "huge.xml", "-d", "0", "-o", "out.bin"},
                 "huge.mesh:4: error: the file ends where coordinate x of vertex 2 should be");
  write("k.json", R"({"obj": "cloth.obj", "k": 1e400})");
  expect_refused({"-s", "k.json", "-d", "0", "-o", "out.bin"},
                 "k.json: error: not valid JSON: number overflow parsing '1e400'");
}

TEST_F(LimitsAndFailures, StepCountsThatOverflowAreRefusedNotRunAsZeroSteps) {
  write("long.xml",
        R"(<scene><duration time="1e300"/><integrator type="explicit-euler" dt="1e-300"/>
<particle m="1" px="0" py="0" vx="0" vy="0" fixed="0"/></scene>)");
  expect_refused({"-s", "long.xml", "-d", "0", "-o", "out.bin"},
                 "FOSSSim: error: duration 1e+300 s at dt 1e-300 s: duration / dt overflows");
  expect_refused({"-s", "spring.xml", "-d", "0", "-o", "out.bin", "--dt", "1e-320"},
                 "duration 1 s at dt 1e-320 s: duration / dt overflows");
  expect_refused({"-s", "spring.xml", "-d", "0", "-o", "out.bin", "--duration", "1e12"},
                 "duration 1e+12 s at dt 0.01 s takes 100000000000000 steps, more than "
                 "the limit of 1000000000 steps (raise it with --max-steps N)");
}

TEST_F(LimitsAndFailures, EveryLimitCanBeRaisedOrLowered) {
  expect_refused({"-s", "spring.xml", "-d", "0", "--max-steps", "99"},
                 "takes 100 steps, more than the limit of 99 steps (raise it with --max-steps N)");
  EXPECT_EQ(fosssim({"-s", "spring.xml", "-d", "0", "-q", "--max-steps", "100"}).status, 0);
  expect_refused({"-s", "spring.xml", "-d", "0", "--max-particles", "1"},
                 "the scene declares 2 particles, more than the limit of 1 particles");
  write("box.xml", R"(<scene dim="3"><duration time="0.01"/>
<integrator type="linearly-implicit-euler" dt="0.01"/>
<generate type="tetbox" nx="100" ny="100" nz="100" k="1" m="1"/></scene>)");
  expect_refused({"-s", "box.xml", "-d", "0", "--max-particles", "1000"},
                 "has 1030301 vertices, more than the limit of 1000 particles");
  write("big.xml", "<!--" + std::string(1 << 21, '-') + "-->" + kFixedSpringScene);
  expect_refused({"-s", "big.xml", "-d", "0", "--max-file-size", "1"},
                 "big.xml: error: the file is more than the limit of 1 MiB (raise it with "
                 "--max-file-size N)");
  EXPECT_EQ(fosssim({"-s", "big.xml", "-d", "0", "-q", "--max-file-size", "3"}).status, 0);
  for (const char* bad : {"0", "-1", "abc"}) {
    EXPECT_EQ(fosssim({"-s", "spring.xml", "-d", "0", "--max-steps", bad}).status, 2) << bad;
  }
}

TEST_F(LimitsAndFailures, OnlyRegularFilesAreRead) {
  ASSERT_EQ(::mkfifo(path("fifo.xml").c_str(), 0600), 0);
  expect_refused({"-s", "fifo.xml", "-d", "0"},
                 "fifo.xml: error: is a FIFO (named pipe), not a regular file");
  expect_refused({"-s", "/dev/zero", "-d", "0"},
                 "/dev/zero: error: is a device, not a regular file");
  write("zero.xml", R"(<scene dim="3"><duration time="1"/>
<integrator type="linearly-implicit-euler" dt="0.01"/>
<clothmesh file="/dev/zero" k="1" m="1"/></scene>)");
  expect_refused({"-s", "zero.xml", "-d", "0"},
                 "/dev/zero: error: is a device, not a regular file (the mesh of zero.xml:3)");
  ASSERT_EQ(fosssim({"-s", "spring.xml", "-d", "0", "-o", "run.bin"}).status, 0);
  expect_refused({"-s", "spring.xml", "-d", "0", "-i", "fifo.xml"},
                 "fifo.xml: error: is a FIFO (named pipe), not a regular file");
}

// Zeros make the springs' lengths zero: the reference cannot take a step. The printed report
// and residual.txt must say the same, line by line.
TEST_F(LimitsAndFailures, TheResidualFileAgreesWithTheReportForAnAllZeroTrajectory) {
  ASSERT_EQ(fosssim({"-s", "spring.xml", "-d", "0", "-o", "run.bin"}).status, 0);
  const auto bytes = fs::file_size(dir_ / "run.bin");
  write("zero.bin", std::string(bytes, '\0'));
  const ProgramResult r = fosssim({"-s", "spring.xml", "-d", "0", "-i", "zero.bin"});
  EXPECT_EQ(r.status, 1) << r.err;
  const std::string residuals = read("residual.txt");
  std::istringstream printed(r.out), written(residuals);
  std::string line, entry;
  int lines = 0;
  while (std::getline(written, entry)) {
    ASSERT_TRUE(std::getline(printed, line));
    const bool passed = line.find("Passed.") != std::string::npos;
    EXPECT_EQ(entry.substr(0, 1), passed ? "1" : "0") << line << " vs " << entry;
    ++lines;
  }
  EXPECT_EQ(lines, 4);
  EXPECT_EQ(residuals, "0   nan\n0   nan\n0   nan\n0   nan\n");
  EXPECT_NE(r.out.find("Overall success: Failed."), std::string::npos);
}

// Failures that are not FOSSSim's own errors (here std::bad_alloc, under a memory limit of 300
// MB for a cloth that needs about 3 GB) reach main's handler: one message, exit status 2, and
// the run's output kept as .incomplete, never left as .partial or under its own name.
TEST_F(LimitsAndFailures, RunningOutOfMemoryIsAMessageAndStatus2WithNoPartialFileLeft) {
#if FOSSSIM_ADDRESS_SANITIZER
  GTEST_SKIP() << "AddressSanitizer reserves more address space than the limit allows";
#endif
  write("big.xml", R"(<scene dim="3"><duration time="0.05"/>
<integrator type="linearly-implicit-euler" dt="0.01"/>
<generate type="cloth" nx="400" ny="400" k="1" m="1"/></scene>)");
  const ProgramResult r = fosssim::testing::run_program(
      {"/bin/sh", "-c",
       "ulimit -v 300000 && exec '" + fosssim::testing::fosssim_program() +
           "' -s big.xml -d 0 -q -o out.bin"},
      dir_.string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(
      r.err.rfind("FOSSSim: error: out of memory: the scene is too large for this machine", 0), 0u)
      << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out.bin"));
  EXPECT_FALSE(fs::exists(dir_ / "out.bin.partial"));
}

TEST_F(LimitsAndFailures, ScenesWithoutFreeParticlesRunUnderEveryIntegrator) {
  for (const IntegratorMethod* method : integrator_methods()) {
    const std::string name(method->name);
    const std::string dim = method->properties.runs_2d ? "2" : "3";
    const std::string z = dim == "3" ? R"( pz="0" vz="0")" : "";
    write("empty.xml", R"(<scene dim=")" + dim + R"("><duration time="0.05"/>
<integrator type=")" + name +
                           R"(" dt="0.01"/></scene>)");
    ProgramResult r = fosssim({"-s", "empty.xml", "-d", "0", "-q", "-o", "empty.bin"});
    EXPECT_EQ(r.status, 0) << name << ": " << r.err;
    write("fixed.xml", R"(<scene dim=")" + dim + R"("><duration time="0.05"/>
<integrator type=")" + name +
                           R"(" dt="0.01"/>
<particle m="1" px="0" py="0" vx="0" vy="0" fixed="1")" +
                           z + R"(/>
<particle m="1" px="1" py="0" vx="0" vy="0" fixed="1")" +
                           z + R"(/>
<edge i="0" j="1"/><springforce edge="0" k="1" l0="1"/></scene>)");
    r = fosssim({"-s", "fixed.xml", "-d", "0", "-q", "-o", "fixed.bin"});
    EXPECT_EQ(r.status, 0) << name << ": " << r.err;
    EXPECT_EQ(fs::file_size(dir_ / "fixed.bin"), 6u * 2 * 2 * std::stoul(dim) * 8) << name;
  }
}

}  // namespace
}  // namespace fosssim
