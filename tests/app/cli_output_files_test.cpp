// Outputs never replace what is not a regular file: `-o /dev/null` must leave /dev/null a device.
// A FIFO stands in for the device here, so that a failure cannot damage the machine.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>

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
  /// Runs FOSSSim with `arguments` while `timeout 20 cat fifo > copy` reads the FIFO.
  testing::ProgramResult fosssim_with_reader(const std::string& arguments) {
    return testing::run_command(folder_, "timeout 20 cat fifo > copy & reader=$!; " +
                                             testing::quoted(testing::fosssim_program()) + " " +
                                             arguments + "; status=$?; wait $reader; exit $status");
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

}  // namespace
}  // namespace fosssim
