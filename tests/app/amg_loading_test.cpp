// Hypre (and the OpenMPI it is built with) is loaded only by a run that asks for multigrid
// (core/solvers/amg_solver.h, docs/solvers.md "Algebraic multigrid"): the dynamic loader's own
// log (LD_DEBUG=libs, glibc) lists every library a FOSSSim run initialises.
// - a run that never asks for multigrid initialises neither libHYPRE nor libmpi;
// - a run with solver=amg initialises both (when the build has hypre), so the first check
//   is not vacuous;
// - a run with solver=amg whose hypre library cannot be loaded says so once, on standard error,
//   exits 0, and writes the same bytes as a run of the same scene with solver=eigen, the path
//   that then answers.

#include <gtest/gtest.h>

#include <string>

#include "core/solvers/amg_solver.h"
#include "support/run_program.h"
#include "support/scratch_folder.h"
#include "support/tiny_scenes.h"

namespace fosssim {
namespace {

using testing::ProgramResult;

std::size_t count(const std::string& text, const std::string& word) {
  std::size_t n = 0;
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
  return n;
}

class AmgLoading : public ::testing::Test {
 protected:
  void SetUp() override { folder_.write("spring.xml", testing::kFixedSpringScene); }

  /// FOSSSim on the spring scene, writing `output`, with `environment` before the command.
  ProgramResult run(const std::string& environment, const std::string& solver,
                    const std::string& output) {
    std::string command = environment + " " + testing::quoted(testing::fosssim_program()) +
                          " -s spring.xml -d 0 -o " + output;
    if (!solver.empty()) command += " --integrator-option solver=" + solver;
    return testing::run_command(folder_, command);
  }

  testing::ScratchFolder folder_;
};

TEST_F(AmgLoading, RunsThatDoNotAskForMultigridLoadNeitherHypreNorMpi) {
  for (const std::string solver : {"", "auto", "eigen", "sparse-direct"}) {
    const ProgramResult r = run("LD_DEBUG=libs", solver, "out.bin");
    ASSERT_EQ(r.status, 0) << r.output();
    ASSERT_GT(count(r.err, "calling init:"), 0u) << "the loader's log is missing: " << r.err;
    EXPECT_EQ(count(r.err, "libHYPRE"), 0u) << solver;
    EXPECT_EQ(count(r.err, "libmpi"), 0u) << solver;
    EXPECT_EQ(count(r.err, "libopen-pal"), 0u) << solver;
  }
}

TEST_F(AmgLoading, AMultigridRunLoadsHypreAndMpi) {
  if (!amg_built_in()) GTEST_SKIP() << "built without hypre";
  const ProgramResult r = run("LD_DEBUG=libs", "amg", "out.bin");
  ASSERT_EQ(r.status, 0) << r.output();
  EXPECT_GT(count(r.err, "libHYPRE-"), 0u)
      << "hypre was not loaded";
  EXPECT_GT(count(r.err, "libmpi.so"), 0u) << "OpenMPI was not loaded";
}

TEST_F(AmgLoading, AMissingHypreIsSaidOnceAndTheDirectPathAnswers) {
  if (!amg_built_in()) GTEST_SKIP() << "built without hypre";
  const ProgramResult missing =
      run("FOSSSIM_HYPRE_LIBRARY=libFOSSSim-no-such-hypre.so", "amg", "missing.bin");
  ASSERT_EQ(missing.status, 0) << missing.output();
  EXPECT_EQ(count(missing.err, "algebraic multigrid (solver=\"amg\") is not available"), 1u)
      << missing.err;
  EXPECT_GT(count(missing.err, "cannot load libFOSSSim-no-such-hypre.so"), 0u) << missing.err;
  const ProgramResult direct = run("", "eigen", "direct.bin");
  ASSERT_EQ(direct.status, 0) << direct.output();
  const std::string bytes = folder_.read("missing.bin");
  EXPECT_GT(bytes.size(), 20u * 2 * 4 * 8);  // more than 20 frames of 2 particles' x, y, vx, vy
  EXPECT_EQ(bytes, folder_.read("direct.bin"));
}

}  // namespace
}  // namespace fosssim
