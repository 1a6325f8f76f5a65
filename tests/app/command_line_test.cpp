// The FOSSSim executable as the course's grading script and students use it (docs/command-line.md):
// flags, messages, exit statuses and the files it leaves behind.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>

#include "core/collisions/contact_registry.h"
#include "core/integrators/integrator_registry.h"
#include "support/run_program.h"
#include "support/scratch_folder.h"

namespace fosssim {
namespace {

namespace fs = std::filesystem;
using testing::ProgramResult;

// One free particle on a damped spring to a fixed one, under gravity: 100 steps.
constexpr const char* kDampedSpringScene = R"(<scene>
  <description text="A damped spring."/>
  <duration time="1.0"/>
  <integrator type="implicit-euler" dt="0.01"/>
  <particle m="1" px="0" py="0" vx="0" vy="0" fixed="1"/>
  <particle m="1" px="1.2" py="0.1" vx="0" vy="0" fixed="0"/>
  <edge i="0" j="1"/>
  <springforce edge="0" k="20" l0="1" b="0.3"/>
  <simplegravity fx="0" fy="-9.81"/>
</scene>)";

// Explicit Euler on a very stiff spring with a large step: blows up within a few dozen steps.
constexpr const char* kExplodingScene = R"(<scene>
  <duration time="10.0"/>
  <integrator type="explicit-euler" dt="0.1"/>
  <particle m="1" px="0" py="0" vx="0" vy="0" fixed="1"/>
  <particle m="1" px="1.5" py="0" vx="0" vy="0" fixed="0"/>
  <edge i="0" j="1"/>
  <springforce edge="0" k="1e6" l0="1"/>
</scene>)";

constexpr std::int64_t kSpringFrameBytes = 2 * 4 * 8;

class CommandLine : public ::testing::Test {
 protected:
  void SetUp() override {
    write("spring.xml", kDampedSpringScene);
    write("explode.xml", kExplodingScene);
  }

  void write(const std::string& name, const std::string& content) { folder_.write(name, content); }
  std::string read(const std::string& name) const { return folder_.read(name); }
  bool exists(const std::string& name) const { return folder_.exists(name); }
  std::string path(const std::string& name) const { return folder_ / name; }

  ProgramResult fosssim(std::vector<std::string> args) {
    args.insert(args.begin(), testing::fosssim_program());
    return testing::run_program(args, folder_.path().string());
  }

  testing::ScratchFolder folder_;
};

TEST_F(CommandLine, HelpDocumentsEveryOptionAndExitStatus) {
  const ProgramResult r = fosssim({"--help"});
  EXPECT_EQ(r.status, 0);
  for (const char* text :
       {"-s,--scene", "-d,--display", "-p,--paused", "-o,--output", "-i,--input", "--duration",
        "--dt", "--newton-max-iterations", "--newton-tolerance", "--residual-file",
        "--check-derivatives", "--integrator-option", "Exit status"}) {
    EXPECT_NE(r.out.find(text), std::string::npos) << text;
  }
  // Every integrator of the registry, its aliases and its options, from the registry itself.
  for (const IntegratorMethod* method : integrator_methods()) {
    EXPECT_NE(r.out.find("  " + std::string(method->name)), std::string::npos) << method->name;
    for (std::string_view alias : method->aliases) {
      EXPECT_NE(r.out.find(std::string(alias)), std::string::npos) << alias;
    }
    for (const OptionSpec& option : method->options) {
      EXPECT_NE(r.out.find(std::string(option.name) + " = " + option.describe_values()),
                std::string::npos)
          << option.name;
    }
  }
  // Every contact method of the registry and its options.
  for (const ContactMethod* method : contact_methods()) {
    EXPECT_NE(
        r.out.find("  " + std::string(method->name) + "\n      " + std::string(method->summary)),
        std::string::npos)
        << method->name;
    for (const OptionSpec& option : method->options) {
      EXPECT_NE(r.out.find(std::string(option.name) + " = " + option.describe_values() +
                           " (default " + option.default_text() + ")"),
                std::string::npos)
          << method->name << " " << option.name;
    }
  }
}

TEST_F(CommandLine, RunWritesTheTrajectoryAndSaysTheCompatMessage) {
  const ProgramResult r = fosssim({"-s", "spring.xml", "-d", "0", "-o", "out.bin"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "A damped spring.\nSimulation complete at time 1. Exiting.\n");
  EXPECT_EQ(r.err, "");  // no progress bar when standard error is not a terminal
  EXPECT_EQ(static_cast<std::int64_t>(fs::file_size(path("out.bin"))), 101 * kSpringFrameBytes);
  EXPECT_FALSE(exists("out.bin.partial"));
}

TEST_F(CommandLine, AtATerminalARunSaysWhatItWroteAndWhere) {
  // `script` runs the program with a terminal as its standard error, as a person would.
  const char* script = "/usr/bin/script";  // util-linux, on every Debian machine
  if (!fs::exists(script)) GTEST_SKIP() << "no " << script;
  const ProgramResult r = testing::run_program(
      {script, "-qec",
       testing::fosssim_program() + " -s spring.xml -d 0 -o out.bin --energy-csv e.csv",
       "/dev/null"},
      folder_.path().string());
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("FOSSSim: wrote the trajectory out.bin (101 frames) and the energies e.csv"),
            std::string::npos)
      << r.out;
  // With -q, or when standard error is not a terminal (the course's scripts), it says nothing.
  const ProgramResult quiet = testing::run_program(
      {script, "-qec", testing::fosssim_program() + " -s spring.xml -d 0 -q -o out.bin",
       "/dev/null"},
      folder_.path().string());
  EXPECT_EQ(quiet.out.find("FOSSSim: wrote"), std::string::npos) << quiet.out;
}

TEST_F(CommandLine, RunWithoutOutputFileStillCompletes) {
  const ProgramResult r = fosssim({"-s", "spring.xml", "-d", "0", "-q"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "Simulation complete at time 1. Exiting.\n");
}

TEST_F(CommandLine, TwoRunsGiveIdenticalBytes) {
  ASSERT_EQ(fosssim({"-s", "spring.xml", "-d", "0", "-o", "a.bin"}).status, 0);
  ASSERT_EQ(fosssim({"-s", "spring.xml", "-d", "0", "-o", "b.bin"}).status, 0);
  EXPECT_FALSE(read("a.bin").empty());
  EXPECT_TRUE(read("a.bin") == read("b.bin"));
}

TEST_F(CommandLine, GradingPassesItsOwnRunAndWritesResiduals) {
  ASSERT_EQ(fosssim({"-s", "spring.xml", "-d", "0", "-o", "out.bin"}).status, 0);
  const ProgramResult r = fosssim({"-s", "spring.xml", "-d", "0", "-i", "out.bin"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out,
            "A damped spring.\n"
            "Accumulated Position Residual: 0   Passed.\n"
            "Accumulated Velocity Residual: 0   Passed.\n"
            "Maximum Position Residual: 0   Passed.\n"
            "Maximum Velocity Residual: 0   Passed.\n"
            "Overall success: Passed.\n");
  EXPECT_EQ(read("residual.txt"), "1   0\n1   0\n1   0\n1   0\n");
}

TEST_F(CommandLine, GradingFailsAPerturbedStepAndSaysWhere) {
  ASSERT_EQ(fosssim({"-s", "spring.xml", "-d", "0", "-o", "out.bin"}).status, 0);
  std::string bytes = read("out.bin");
  double x = 0.0;
  const std::size_t offset = 42 * kSpringFrameBytes + 2 * 8;  // frame 42, particle 1, x
  std::memcpy(&x, bytes.data() + offset, 8);
  x += 1e-9;
  std::memcpy(bytes.data() + offset, &x, 8);
  write("out.bin", bytes);
  const ProgramResult r = fosssim({"-s", "spring.xml", "-d", "0", "-i", "out.bin", "-q"});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("Maximum Position Residual: 1e-09   Failed.\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Overall success: Failed.\n"), std::string::npos);
  EXPECT_NE(r.err.find("First divergence at step 42, particle 1"), std::string::npos) << r.err;
  EXPECT_EQ(read("residual.txt").substr(0, 4), "1   ");
}

TEST_F(CommandLine, GradingACutShortFileIsAnError) {
  ASSERT_EQ(fosssim({"-s", "spring.xml", "-d", "0", "-o", "out.bin"}).status, 0);
  fs::resize_file(path("out.bin"), 60 * kSpringFrameBytes);
  const ProgramResult r = fosssim({"-s", "spring.xml", "-d", "0", "-i", "out.bin"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err,
            "FOSSSim: error: out.bin: the trajectory has 60 frames, but the scene takes 100 steps "
            "and so needs 101 (the initial state and one frame per step); the file was cut short, "
            "or made with another duration\n");
  EXPECT_EQ(r.out.find("Overall success"), std::string::npos);
}

// Issue 23: a trajectory made with another --dt was called "cut short"; its first step tells
// its time step, and the message says so.
TEST_F(CommandLine, GradingAFileOfAnotherTimeStepSaysSo) {
  ASSERT_EQ(fosssim({"-s", "spring.xml", "-d", "0", "--dt", "0.005", "-o", "half.bin"}).status, 0);
  const ProgramResult r = fosssim({"-s", "spring.xml", "-d", "0", "-i", "half.bin"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("the trajectory has 201 frames, but the scene takes 100 steps and so "
                       "needs 101 (the initial state and one frame per step); its frames are "
                       "0.005 s apart"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("not the scene's 0.01 s: it was made with another time step (grade with "
                       "--dt 0.005, as it was run)"),
            std::string::npos)
      << r.err;
}

TEST_F(CommandLine, GradingAFileOfTheWrongSizeIsAnError) {
  write("garbage.bin", "not a trajectory");
  const ProgramResult r = fosssim({"-s", "spring.xml", "-d", "0", "-i", "garbage.bin"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("garbage.bin has 16 bytes, not a whole number of frames of 64 bytes"),
            std::string::npos)
      << r.err;
}

TEST_F(CommandLine, BlowUpStopsAtTheStepAndKeepsOnlyAnIncompleteFile) {
  write("out.bin", "earlier run");
  const ProgramResult r = fosssim({"-s", "explode.xml", "-d", "0", "-o", "out.bin"});
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find("FOSSSim: error: explode.xml: step "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(": particle 1 has a non-finite "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("frames computed so far are in out.bin.incomplete"), std::string::npos);
  EXPECT_EQ(read("out.bin"), "earlier run");
  ASSERT_TRUE(exists("out.bin.incomplete"));
  EXPECT_EQ(fs::file_size(path("out.bin.incomplete")) % kSpringFrameBytes, 0u);
  EXPECT_EQ(r.out.find("Simulation complete"), std::string::npos);
}

TEST_F(CommandLine, DurationAndTimeStepCanBeOverridden) {
  const ProgramResult r =
      fosssim({"-s", "spring.xml", "-d", "0", "--duration", "0.5", "--dt", "0.001", "-o", "o.bin"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(static_cast<std::int64_t>(fs::file_size(path("o.bin"))), 501 * kSpringFrameBytes);
  const ProgramResult graded =
      fosssim({"-s", "spring.xml", "-d", "0", "--duration", "0.5", "--dt", "0.001", "-i", "o.bin"});
  EXPECT_EQ(graded.status, 0) << graded.err;
}

TEST_F(CommandLine, InvalidOverridesAreRejected) {
  const ProgramResult r = fosssim({"-s", "spring.xml", "-d", "0", "--dt", "-1"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "FOSSSim: error: --dt must be a finite number > 0, found -1\n");
}

TEST_F(CommandLine, IntegratorOptionsAreValidatedAgainstTheScenesMethod) {
  // spring.xml runs implicit Euler: its options apply, others are refused with its list.
  ProgramResult r = fosssim({"-s", "spring.xml", "-d", "0", "--integrator-option", "iterations=3"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err,
            "FOSSSim: error: --integrator-option: the scene's integrator implicit-euler has no "
            "option 'iterations' (its options: newton-tolerance, newton-max-iterations, "
            "solver)\n");
  r = fosssim({"-s", "spring.xml", "-d", "0", "--integrator-option", "newton-max-iterations=0"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err,
            "FOSSSim: error: --integrator-option newton-max-iterations: must be a whole number "
            "from 1 to 1000000, found 0\n");
  r = fosssim({"-s", "spring.xml", "-d", "0", "--integrator-option", "newton-tolerance"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("must be NAME=VALUE"), std::string::npos) << r.err;
  // The same setting through the option and through its shorthand gives the same bytes.
  ASSERT_EQ(fosssim({"-s", "spring.xml", "-d", "0", "-q", "--integrator-option",
                     "newton-tolerance=1e-3", "-o", "a.bin"})
                .status,
            0);
  ASSERT_EQ(
      fosssim({"-s", "spring.xml", "-d", "0", "-q", "--newton-tolerance", "1e-3", "-o", "b.bin"})
          .status,
      0);
  ASSERT_EQ(fosssim({"-s", "spring.xml", "-d", "0", "-q", "-o", "c.bin"}).status, 0);
  EXPECT_EQ(read("a.bin"), read("b.bin"));
  EXPECT_NE(read("a.bin"), read("c.bin")) << "a looser tolerance changes the trajectory";
}

TEST_F(CommandLine, NewtonShorthandsOnAnotherMethodAreIgnoredWithAWarning) {
  write("explicit.xml",
        "<scene>\n<duration time=\"0.1\"/>\n<integrator type=\"explicit-euler\" "
        "dt=\"0.1\"/>\n</scene>\n");
  const ProgramResult r =
      fosssim({"-s", "explicit.xml", "-d", "0", "-q", "--newton-max-iterations", "5"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err,
            "FOSSSim: warning: --newton-max-iterations ignored: the scene's integrator "
            "explicit-euler has no option 'newton-max-iterations' (its options: none)\n");
}

TEST_F(CommandLine, NewtonThatCannotConvergeNamesTheStep) {
  const ProgramResult r = fosssim({"-s", "spring.xml", "-d", "0", "--newton-max-iterations", "2",
                                   "--newton-tolerance", "1e-300", "-o", "out.bin"});
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find("step 1: implicit Euler: Newton's method did not converge in 2 iterations"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(exists("out.bin"));
}

TEST_F(CommandLine, BadSceneGivesFileLineAndExitTwo) {
  write("bad.xml",
        "<scene>\n<duration time=\"1\"/>\n<integrator type=\"explicit\" dt=\"0.1\"/>\n</scene>\n");
  const ProgramResult r = fosssim({"-s", "bad.xml", "-d", "0"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("bad.xml:3: error: <integrator>: attribute \"type\" names an unknown "
                        "integrator \"explicit\" (expected one of explicit-euler, ",
                        0),
            0u)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line";
}

TEST_F(CommandLine, MissingSceneFileIsExitTwo) {
  const ProgramResult r = fosssim({"-s", "nowhere.xml", "-d", "0"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "nowhere.xml: error: cannot open the file: No such file or directory\n");
}

TEST_F(CommandLine, UsageErrorsAreExitTwo) {
  EXPECT_EQ(fosssim({}).status, 2);
  EXPECT_EQ(fosssim({"-s", "spring.xml", "-d", "2"}).status, 2);
  const ProgramResult both = fosssim({"-s", "spring.xml", "-d", "0", "-o", "a.bin", "-i", "b.bin"});
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.err.find("excludes"), std::string::npos) << both.err;
  EXPECT_EQ(fosssim({"-s", "spring.xml", "--no-such-flag"}).status, 2);
}

TEST_F(CommandLine, UnwritableOutputIsAnIoError) {
  const ProgramResult r = fosssim({"-s", "spring.xml", "-d", "0", "-o", "missing/dir/out.bin"});
  EXPECT_EQ(r.status, 4);
  EXPECT_NE(r.err.find("cannot create missing/dir/out.bin: No such file or directory"),
            std::string::npos)
      << r.err;
}

TEST_F(CommandLine, ProgressLinesWhenStandardErrorIsNotATerminal) {
  // The tests' standard error is a pipe: a short run prints no progress by default ...
  const ProgramResult quiet = fosssim({"-s", "spring.xml", "-d", "0", "-o", "a.bin"});
  EXPECT_EQ(quiet.status, 0) << quiet.err;
  EXPECT_EQ(quiet.err.find("FOSSSim: simulating"), std::string::npos) << quiet.err;
  // ... and lines at the interval asked for, ending with the last step (200,000 steps take
  // well over the millisecond asked for).
  const ProgramResult lines =
      fosssim({"-s", "spring.xml", "-d", "0", "--dt", "0.0001", "--duration", "20", "--progress",
               "lines", "--progress-every", "0.001"});
  EXPECT_EQ(lines.status, 0) << lines.err;
  EXPECT_NE(lines.err.find("FOSSSim: simulating: step "), std::string::npos) << lines.err;
  EXPECT_NE(lines.err.find("step 200000 of 200000 (100%)"), std::string::npos) << lines.err;
  const ProgramResult off =
      fosssim({"-s", "spring.xml", "-d", "0", "-i", "a.bin", "--progress", "off"});
  EXPECT_EQ(off.err.find("FOSSSim: grading"), std::string::npos) << off.err;
  for (const char* bad : {"nan", "0", "-1", "1e9", "10s"}) {
    const ProgramResult r = fosssim({"-s", "spring.xml", "-d", "0", "--progress-every", bad});
    EXPECT_EQ(r.status, 2) << bad << ": " << r.err;
  }
  EXPECT_EQ(fosssim({"-s", "spring.xml", "-d", "0", "--progress", "sometimes"}).status, 2);
}

TEST_F(CommandLine, ChecksDerivativesOfAScene) {
  const ProgramResult r = fosssim({"-s", "spring.xml", "--check-derivatives", "-q"});
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("springforce(0, 1)"), std::string::npos);
  EXPECT_NE(r.out.find("all passed"), std::string::npos);
  // Gravity's Hessians vanish: the table says so instead of a relative error of noise over
  // noise (1.000e+00 with the verdict ok).
  EXPECT_NE(r.out.find("ok (zero)"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("1.000e+00"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace fosssim
