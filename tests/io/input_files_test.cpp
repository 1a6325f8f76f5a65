// Tests of how input files are read (io/input_files.h) and of the limits readers apply.
//
// Checked: only regular files are read as scenes, meshes and trajectories: a FIFO is refused at
// once (not waited on) and /dev/zero is refused instead of read forever; a file over the size
// limit is refused naming the limit and --max-file-size; Scene::files lists the scene and its
// mesh files; in-memory files serve fuzzers without touching the disk; a JSON number beyond the
// range of a double is a located SceneError; a MEDIT header declaring 2147483647 vertices ends
// at the file's end with a message (nothing is reserved from it); generators and particle
// counts over the limit are refused before anything is allocated, naming --max-particles.

#include "io/input_files.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/json_scene_reader.h"
#include "io/medit_reader.h"
#include "io/scene_loader.h"
#include "io/trajectory_file.h"
#include "support/thrown.h"

namespace fosssim {
namespace {

namespace fs = std::filesystem;

class InputFilesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("fosssim_inputs_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& content) const {
    std::ofstream(dir_ / name, std::ios::binary) << content;
    return path(name);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string fifo(const std::string& name) const {
    EXPECT_EQ(::mkfifo(path(name).c_str(), 0600), 0);
    return path(name);
  }

  fs::path dir_;
};

constexpr const char* kParticleScene = R"(<scene>
  <duration time="1"/>
  <integrator type="explicit-euler" dt="0.1"/>
  <particle m="1" px="0" py="0" vx="0" vy="0" fixed="0"/>
</scene>)";

TEST_F(InputFilesTest, AFifoIsRefusedWithoutWaitingForAWriter) {
  const std::string scene = fifo("scene.xml");
  const SceneError error = thrown_by<SceneError>([&] { load_scene_file(scene); });
  EXPECT_EQ(error.file(), scene);
  EXPECT_EQ(error.problem(), "is a FIFO (named pipe), not a regular file");
  const SceneError json = thrown_by<SceneError>([&] { load_json_scene_file(fifo("s.json")); });
  EXPECT_EQ(json.problem(), "is a FIFO (named pipe), not a regular file");
  const Error trajectory = thrown_by([&] { TrajectoryReader::open(fifo("run.bin"), 4); });
  EXPECT_EQ(trajectory.kind(), ErrorKind::kBadInput);
  EXPECT_NE(std::string(trajectory.what()).find("is a FIFO"), std::string::npos);
}

TEST_F(InputFilesTest, ADeviceIsRefusedInsteadOfReadForever) {
  const SceneError error = thrown_by<SceneError>([] { load_scene_file("/dev/zero"); });
  EXPECT_EQ(error.problem(), "is a device, not a regular file");
  const Error trajectory = thrown_by([] { TrajectoryReader::open("/dev/zero", 4); });
  EXPECT_STREQ(trajectory.what(), "/dev/zero: error: is a device, not a regular file");
}

TEST_F(InputFilesTest, AFifoOrDeviceAsAMeshFileIsRefusedNamingTheSceneToo) {
  fifo("cloth.obj");
  const std::string scene = write("scene.xml", R"(<scene dim="3">
  <duration time="1"/>
  <integrator type="linearly-implicit-euler" dt="0.1"/>
  <clothmesh file="cloth.obj" k="1" m="1"/>
  <tetmesh file="/dev/zero" k="1" m="1"/>
</scene>)");
  const SceneError error = thrown_by<SceneError>([&] { load_scene_file(scene); });
  EXPECT_EQ(error.file(), path("cloth.obj"));
  EXPECT_EQ(error.problem(),
            "is a FIFO (named pipe), not a regular file (the mesh of " + scene + ":4)");
}

TEST_F(InputFilesTest, AFileOverTheSizeLimitIsRefusedNamingTheLimit) {
  const std::string scene = write("scene.xml", kParticleScene);
  Limits limits;
  limits.max_file_bytes = 100;
  InputFiles files(limits);
  const SceneError error = thrown_by<SceneError>([&] { load_scene_file(scene, files); });
  EXPECT_EQ(error.problem(),
            "the file is more than the limit of 100 bytes (raise it with --max-file-size N)");
  limits.max_file_bytes = 2 << 20;
  InputFiles roomy(limits);
  EXPECT_EQ(load_scene_file(scene, roomy).model.num_particles(), 1);
  const std::string big = write("big.xml", std::string((3 << 20), ' '));
  const SceneError mib = thrown_by<SceneError>([&] { load_scene_file(big, roomy); });
  EXPECT_EQ(mib.problem(),
            "the file is more than the limit of 2 MiB (raise it with --max-file-size N)");
}

TEST_F(InputFilesTest, TheSceneListsEveryFileItWasReadFrom) {
  write("cloth.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string scene = write("scene.xml", R"(<scene dim="3">
  <duration time="1"/>
  <integrator type="linearly-implicit-euler" dt="0.1"/>
  <clothmesh file="cloth.obj" k="1" m="1"/>
</scene>)");
  EXPECT_EQ(load_scene_file(scene).files, (std::vector<std::string>{scene, path("cloth.obj")}));
  const std::string json = write("scene.json", R"({"obj": "cloth.obj", "k": 10})");
  EXPECT_EQ(load_scene_file(json).files, (std::vector<std::string>{json, path("cloth.obj")}));
}

TEST_F(InputFilesTest, InMemoryFilesNeverTouchTheDisk) {
  write("cloth.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  InputFiles files = InputFiles::in_memory({{"mem.obj", "v 0 0 0\nv 2 0 0\nv 0 2 0\nf 1 2 3\n"}});
  const Scene scene = load_json_scene_text(R"({"obj": "mem.obj", "k": 10})", "s.json", files);
  EXPECT_EQ(scene.model.num_particles(), 3);
  EXPECT_EQ(files.paths(), std::vector<std::string>{"mem.obj"});
  const SceneError missing =
      thrown_by<SceneError>([&] { files.read(path("cloth.obj")); });  // on disk, but not in memory
  EXPECT_EQ(missing.problem(), "cannot open the file: No such file or directory");
}

TEST_F(InputFilesTest, ATrajectoryInMemoryReadsLikeAFile) {
  std::string bytes(2 * 2 * 4 * sizeof(double), '\0');
  const double value = 1.5;
  std::memcpy(bytes.data() + 8 * sizeof(double), &value, sizeof value);  // frame 1, q[0]
  TrajectoryReader reader = TrajectoryReader::from_bytes(bytes, 4, "mem.bin");
  EXPECT_EQ(reader.num_frames(), 2);
  Vector q, v;
  reader.read_frame(1, q, v);
  EXPECT_EQ(q[0], 1.5);
  EXPECT_THROW(reader.read_frame(2, q, v), Error);
  EXPECT_EQ(TrajectoryReader::from_bytes("", 4, "empty.bin").num_frames(), 0);
  const Error cut = thrown_by([] { TrajectoryReader::from_bytes("abc", 4, "cut.bin"); });
  EXPECT_NE(std::string(cut.what()).find("cut.bin has 3 bytes"), std::string::npos);
  const Error empty_scene = thrown_by([] { TrajectoryReader::from_bytes("", 0, "e.bin"); });
  EXPECT_STREQ(empty_scene.what(),
               "e.bin: the scene has no particles, so its trajectory has nothing to read");
}

TEST(ReaderLimits, AJsonNumberBeyondDoubleRangeIsALocatedError) {
  const SceneError error = thrown_by<SceneError>(
      [] { load_json_scene_text(R"({"obj": "x.obj", "k": 1e400})", "s.json"); });
  EXPECT_STREQ(error.what(), "s.json: error: not valid JSON: number overflow parsing '1e400'");
}

TEST(ReaderLimits, AMeditCountIsNeverTrustedForMemory) {
  const SceneError error = thrown_by<SceneError>([] {
    read_medit_text("MeshVersionFormatted 1\nDimension 3\nVertices 2147483647\n0 0 0 0\n",
                    "m.mesh");
  });
  EXPECT_STREQ(error.what(),
               "m.mesh:4: error: the file ends where coordinate x of vertex 2 should be");
}

TEST(ReaderLimits, GeneratorsOverTheParticleLimitAreRefusedBeforeGenerating) {
  const auto error_of = [](const std::string& generate) {
    return std::string(thrown_by<SceneError>([&] {
                         load_scene_text(R"(<scene dim="3"><duration time="1"/>
<integrator type="linearly-implicit-euler" dt="0.1"/>
)" + generate + "</scene>",
                                         "big.xml");
                       }).what());
  };
  EXPECT_EQ(error_of(R"(<generate type="tetbox" nx="2000" ny="2000" nz="2000" k="1" m="1"/>)"),
            "big.xml:3: error: <generate> 0: a tetbox of 2000 × 2000 × 2000 cubes has 8012006001 "
            "vertices, more than the limit of 1000000 particles (raise it with --max-particles N)");
  EXPECT_EQ(error_of(R"(<generate type="cloth" nx="100000" ny="100000" k="1" m="1"/>)"),
            "big.xml:3: error: <generate> 0: a cloth of 100000 × 100000 vertices has 10000000000 "
            "vertices, more than the limit of 1000000 particles (raise it with --max-particles N)");
  EXPECT_NE(error_of(R"(<generate type="tetball" cells="2147483647" k="1" m="1"/>)")
                .find("has more than 9223372036854775807 vertices"),
            std::string::npos);
  EXPECT_NE(error_of(R"(<generate type="chain" links="2147483647" k="1" m="1"/>)")
                .find("a chain of 2147483647 links has 2147483648 vertices"),
            std::string::npos);
}

TEST(ReaderLimits, TheParticleLimitCountsEveryParticleAndCanBeRaised) {
  std::string scene = R"(<scene><duration time="1"/><integrator type="explicit-euler" dt="0.1"/>)";
  for (int p = 0; p < 5; ++p) scene += R"(<particle m="1" px="0" py="0" vx="0" vy="0" fixed="0"/>)";
  scene += "</scene>";
  Limits limits;
  limits.max_particles = 4;
  InputFiles files(limits);
  const SceneError error = thrown_by<SceneError>([&] { load_scene_text(scene, "p.xml", files); });
  EXPECT_STREQ(error.what(),
               "p.xml:1: error: <particle>: the scene declares 5 particles, more than the limit of "
               "4 particles (raise it with --max-particles N)");
  limits.max_particles = 5;
  InputFiles enough(limits);
  EXPECT_EQ(load_scene_text(scene, "p.xml", enough).model.num_particles(), 5);
}

}  // namespace
}  // namespace fosssim
