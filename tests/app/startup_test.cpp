// What a FOSSSim run loads when it starts (docs/limits-and-failures.md, "Start-up"): Cairo and
// GLUT with OpenGL and X11 only when the run draws or opens its window, not in a headless run;
// the sparse solvers' libraries (CHOLMOD, UMFPACK, MUMPS, OpenBLAS) only when it factors.
// glibc's loader says which shared objects it maps (LD_DEBUG=files, on standard error). A picture
// run on a machine without Cairo fails as unavailable (exit 2), naming it and its package.

#include <gtest/gtest.h>

#include <string>

#include "support/run_program.h"
#include "support/scratch_folder.h"
#include "support/tiny_scenes.h"

namespace fosssim {
namespace {

class Startup : public ::testing::Test {
 protected:
  void SetUp() override { folder_.write("scene.xml", testing::kTinyScene); }
  /// The run's output, with the loader's list of the objects it mapped.
  std::string loaded_by(const std::string& arguments) {
    const testing::ProgramResult result = testing::run_command(
        folder_, "LD_DEBUG=files timeout -k 5 60 " + testing::quoted(testing::fosssim_program()) +
                     " " + arguments);
    EXPECT_EQ(result.status, 0) << result.output();
    EXPECT_NE(result.output().find("file="), std::string::npos)
        << "the loader does not list what it maps (not glibc?)";
    return result.output();
  }
  testing::ScratchFolder folder_;
};

TEST_F(Startup, AHeadlessRunLoadsNoDrawingLibrary) {
  const std::string loaded = loaded_by("-s scene.xml -d 0 -q -o out.bin");
  for (const char* library : {"libcairo", "libglut", "libGL", "libX11", "libfontconfig"}) {
    EXPECT_EQ(loaded.find(library), std::string::npos) << library << " was loaded:\n" << loaded;
  }
}

TEST_F(Startup, ARunThatFactorsNothingLoadsNoSolverLibrary) {
  const std::string loaded = loaded_by("--threads 2 -s scene.xml -d 0 -q -o out.bin");
  for (const char* library : {"libcholmod", "libumfpack", "mumps", "libopenblas", "libblas",
                              "liblapack", "libgfortran", "libgomp"}) {
    EXPECT_EQ(loaded.find(library), std::string::npos) << library << " was loaded:\n" << loaded;
  }
}

TEST_F(Startup, ARunThatFactorsLoadsItsSolverWhenItFactors) {
  // Implicit Euler on a 50x50 cloth: its step matrix is factored by MUMPS, with OpenBLAS.
  folder_.write("cloth.xml", R"(<scene dim="3">
  <duration time="0.02"/>
  <integrator type="linearly-implicit-euler" dt="0.02"/>
  <generate type="cloth" nx="50" ny="50" plane="xz" pin="corners" k="200" m="0.001"/>
</scene>)");
  const std::string loaded = loaded_by("-s cloth.xml -d 0 -q -o out.bin");
  EXPECT_NE(loaded.find("libdmumps_seq"), std::string::npos) << loaded;
  EXPECT_NE(loaded.find("libopenblas.so"), std::string::npos) << loaded;
  EXPECT_TRUE(folder_.exists("out.bin"));
}

TEST_F(Startup, APictureRunLoadsCairoWhenItDraws) {
  const std::string loaded = loaded_by("-s scene.xml -d 0 -q --duration 0 -m svgs");
  EXPECT_NE(loaded.find("libcairo.so"), std::string::npos) << loaded;
  EXPECT_EQ(loaded.find("libglut"), std::string::npos) << loaded;
  EXPECT_TRUE(folder_.exists("svgs/frame_00000.svg"));
}

TEST_F(Startup, APictureRunWithoutCairoIsUnavailableNamingItAndItsPackage) {
  // An empty libcairo.so.2 first on the loader's path stands for a machine without Cairo.
  folder_.write("no-cairo/libcairo.so.2", "");
  const testing::ProgramResult result = testing::run_command(
      folder_, "LD_LIBRARY_PATH=" + testing::quoted(folder_ / "no-cairo") + " timeout -k 5 60 " +
                   testing::quoted(testing::fosssim_program()) +
                   " -s scene.xml -d 0 -q --duration 0 -m svgs");
  EXPECT_EQ(result.status, 2) << result.output();  // unavailable
  EXPECT_NE(result.err.find("pictures need Cairo: cannot load libcairo.so.2: "), std::string::npos)
      << result.err;
  EXPECT_NE(result.err.find("(install the libcairo2 package)"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace fosssim
