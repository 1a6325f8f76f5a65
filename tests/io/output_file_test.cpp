// Tests of outputs written whole or not at all (io/output_file.h), streamed without being held
// in memory.
//
// Checked: stream_output_file writes what its body streams under the final name only at the
// end; a body that throws leaves neither a .partial file nor a changed earlier file, and its
// exception goes on; a device that cannot take the bytes (/dev/full) is an Error of kind
// kCannotWrite naming it.

#include "io/output_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "core/error.h"
#include "support/thrown.h"

namespace fosssim {
namespace {

namespace fs = std::filesystem;

class StreamOutputFile : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("fosssim_output_" +
            std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string read(const std::string& name) const {
    std::ifstream in(path(name), std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
  }
  fs::path dir_;
};

TEST_F(StreamOutputFile, AppearsWholeUnderItsNameOnlyAtTheEnd) {
  stream_output_file(path("t.tsv"), [&](std::FILE* file) {
    EXPECT_FALSE(fs::exists(path("t.tsv")));
    EXPECT_TRUE(fs::exists(path("t.tsv.partial")));
    for (int k = 0; k < 100000; ++k) std::fputs("0123456789\n", file);
  });
  EXPECT_EQ(fs::file_size(path("t.tsv")), 1100000u);
  EXPECT_FALSE(fs::exists(path("t.tsv.partial")));
}

TEST_F(StreamOutputFile, ABodyThatThrowsLeavesTheEarlierFileAndNoPartial) {
  write_output_file(path("t.tsv"), "earlier\n");
  EXPECT_THROW(stream_output_file(path("t.tsv"),
                                  [](std::FILE* file) {
                                    std::fputs("half", file);
                                    throw std::runtime_error("stopped");
                                  }),
               std::runtime_error);
  EXPECT_EQ(read("t.tsv"), "earlier\n");
  EXPECT_FALSE(fs::exists(path("t.tsv.partial")));
}

TEST_F(StreamOutputFile, AFullDeviceIsACannotWriteError) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const Error error = thrown_by([] {
    stream_output_file("/dev/full", [](std::FILE* file) {
      for (int k = 0; k < 10000; ++k) std::fputs("0123456789\n", file);
    });
  });
  EXPECT_EQ(error.kind(), ErrorKind::kCannotWrite);
  EXPECT_STREQ(error.what(), "cannot write /dev/full: No space left on device");
}

}  // namespace
}  // namespace fosssim
