// Tests of outputs written whole or not at all (io/output_file.h), streamed without being held
// in memory.
//
// Checked: stream_output_file writes what its body streams under the final name only at the
// end; a body that throws leaves neither a .partial file nor a changed earlier file, and its
// exception goes on; a device that cannot take the bytes (/dev/full) is an Error of kind
// kCannotWrite naming it. OutputFile creates its temporary file exclusively under a name no
// one can plant in advance (a symbolic or hard link at the old fixed name "<name>.partial" is
// left alone), with the usual permissions; refuses empty names, folders, dangling links and a
// FIFO nobody reads (at once, without blocking); replaces the file a link names; keeps
// nothing beside a device.

#include "io/output_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "core/error.h"
#include "support/thrown.h"

namespace fosssim {
namespace {

namespace fs = std::filesystem;

class StreamOutputFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("fosssim_output_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string read(const std::string& name) const {
    std::ifstream in(path(name), std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
  }
  /// How many "*.partial" files the folder holds.
  int partial_files() const {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(dir_))
      count += entry.path().filename().string().ends_with(".partial") ? 1 : 0;
    return count;
  }
  fs::path dir_;
};

TEST_F(StreamOutputFile, AppearsWholeUnderItsNameOnlyAtTheEnd) {
  stream_output_file(path("t.tsv"), [&](std::FILE* file) {
    EXPECT_FALSE(fs::exists(path("t.tsv")));
    EXPECT_EQ(partial_files(), 1);
    for (int k = 0; k < 100000; ++k) std::fputs("0123456789\n", file);
  });
  EXPECT_EQ(fs::file_size(path("t.tsv")), 1100000u);
  EXPECT_EQ(partial_files(), 0);
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

TEST_F(StreamOutputFile, TemporaryNamesAreNewEachTimeInTheTargetsFolderAndExclusive) {
  OutputFile first(path("t.bin"));
  OutputFile second(path("t.bin"));
  EXPECT_NE(first.write_path(), second.write_path());
  for (const OutputFile* output : {&first, &second}) {
    EXPECT_EQ(fs::path(output->write_path()).parent_path(), dir_);
    EXPECT_TRUE(output->write_path().starts_with(path("t.bin.")));
    EXPECT_TRUE(output->write_path().ends_with(".partial"));
    EXPECT_FALSE(output->in_place());
    EXPECT_GE(output->descriptor(), 0);
  }
  second.discard();
  EXPECT_EQ(partial_files(), 1);
  first.commit();
  EXPECT_EQ(partial_files(), 0);
  EXPECT_TRUE(fs::is_regular_file(path("t.bin")));
}

TEST_F(StreamOutputFile, ASymbolicLinkPlantedAtTheOldTemporaryNameIsNeverFollowed) {
  write_output_file(path("victim"), "precious\n");
  fs::create_symlink(path("victim"), path("t.bin.partial"));
  write_output_file(path("t.bin"), "new\n");
  EXPECT_EQ(read("victim"), "precious\n");
  EXPECT_TRUE(fs::is_symlink(path("t.bin.partial")));
  EXPECT_EQ(read("t.bin"), "new\n");
}

TEST_F(StreamOutputFile, AHardLinkPlantedAtTheOldTemporaryNameIsNeverWritten) {
  write_output_file(path("victim"), "precious\n");
  fs::create_hard_link(path("victim"), path("t.bin.partial"));
  write_output_file(path("t.bin"), "new\n");
  EXPECT_EQ(read("victim"), "precious\n");
  EXPECT_EQ(fs::hard_link_count(path("victim")), 2u);
  EXPECT_EQ(read("t.bin"), "new\n");
}

TEST_F(StreamOutputFile, NewFilesGetThePermissionsTheUmaskAllows) {
  const mode_t mask = ::umask(022);
  write_output_file(path("t.bin"), "x");
  ::umask(mask);
  struct stat status {};
  ASSERT_EQ(::stat(path("t.bin").c_str(), &status), 0);
  EXPECT_EQ(status.st_mode & 0777, 0644u);
}

TEST_F(StreamOutputFile, AnEmptyNameIsRefused) {
  const Error error = thrown_by([] { OutputFile output(""); });
  EXPECT_EQ(error.kind(), ErrorKind::kBadInput);
  EXPECT_STREQ(error.what(), "an output file name cannot be empty");
}

TEST_F(StreamOutputFile, AFolderIsRefused) {
  fs::create_directories(path("sub"));
  const Error error = thrown_by([&] { write_output_file(path("sub"), "x"); });
  EXPECT_EQ(error.kind(), ErrorKind::kBadInput);
  EXPECT_EQ(std::string(error.what()), "the output " + path("sub") + " is a folder");
  EXPECT_EQ(partial_files(), 0);
}

TEST_F(StreamOutputFile, ADanglingSymbolicLinkIsRefusedAndLeftAsItIs) {
  fs::create_symlink(path("nowhere/t.bin"), path("link"));
  const Error error = thrown_by([&] { write_output_file(path("link"), "x"); });
  EXPECT_EQ(error.kind(), ErrorKind::kBadInput);
  EXPECT_NE(std::string(error.what())
                .find("is a symbolic link to " + path("nowhere/t.bin") + ", which does not exist"),
            std::string::npos)
      << error.what();
  EXPECT_TRUE(fs::is_symlink(path("link")));
  EXPECT_EQ(partial_files(), 0);
}

TEST_F(StreamOutputFile, ASymbolicLinkToAFileReplacesThatFileAndStays) {
  fs::create_directories(path("real"));
  write_output_file(path("real/t.bin"), "old");
  fs::create_symlink("real/t.bin", path("link"));
  write_output_file(path("link"), "new");
  EXPECT_TRUE(fs::is_symlink(path("link")));
  EXPECT_EQ(read("real/t.bin"), "new");
}

TEST_F(StreamOutputFile, AFifoThatNobodyReadsIsRefusedAtOnce) {
  ASSERT_EQ(::mkfifo(path("fifo").c_str(), 0600), 0);
  const Error error = thrown_by([&] { OutputFile output(path("fifo")); });
  EXPECT_EQ(error.kind(), ErrorKind::kCannotWrite);
  EXPECT_EQ(std::string(error.what()),
            "cannot write " + path("fifo") + ": it is a FIFO that no program is reading");
  EXPECT_TRUE(fs::is_fifo(path("fifo")));
}

TEST_F(StreamOutputFile, ADeviceIsWrittenInPlaceAndNothingIsKeptBesideIt) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  OutputFile output("/dev/full");
  EXPECT_TRUE(output.in_place());
  EXPECT_EQ(output.keep_unfinished(), "/dev/full");
  EXPECT_FALSE(fs::exists("/dev/full.incomplete"));
  EXPECT_TRUE(output_is_in_place("/dev/full"));
  EXPECT_FALSE(output_is_in_place(path("t.bin")));
}

TEST_F(StreamOutputFile, KeepUnfinishedRenamesTheTemporaryFile) {
  OutputFile output(path("t.bin"));
  ASSERT_TRUE(write_all(output.descriptor(), "half", 4));
  EXPECT_EQ(output.keep_unfinished(), path("t.bin.incomplete"));
  EXPECT_EQ(read("t.bin.incomplete"), "half");
  EXPECT_FALSE(fs::exists(path("t.bin")));
  EXPECT_EQ(partial_files(), 0);
}

TEST_F(StreamOutputFile, AnOutputDroppedUnfinishedLeavesNothing) {
  {
    OutputFile output(path("t.bin"));
    ASSERT_TRUE(write_all(output.descriptor(), "half", 4));
  }
  EXPECT_TRUE(fs::is_empty(dir_));
}

}  // namespace
}  // namespace fosssim
