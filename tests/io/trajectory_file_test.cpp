// The course's trajectory file (docs/command-line.md): byte layout, round trip, and the guarantee
// that an unfinished run never leaves a file that looks complete.

#include "io/trajectory_file.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "support/scratch_folder.h"
#include "support/thrown.h"

namespace fosssim {
namespace {

namespace fs = std::filesystem;

class TrajectoryFile : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return folder_ / name; }

  static State state(double base) {
    State s;
    s.q = (Vector(4) << base, base + 1, base + 2, base + 3).finished();
    s.v = (Vector(4) << -base, 0.5, 1e-300, -0.0).finished();
    return s;
  }

  testing::ScratchFolder folder_;
};

TEST_F(TrajectoryFile, FrameIsPositionsThenVelocitiesAsLittleEndianDoubles) {
  auto writer = TrajectoryWriter::open(path("t.bin"));
  State s;
  s.q = (Vector(2) << 1.0, 2.0).finished();
  s.v = (Vector(2) << -1.0, 0.5).finished();
  writer.write_frame(s);
  writer.commit();
  const std::string bytes = testing::read_file(path("t.bin"));
  const unsigned char expected[] = {
      0, 0, 0, 0, 0, 0, 0xf0, 0x3f,  // 1.0
      0, 0, 0, 0, 0, 0, 0x00, 0x40,  // 2.0
      0, 0, 0, 0, 0, 0, 0xf0, 0xbf,  // -1.0
      0, 0, 0, 0, 0, 0, 0xe0, 0x3f,  // 0.5
  };
  ASSERT_EQ(bytes.size(), sizeof(expected));
  EXPECT_EQ(std::memcmp(bytes.data(), expected, sizeof(expected)), 0);
}

TEST_F(TrajectoryFile, RoundTripsEveryBit) {
  auto writer = TrajectoryWriter::open(path("t.bin"));
  for (int k = 0; k < 5; ++k) writer.write_frame(state(0.1 * k));
  writer.commit();
  auto reader = TrajectoryReader::open(path("t.bin"), 4);
  EXPECT_EQ(reader.num_frames(), 5);
  Vector q, v;
  for (int k : {3, 0, 4}) {
    reader.read_frame(k, q, v);
    const State expected = state(0.1 * k);
    EXPECT_EQ(std::memcmp(q.data(), expected.q.data(), 4 * sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(v.data(), expected.v.data(), 4 * sizeof(double)), 0);
  }
}

TEST_F(TrajectoryFile, FinalNameAppearsOnlyOnCommit) {
  auto writer = TrajectoryWriter::open(path("t.bin"));
  writer.write_frame(state(1));
  EXPECT_FALSE(fs::exists(path("t.bin")));
  EXPECT_TRUE(fs::exists(path("t.bin.partial")));
  writer.commit();
  EXPECT_TRUE(fs::exists(path("t.bin")));
  EXPECT_FALSE(fs::exists(path("t.bin.partial")));
}

TEST_F(TrajectoryFile, UnfinishedRunKeepsFramesAsIncompleteAndLeavesEarlierFileAlone) {
  std::ofstream(path("t.bin")) << "an earlier complete run";
  {
    auto writer = TrajectoryWriter::open(path("t.bin"));
    writer.write_frame(state(1));
    writer.write_frame(state(2));
  }  // destroyed without commit, as when a run fails
  EXPECT_EQ(testing::read_file(path("t.bin")), "an earlier complete run");
  EXPECT_FALSE(fs::exists(path("t.bin.partial")));
  EXPECT_EQ(fs::file_size(path("t.bin.incomplete")), 2u * 8 * sizeof(double));
}

TEST_F(TrajectoryFile, AbandonReportsWhereTheFramesAre) {
  auto writer = TrajectoryWriter::open(path("t.bin"));
  writer.write_frame(state(1));
  EXPECT_EQ(writer.abandon(), path("t.bin.incomplete"));
  EXPECT_TRUE(fs::exists(path("t.bin.incomplete")));
}

TEST_F(TrajectoryFile, OpenFailsWithTheReasonWhenTheFolderIsMissing) {
  const Error error = thrown_by([&] { TrajectoryWriter::open(path("no/such/dir/t.bin")); });
  EXPECT_EQ(error.kind(), ErrorKind::kCannotWrite);
  EXPECT_STREQ(error.what(), ("cannot create " + path("no/such/dir/t.bin.partial") +
                              ": No such file or directory")
                                 .c_str());
}

TEST_F(TrajectoryFile, ReaderRejectsCutShortFiles) {
  std::ofstream(path("short.bin"), std::ios::binary) << std::string(8 * 8 + 5, '\0');
  const Error error = thrown_by([&] { TrajectoryReader::open(path("short.bin"), 4); });
  EXPECT_EQ(error.kind(), ErrorKind::kBadInput);
  EXPECT_EQ(std::string(error.what()),
            path("short.bin") +
                " has 69 bytes, not a whole number of frames of 64 bytes (4 "
                "positions and velocities); it was cut short or is for another scene");
}

TEST_F(TrajectoryFile, ReaderRejectsMissingFile) {
  const Error error = thrown_by([&] { TrajectoryReader::open(path("missing.bin"), 4); });
  EXPECT_NE(std::string(error.what()).find("missing.bin"), std::string::npos);
}

}  // namespace
}  // namespace fosssim
