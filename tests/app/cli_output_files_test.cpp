// Outputs never replace what is not a regular file: `-o /dev/null` must leave /dev/null a device.
// A FIFO stands in for the device here, so that a failure cannot damage the machine. Outputs
// cannot be hijacked or lost (docs/limits-and-failures.md, 'Outputs'): a link planted at the
// old temporary name is not followed; empty names, dangling links, a FIFO nobody reads and two
// outputs naming one file are refused with a message; numbers are decimal as in scene files;
// every catchable terminating signal stops the run as Ctrl-C does, keeping *.incomplete.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "support/run_program.h"
#include "support/scratch_folder.h"
#include "support/tiny_scenes.h"

namespace fosssim {
namespace {

namespace fs = std::filesystem;

class CliOutputFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_.write("scene.xml", testing::kTinyScene);
    ASSERT_EQ(::mkfifo((folder_ / "fifo").c_str(), 0600), 0);
  }
  /// Runs FOSSSim with `arguments` while `cat` copies the FIFO to `copy` (at most 20 s). FOSSSim
  /// starts in about 10 ms and could open the FIFO before a background reader had, so the order
  /// is made certain: the shell holds the FIFO open read-write (which does not block on Linux),
  /// the reader opens it and says so by creating `ready`, FOSSSim runs once `ready` exists, and
  /// the shell's end is closed after FOSSSim's, so that the reader sees the end of the data.
  testing::ProgramResult fosssim_with_reader(const std::string& arguments) {
    return testing::run_command(
        folder_, "exec 3<>fifo; (exec 3<&-; exec 4<fifo; : > ready; exec timeout 20 cat <&4 > copy) "
                 "& reader=$!; n=0; while [ ! -e ready ] && [ $n -lt 2000 ]; do sleep 0.01; "
                 "n=$((n+1)); done; " +
                     testing::quoted(testing::fosssim_program()) + " " + arguments +
                     " 3<&-; status=$?; exec 3<&-; wait $reader; exit $status");
  }
  testing::ProgramResult fosssim(const std::string& arguments) {
    return testing::run_command(
        folder_,
        "timeout -k 5 60 " + testing::quoted(testing::fosssim_program()) + " " + arguments);
  }
  /// The names in the folder, sorted.
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& entry : fs::directory_iterator(folder_.path()))
      out.push_back(entry.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }
  /// Expects the run refused with status 2 and `message` in its error, no file written.
  void expect_refused(const std::string& arguments, const std::string& message) {
    const std::vector<std::string> before = names();
    const auto result = fosssim(arguments);
    EXPECT_EQ(result.status, 2) << arguments << "\n" << result.err;
    EXPECT_NE(result.err.find(message), std::string::npos) << arguments << "\n" << result.err;
    EXPECT_EQ(names(), before) << arguments;
  }
  testing::ScratchFolder folder_;
};

TEST_F(CliOutputFiles, TrajectoryToAFifoIsWrittenInPlace) {
  const auto result = fosssim_with_reader("-s scene.xml -d 0 -o fifo");
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_TRUE(fs::is_fifo(folder_ / "fifo"));
  EXPECT_FALSE(fs::exists(folder_ / "fifo.partial"));
  EXPECT_EQ(fs::file_size(folder_ / "copy"), (testing::kTinySteps + 1u) * 2 * 4 * 8);
}

TEST_F(CliOutputFiles, ResidualFileToAFifoIsWrittenInPlace) {
  ASSERT_EQ(testing::run_command(folder_, testing::quoted(testing::fosssim_program()) +
                                              " -s scene.xml -d 0 -o run.bin")
                .status,
            0);
  const auto result = fosssim_with_reader("-s scene.xml -d 0 -i run.bin --residual-file fifo");
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_TRUE(fs::is_fifo(folder_ / "fifo"));
  EXPECT_EQ(testing::read_file(folder_ / "copy").substr(0, 5), "1   0");
}

TEST_F(CliOutputFiles, EnergyCsvThroughASymbolicLinkReplacesTheTarget) {
  folder_.write("real.csv", "old");
  fs::create_symlink("real.csv", folder_ / "link.csv");
  const auto result = testing::run_command(folder_, testing::quoted(testing::fosssim_program()) +
                                                        " -s scene.xml -d 0 --energy-csv link.csv");
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_TRUE(fs::is_symlink(folder_ / "link.csv"));
  EXPECT_EQ(testing::read_file(folder_ / "real.csv").substr(0, 4), "time");
}

TEST_F(CliOutputFiles, EmptyOutputNamesAreRefused) {
  for (const char* option : {"-o", "--energy-csv", "--energy-plot", "-m", "--movie", "--png-dir"}) {
    expect_refused(std::string("-s scene.xml -d 0 -g 1 ") + option + " ''",
                   ": the name cannot be empty");
  }
}

TEST_F(CliOutputFiles, TwoOutputsNamingOneFileAreRefused) {
  expect_refused("-s scene.xml -d 0 -o x --energy-csv x",
                 "-o x and --energy-csv x name the same file");
  expect_refused("-s scene.xml -d 0 --energy-plot e.png --energy-csv ./e.png",
                 "--energy-plot e.png and --energy-csv ./e.png name the same file");
  expect_refused("-s scene.xml --movie m.mp4 -o m.mp4", "-o m.mp4 and --movie m.mp4 name");
  expect_refused("-s scene.xml -d 0 -o pics -g 1 --png-dir pics",
                 "-o pics and --png-dir pics name the same file");
  folder_.write("real.csv", "old");
  fs::create_symlink("real.csv", folder_ / "link.csv");
  expect_refused("-s scene.xml -d 0 --energy-csv link.csv -o real.csv",
                 "-o real.csv and --energy-csv link.csv name the same file");
  EXPECT_EQ(folder_.read("real.csv"), "old");
}

TEST_F(CliOutputFiles, TwoOutputsToNullDeviceAreFine) {
  const auto result = fosssim("-s scene.xml -d 0 -o /dev/null --energy-csv /dev/null");
  EXPECT_EQ(result.status, 0) << result.err;
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST_F(CliOutputFiles, ADanglingLinkAsOutputIsRefusedAndLeftAlone) {
  fs::create_symlink("missing/out.bin", folder_ / "link.bin");
  expect_refused("-s scene.xml -d 0 -o link.bin",
                 "the output link.bin is a symbolic link to missing/out.bin, which does not "
                 "exist");
  EXPECT_TRUE(fs::is_symlink(folder_ / "link.bin"));
}

TEST_F(CliOutputFiles, AFifoThatNobodyReadsIsAnErrorNotAHang) {
  const auto result = fosssim("-s scene.xml -d 0 -o fifo");
  EXPECT_EQ(result.status, 4) << result.err;
  EXPECT_NE(result.err.find("cannot write fifo: it is a FIFO that no program is reading"),
            std::string::npos)
      << result.err;
  EXPECT_TRUE(fs::is_fifo(folder_ / "fifo"));
}

TEST_F(CliOutputFiles, ALinkPlantedAtTheOldTemporaryNameIsNotFollowed) {
  folder_.write("victim", "precious");
  fs::create_symlink("victim", folder_ / "out.bin.partial");
  fs::create_hard_link(folder_ / "victim", folder_ / "e.csv.partial");
  const auto result = fosssim("-s scene.xml -d 0 -o out.bin --energy-csv e.csv");
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_EQ(folder_.read("victim"), "precious");
  EXPECT_EQ(fs::file_size(folder_ / "out.bin"), (testing::kTinySteps + 1u) * 2 * 4 * 8);
  EXPECT_EQ(folder_.read("e.csv").substr(0, 5), "time,");
  EXPECT_EQ(names(), (std::vector<std::string>{"e.csv", "e.csv.partial", "fifo", "out.bin",
                                               "out.bin.partial", "scene.xml", "victim"}));
}

TEST_F(CliOutputFiles, AFullDeviceIsAnErrorAndNothingIsMadeBesideIt) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const auto result = fosssim("-s scene.xml -d 0 --energy-csv /dev/full");
  EXPECT_EQ(result.status, 4) << result.err;
  EXPECT_NE(result.err.find("cannot write /dev/full: No space left on device"), std::string::npos)
      << result.err;
  EXPECT_FALSE(fs::exists("/dev/full.incomplete"));
}

TEST_F(CliOutputFiles, NumbersOnTheCommandLineAreDecimalAsInSceneFiles) {
  expect_refused("-s scene.xml -d 0 --dt 0x10",
                 "--dt: must be a finite decimal number (like 0.01, -3 or 1e-4), found '0x10'");
  expect_refused("-s scene.xml -d 0 --duration 1_0", "found '1_0'");
  expect_refused("-s scene.xml -d 0 --max-steps 0b11", "0b11");
  expect_refused("-s scene.xml -d 0 --dt inf", "found 'inf'");
  expect_refused("-s scene.xml -d 0 --newton-tolerance 0x1", "found '0x1'");
  const auto fine = fosssim("-s scene.xml -d 0 --dt +1e-2 --duration 0.1");
  EXPECT_EQ(fine.status, 0) << fine.err;
}

// Signals other than SIGINT and SIGTERM used to kill the run and leave its temporary files.
TEST_F(CliOutputFiles, EveryCatchableTerminatingSignalStopsTheRunCleanly) {
  for (const char* signal : {"HUP", "USR1", "USR2", "ALRM", "PIPE", "XFSZ", "VTALRM", "TERM"}) {
    const auto result = testing::run_command(
        folder_, testing::quoted(testing::fosssim_program()) +
                     " -s scene.xml -d 0 -q --duration 1e6 -o out.bin --energy-csv e.csv & "
                     "pid=$!; i=0; while [ $i -lt 600 ] && ! ls | grep -q 'partial$'; do "
                     "sleep 0.05; i=$((i+1)); done; kill -s " +
                     signal + " $pid; wait $pid");
    EXPECT_EQ(result.status, 130) << signal << "\n" << result.err;
    EXPECT_NE(result.err.find("FOSSSim: interrupted by signal"), std::string::npos)
        << signal << "\n"
        << result.err;
    EXPECT_TRUE(fs::exists(folder_ / "out.bin.incomplete")) << signal;
    EXPECT_TRUE(fs::exists(folder_ / "e.csv.incomplete")) << signal;
    EXPECT_EQ(names(), (std::vector<std::string>{"e.csv.incomplete", "fifo", "out.bin.incomplete",
                                                 "scene.xml"}))
        << signal;
    fs::remove(folder_ / "out.bin.incomplete");
    fs::remove(folder_ / "e.csv.incomplete");
  }
}

}  // namespace
}  // namespace fosssim
