// FOSSSim and FOSSSim-generate on 3D scenes, run as a user would.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/run_program.h"
#include "support/scratch_folder.h"

namespace {

using fosssim::testing::ProgramResult;

class CommandLine3D : public ::testing::Test {
 protected:
  /// Runs a shell command line in the test's folder.
  ProgramResult run(const std::string& command) const {
    return fosssim::testing::run_command(folder_, command);
  }
  std::string path(const std::string& name) const { return folder_ / name; }
  std::string write(const std::string& name, const std::string& content) const {
    return folder_.write(name, content);
  }
  static std::string asset(const std::string& name) {
    return std::string(FOSSSIM_SOURCE_DIR) + "/assets3d/" + name;
  }

  fosssim::testing::ScratchFolder folder_;
};

const std::string kFosssim = fosssim::testing::fosssim_program();
const std::string kGenerate = fosssim::testing::fosssim_generate_program();

/// A 50×50 cloth pinned at its corners, falling under gravity with `method` at dt 0.02 for
/// `duration` seconds: large enough that its implicit steps factor (CHOLMOD) and thread.
std::string cloth_50_scene(const std::string& method, const std::string& duration) {
  return R"(<scene dim="3">
  <duration time=")" + duration + R"("/>
  <integrator type=")" + method + R"(" dt="0.02"/>
  <generate type="cloth" nx="50" ny="50" plane="xz" pin="corners" k="200" m="0.001"/>
  <simplegravity fx="0" fy="-9.8" fz="0"/>
</scene>)";
}

TEST_F(CommandLine3D, WritesAndGradesTheTrajectoryOfAMeshScene) {
  const std::string scene = asset("scenes/tet_box.xml");
  const ProgramResult simulate =
      run(kFosssim + " -s " + scene + " -d 0 -q --duration 0.05 -o " + path("out.bin"));
  ASSERT_EQ(simulate.status, 0) << simulate.output();
  EXPECT_NE(simulate.output().find("Simulation complete"), std::string::npos);
  const ProgramResult grade = run(kFosssim + " -s " + scene + " -d 0 -q --duration 0.05 -i " +
                                  path("out.bin") + " --residual-file " + path("residual.txt"));
  EXPECT_EQ(grade.status, 0) << grade.output();
  EXPECT_NE(grade.output().find("Overall success: Passed."), std::string::npos) << grade.output();
}

TEST_F(CommandLine3D, RunsTheAssignmentsJsonScenes) {
  const ProgramResult json = run(kFosssim + " -s " + asset("json/cloth_9x9.json") +
                                 " -d 0 -q --duration 0.2 -o " + path("j.bin"));
  EXPECT_EQ(json.status, 0) << json.output();
  EXPECT_EQ(std::filesystem::file_size(path("j.bin")), 7u * 2u * 81u * 3u * 8u);
}

TEST_F(CommandLine3D, TheIterationStartIsReadAlikeFromJsonKeysXmlAttributesAndTheCommandLine) {
  const auto bytes = [this](const std::string& arguments, const std::string& name) {
    const ProgramResult r =
        run(kFosssim + " " + arguments + " -d 0 -q --duration 0.3 -o " + path(name));
    EXPECT_EQ(r.status, 0) << arguments << "\n" << r.output();
    return folder_.read(name);
  };
  // JSON scenes start at the current positions unless the key or the option says otherwise.
  write("inertial.json", "{\"obj\": \"" + asset("cloth/cloth_flat_9x9.obj") +
                             "\", \"k\": 20000, \"b\": [1, 9], \"start\": \"inertial\"}");
  const std::string json = "-s " + asset("json/cloth_9x9.json");
  const std::string current = bytes(json, "current.bin");
  const std::string by_option = bytes(json + " --integrator-option start=inertial", "o.bin");
  const std::string by_key = bytes("-s " + path("inertial.json"), "k.bin");
  EXPECT_EQ(by_option, by_key);
  EXPECT_NE(by_option, current);
  // XML scenes start at the inertial prediction unless the attribute or the option says so.
  const std::string xml = R"(<scene dim="3">
  <duration time="1"/>
  <integrator type="local-global" dt="0.03" iterations="5" START/>
  <generate type="cloth" nx="6" ny="6" k="500" mass="voronoi" density="0.1"/>
  <simplegravity fx="0" fy="-9.8" fz="0"/>
</scene>)";
  std::string with = xml, without = xml;
  with.replace(with.find("START"), 5, "start=\"current\"");
  without.replace(without.find("START"), 5, "");
  write("with.xml", with);
  write("without.xml", without);
  const std::string by_attribute = bytes("-s " + path("with.xml"), "a.bin");
  EXPECT_EQ(bytes("-s " + path("without.xml") + " --integrator-option start=current", "c.bin"),
            by_attribute);
  EXPECT_NE(bytes("-s " + path("without.xml"), "i.bin"), by_attribute);
}

TEST_F(CommandLine3D, RejectsAMalformedMeshWithItsLineAndStatus2) {
  write("broken.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 4\n");
  const std::string scene = write("scene.xml", R"(<scene dim="3">
  <duration time="1"/>
  <integrator type="local-global" dt="0.01"/>
  <clothmesh file="broken.obj" k="1" m="1"/>
</scene>)");
  const ProgramResult result = run(kFosssim + " -s " + scene + " -d 0 -o " + path("out.bin"));
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output().find(path("broken.obj") +
                                 ":4: error: vertex index 4 is past the last vertex"),
            std::string::npos)
      << result.output();
  EXPECT_FALSE(std::filesystem::exists(path("out.bin")));
}

TEST_F(CommandLine3D, GeneratesMeshesAndJsonScenesThatRun) {
  const ProgramResult cloth = run(kGenerate + " -o " + path("c.obj") + " --json " + path("c.json") +
                                  " --k 5000 cloth --nx 6 --ny 4");
  ASSERT_EQ(cloth.status, 0) << cloth.output();
  EXPECT_NE(cloth.output().find("24 vertices"), std::string::npos) << cloth.output();
  const ProgramResult json = run(kFosssim + " -s " + path("c.json") + " -d 0 -q --duration 0.1");
  EXPECT_EQ(json.status, 0) << json.output();
  const ProgramResult ball = run(kGenerate + " -o " + path("b.mesh") + " tetball --cells 4");
  ASSERT_EQ(ball.status, 0) << ball.output();
  write("ball.xml", R"(<scene dim="3">
  <duration time="0.05"/>
  <integrator type="linearly-implicit-euler" dt="0.01"/>
  <tetmesh file="b.mesh" k="100" mass="volume" density="10"><pin axis="y" side="highest" within="0.01"/></tetmesh>
  <simplegravity fx="0" fy="-9.8" fz="0"/>
</scene>)");
  const ProgramResult ball_run = run(kFosssim + " -s " + path("ball.xml") + " -d 0 -q");
  EXPECT_EQ(ball_run.status, 0) << ball_run.output();
  const ProgramResult wrong = run(kGenerate + " -o " + path("b.obj") + " tetbox");
  EXPECT_EQ(wrong.status, 2);
  EXPECT_NE(wrong.output().find("MEDIT (.mesh)"), std::string::npos) << wrong.output();
  const ProgramResult bad_pins = run(kGenerate + " -o " + path("c2.obj") + " --json " +
                                     path("c2.json") + " --pins middle cloth");
  EXPECT_EQ(bad_pins.status, 2);
  // Sizes over the limit are refused before anything is generated, and the limit can be set.
  const ProgramResult huge =
      run(kGenerate + " -o " + path("h.mesh") + " tetbox --nx 2000 --ny 2000 --nz 2000");
  EXPECT_EQ(huge.status, 2);
  EXPECT_NE(huge.output().find("FOSSSim-generate: error: a tetbox of 2000 × 2000 × 2000 cubes has "
                               "8012006001 vertices, more than the limit of 1000000 particles"),
            std::string::npos)
      << huge.output();
  EXPECT_FALSE(std::filesystem::exists(path("h.mesh")));
  EXPECT_EQ(
      run(kGenerate + " -o " + path("c3.obj") + " --max-particles 23 cloth --nx 6 --ny 4").status,
      2);
}

// FOSSSim-generate checks its numbers as FOSSSim does, so it never writes a file FOSSSim
// refuses, and never lets one of its outputs replace the other.
TEST_F(CommandLine3D, GenerateRefusesNumbersAndNamesThatWouldMakeBadFiles) {
  const auto refused = [this](const std::string& arguments, const std::string& message) {
    const ProgramResult r = run(kGenerate + " " + arguments);
    EXPECT_EQ(r.status, 2) << arguments << "\n" << r.output();
    EXPECT_NE(r.output().find(message), std::string::npos) << arguments << "\n" << r.output();
  };
  const std::string out = " -o " + path("c.obj") + " ";
  refused(out + "--json " + path("c.json") + " --k nan cloth", "found 'nan'");
  refused(out + "--json " + path("c.json") + " --k 1e400 cloth", "found '1e400'");
  refused(out + "--json " + path("c.json") + " --k -1 cloth", "--k must be between 0 and");
  refused(out + "--json " + path("c.json") + " --k 0x10 cloth", "found '0x10'");
  refused(out + "cloth --width 1e308", "sizes must be at most 1e+06 m, found 1e+308");
  refused(out + "cloth --nx 0x10", "found '0x10'");
  refused(out + "--json " + path("c.obj") + " cloth", "name the same file");
  refused(out + "--json " + path("./c.obj") + " cloth", "name the same file");
  refused(out + "--json " + path("c.xml") + " cloth", "must end in .json");
  refused("-o '' cloth", "the name cannot be empty");
  EXPECT_FALSE(std::filesystem::exists(path("c.obj")));
  EXPECT_FALSE(std::filesystem::exists(path("c.json")));
  // What it writes, FOSSSim reads: a folder name with a quote is escaped in the JSON.
  std::filesystem::create_directories(path("a\"b"));
  const ProgramResult made = run(kGenerate + " -o '" + path("a\"b/c.obj") + "' --json " +
                                 path("c.json") + " --k 100 cloth --nx 3 --ny 3");
  ASSERT_EQ(made.status, 0) << made.output();
  const ProgramResult ran =
      run(kFosssim + " -s " + path("c.json") + " -d 0 -q --duration 0.01 -o /dev/null");
  EXPECT_EQ(ran.status, 0) << ran.output();
}

TEST_F(CommandLine3D, SparseSolversGiveTheSameBitsFromRunToRunOnTwoThreads) {
  // A 50x50 cloth: 7500 unknowns, past the size where the step solver takes CHOLMOD's factors
  // (supernodal, with OpenBLAS behind it) and GMRES. With two BLAS and OpenMP threads
  // (--threads 2) the trajectories of two runs must be identical, byte for byte, for every
  // sparse method, and the run says how many threads it used.
  for (const std::string method :
       {"linearly-implicit-euler", "newton", "quasi-newton", "accelerated-local-global"}) {
    write(method + ".xml", cloth_50_scene(method, "0.1"));
    std::string runs[2];
    for (int r = 0; r < 2; ++r) {
      const std::string out = method + std::to_string(r) + ".bin";
      const ProgramResult result =
          run(kFosssim + " --threads 2 -s " + path(method + ".xml") + " -d 0 -q -o " + path(out));
      ASSERT_EQ(result.status, 0) << method << "\n" << result.output();
      EXPECT_NE(result.output().find("FOSSSim: note: the sparse solvers use 2 BLAS threads"),
                std::string::npos)
          << result.output();
      runs[r] = folder_.read(out);
    }
    EXPECT_GT(runs[0].size(), 6u * 2500u * 3u * 8u) << method;
    EXPECT_TRUE(runs[0] == runs[1]) << method << ": two runs differ";
  }
}

// The thread count is --threads alone (default 1): the environment's OPENBLAS_NUM_THREADS and
// OMP_NUM_THREADS do not change a run's bytes, and a default run says nothing about threads.
TEST_F(CommandLine3D, TheDefaultOfOneSolverThreadOverridesTheEnvironment) {
  write("cloth.xml", cloth_50_scene("linearly-implicit-euler", "0.06"));
  const ProgramResult by_environment =
      run("OPENBLAS_NUM_THREADS=2 OMP_NUM_THREADS=2 " + kFosssim + " -s " + path("cloth.xml") +
          " -d 0 -q -o " + path("environment.bin"));
  ASSERT_EQ(by_environment.status, 0) << by_environment.output();
  EXPECT_EQ(by_environment.output().find("threads"), std::string::npos) << by_environment.output();
  const ProgramResult one =
      run("OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 " + kFosssim + " --threads 1 -s " +
          path("cloth.xml") + " -d 0 -q -o " + path("one.bin"));
  ASSERT_EQ(one.status, 0) << one.output();
  EXPECT_TRUE(folder_.read("environment.bin") == folder_.read("one.bin"));
}

// OpenBLAS starts its thread pool when it is loaded, by the first factorization
// (core/solvers/solver_libraries.h): the count is set from the command line before that. A run
// with one thread is a process of one thread from start to end, whatever the environment asks;
// a run that factors nothing loads no BLAS and starts no thread even with --threads 2; and a run
// that factors (the 50x50 cloth, CHOLMOD) with --threads 2 (in either spelling) gives the BLAS
// its second thread. The run summary counts the process's threads at the end of the run
// (/proc/self/task).
TEST_F(CommandLine3D, TheProcessHasTheThreadsTheCommandLineAsksFor) {
  if (!std::filesystem::exists("/proc/self/task")) GTEST_SKIP() << "no /proc";
  write("ball.xml", R"(<scene>
  <duration time="0.02"/>
  <integrator type="explicit-euler" dt="0.01"/>
  <particle m="1" px="0" py="0" vx="1" vy="0" fixed="0"/>
</scene>)");
  write("cloth.xml", cloth_50_scene("linearly-implicit-euler", "0.02"));
  const auto threads_of = [&](const std::string& environment, const std::string& option,
                              const std::string& name, const char* scene = "ball.xml") -> long {
    const ProgramResult result = run(environment + " " + kFosssim + " " + option + " -s " +
                                     path(scene) + " -d 0 -q --stats-json " + path(name));
    EXPECT_EQ(result.status, 0) << result.output();
    const std::string text = folder_.read(name);
    const std::string key = "\"threads\": ";
    const std::size_t at = text.find(key);
    if (at == std::string::npos) {
      ADD_FAILURE() << text;
      return -1;
    }
    return std::stol(text.substr(at + key.size()));
  };
  EXPECT_EQ(threads_of("", "", "default.json"), 1);
  EXPECT_EQ(threads_of("OPENBLAS_NUM_THREADS=4 OMP_NUM_THREADS=4", "", "environment.json"), 1);
  EXPECT_EQ(threads_of("OPENBLAS_NUM_THREADS=4", "--threads 1", "one.json"), 1);
  EXPECT_EQ(threads_of("", "--threads 2", "no_factor.json"), 1);
  EXPECT_EQ(
      threads_of("OPENBLAS_NUM_THREADS=4 OMP_NUM_THREADS=4", "", "cloth_default.json", "cloth.xml"),
      1);
  EXPECT_EQ(threads_of("", "--threads 2", "two.json", "cloth.xml"), 2);
  EXPECT_EQ(threads_of("OPENBLAS_NUM_THREADS=1", "--threads=2", "two_equals.json", "cloth.xml"), 2);
}

TEST_F(CommandLine3D, ThreadsMustBeAPositiveCount) {
  for (const char* bad : {"0", "-1", "x", "1.5"}) {
    const ProgramResult result =
        run(kFosssim + " --threads " + bad + " -s " + path("none.xml") + " -d 0");
    EXPECT_EQ(result.status, 2) << bad << "\n" << result.output();
    EXPECT_NE(result.output().find("--threads"), std::string::npos) << result.output();
  }
}

// Issue 24: a signal used to be looked at between steps only, so a step that never ends could
// not be interrupted. Here one step is a million local/global iterations of a 40x40 cloth
// (minutes); SIGTERM must end the run within 2 s, in the middle of that step, keeping its
// frames as out.bin.incomplete and leaving nothing under the final name.
TEST_F(CommandLine3D, SigtermEndsARunInsideAStepThatWouldTakeMinutes) {
  write("long.xml", R"(<scene dim="3">
  <duration time="1"/>
  <integrator type="local-global" dt="0.01" iterations="1000000" tolerance="0"/>
  <generate type="cloth" nx="40" ny="40" plane="xz" pin="corners" k="1000" m="0.001"/>
  <simplegravity fx="0" fy="-9.8" fz="0"/>
</scene>)");
  const ProgramResult result =
      run(kFosssim + " -s " + path("long.xml") + " -d 0 -q -o " + path("out.bin") +
          " & pid=$!; i=0; while [ $i -lt 600 ] && ! ls | grep -q 'partial$'; do sleep 0.05; "
          "i=$((i+1)); done; sleep 0.5; start=$(date +%s%N); kill -s TERM $pid; wait $pid; "
          "status=$?; echo \"ms $(( ($(date +%s%N) - start) / 1000000 ))\"; exit $status");
  EXPECT_EQ(result.status, 130) << result.output();
  EXPECT_NE(result.err.find("FOSSSim: interrupted by signal 15 (Terminated) at step 0"),
            std::string::npos)
      << result.err;
  const std::size_t at = result.out.find("ms ");
  ASSERT_NE(at, std::string::npos) << result.output();
  EXPECT_LT(std::stol(result.out.substr(at + 3)), 2000) << result.output();
  EXPECT_FALSE(std::filesystem::exists(path("out.bin")));
  EXPECT_TRUE(std::filesystem::exists(path("out.bin.incomplete")));
}

// The same inside grading (-i): the reference step restarted from the file's frame is a million
// local/global iterations; SIGTERM must end the grading within 2 s with no report.
TEST_F(CommandLine3D, SigtermEndsAGradingInsideAReferenceStep) {
  const std::string cloth =
      R"(<generate type="cloth" nx="40" ny="40" plane="xz" pin="corners" k="1000" m="0.001"/>
  <simplegravity fx="0" fy="-9.8" fz="0"/>
</scene>)";
  write("short.xml", R"(<scene dim="3">
  <duration time="0.02"/>
  <integrator type="local-global" dt="0.01" iterations="1"/>
  )" + cloth);
  write("long.xml", R"(<scene dim="3">
  <duration time="0.02"/>
  <integrator type="local-global" dt="0.01" iterations="1000000" tolerance="0"/>
  )" + cloth);
  const ProgramResult written =
      run(kFosssim + " -s " + path("short.xml") + " -d 0 -q -o " + path("short.bin"));
  ASSERT_EQ(written.status, 0) << written.output();
  const ProgramResult result =
      run(kFosssim + " -s " + path("long.xml") + " -d 0 -q -i " + path("short.bin") +
          " & pid=$!; sleep 1; start=$(date +%s%N); kill -s TERM $pid; wait $pid; "
          "status=$?; echo \"ms $(( ($(date +%s%N) - start) / 1000000 ))\"; exit $status");
  EXPECT_EQ(result.status, 130) << result.output();
  EXPECT_NE(result.err.find("FOSSSim: interrupted at step 0 of the grading"), std::string::npos)
      << result.err;
  const std::size_t at = result.out.find("ms ");
  ASSERT_NE(at, std::string::npos) << result.output();
  EXPECT_LT(std::stol(result.out.substr(at + 3)), 2000) << result.output();
}

}  // namespace
