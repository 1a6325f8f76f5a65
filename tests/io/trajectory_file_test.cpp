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
  /// How many temporary "*.partial" files the folder holds.
  int partial_files() const {
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder_.path()))
      count += entry.path().filename().string().ends_with(".partial") ? 1 : 0;
    return count;
  }

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
  EXPECT_EQ(partial_files(), 1);
  writer.commit();
  EXPECT_TRUE(fs::exists(path("t.bin")));
  EXPECT_EQ(partial_files(), 0);
}

TEST_F(TrajectoryFile, UnfinishedRunKeepsFramesAsIncompleteAndLeavesEarlierFileAlone) {
  std::ofstream(path("t.bin")) << "an earlier complete run";
  {
    auto writer = TrajectoryWriter::open(path("t.bin"));
    writer.write_frame(state(1));
    writer.write_frame(state(2));
  }  // destroyed without commit, as when a run fails
  EXPECT_EQ(testing::read_file(path("t.bin")), "an earlier complete run");
  EXPECT_EQ(partial_files(), 0);
  EXPECT_EQ(fs::file_size(path("t.bin.incomplete")), 2u * 8 * sizeof(double));
}

TEST_F(TrajectoryFile, AbandonReportsWhereTheFramesAre) {
  auto writer = TrajectoryWriter::open(path("t.bin"));
  writer.write_frame(state(1));
  EXPECT_EQ(writer.abandon(), path("t.bin.incomplete"));
  EXPECT_TRUE(fs::exists(path("t.bin.incomplete")));
}

TEST_F(TrajectoryFile, AWriterAbandonedBeforeItsFirstFrameLeavesNothing) {
  {
    auto writer = TrajectoryWriter::open(path("t.bin"));
    EXPECT_EQ(writer.abandon(), "");
  }
  { auto writer = TrajectoryWriter::open(path("u.bin")); }
  EXPECT_TRUE(fs::is_empty(folder_.path()));
}

TEST_F(TrajectoryFile, OpenFailsWithTheReasonWhenTheFolderIsMissing) {
  const Error error = thrown_by([&] { TrajectoryWriter::open(path("no/such/dir/t.bin")); });
  EXPECT_EQ(error.kind(), ErrorKind::kCannotWrite);
  EXPECT_STREQ(
      error.what(),
      ("cannot create " + path("no/such/dir/t.bin") + ": No such file or directory").c_str());
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

TEST_F(TrajectoryFile, CollisionRecordsAndPolynomialsRoundTripInTheCoursesLayout) {
  const CollisionRecord hit{CollisionKind::kParticleEdge, 1, 0, Eigen::Vector2d(0.25, -0.5), 0.75};
  const std::vector<Polynomial> polys = {Polynomial::as_written({1.0, -2.0, 0.5}),
                                         Polynomial::as_written({})};
  {
    TrajectoryWriter writer = TrajectoryWriter::open(path("c.bin"));
    const State s0 = state(0), s1 = state(1), s2 = state(2);
    const auto layout = TrajectoryLayout::kCollisionsAndPolynomials;
    writer.write_record(layout, s0.q, s0.v, {}, {});
    writer.write_record(layout, s1.q, s1.v, {hit}, {polys[0]});  // sync record of step 1
    writer.write_record(layout, s2.q, s2.v, {hit}, polys);       // end of step 1
    writer.commit();
  }
  // 3 frames of 64 bytes; counts; one 36-byte collision per step record; polynomials.
  EXPECT_EQ(fs::file_size(path("c.bin")), 3 * 64 + 3 * 8 + 2 * 36 + (4 + 24) + (4 + 24 + 4));
  const std::string bytes = testing::read_file(path("c.bin"));
  std::int32_t type = -1;
  std::memcpy(&type, bytes.data() + 64 + 8 + 64 + 4, 4);  // first record after record 0
  EXPECT_EQ(type, 1);
  TrajectoryReader reader =
      TrajectoryReader::open(path("c.bin"), 4, 2, TrajectoryLayout::kCollisionsAndPolynomials);
  EXPECT_EQ(reader.num_frames(), 2);
  TrajectoryRecord end, sync;
  reader.read_record(1, end);
  reader.read_sync_record(1, sync);
  EXPECT_EQ(end.q, state(2).q);
  EXPECT_EQ(sync.q, state(1).q);
  ASSERT_EQ(end.collisions.size(), 1u);
  EXPECT_TRUE(end.collisions[0].same_pair(hit));
  EXPECT_EQ(end.collisions[0].normal, hit.normal);
  EXPECT_EQ(end.collisions[0].time, 0.75);
  EXPECT_EQ(end.polynomials, polys);
  EXPECT_EQ(sync.polynomials.size(), 1u);
  Vector q, v;
  reader.read_frame(1, q, v);
  EXPECT_EQ(q, state(2).q);
}

// The reader keeps no table of record offsets (its memory must not grow with the file): it
// walks from the last record it found, and from the start when asked for an earlier one. Any
// order of reads gives the records written, whether the file is on disk or in memory.
TEST_F(TrajectoryFile, RecordsWithCollisionsReadAlikeInAnyOrder) {
  const auto layout = TrajectoryLayout::kCollisionsAndPolynomials;
  constexpr int kSteps = 6;
  {
    TrajectoryWriter writer = TrajectoryWriter::open(path("c.bin"));
    for (int r = 0; r <= 2 * kSteps; ++r) {
      const State s = state(r);
      std::vector<CollisionRecord> hits(
          static_cast<std::size_t>(r % 3),
          {CollisionKind::kParticleParticle, r, 0, Eigen::Vector2d(1, 0), 0.5});
      std::vector<Polynomial> polys(static_cast<std::size_t>(r % 2),
                                    Polynomial::as_written({1.0 * r, 2.0}));
      writer.write_record(layout, s.q, s.v, hits, polys);
    }
    writer.commit();
  }
  TrajectoryReader file = TrajectoryReader::open(path("c.bin"), 4, 2, layout);
  TrajectoryReader memory =
      TrajectoryReader::from_bytes(testing::read_file(path("c.bin")), 4, "c.bin", 2, layout);
  ASSERT_EQ(file.num_frames(), kSteps + 1);
  ASSERT_EQ(memory.num_frames(), kSteps + 1);
  const auto check = [&](TrajectoryReader& reader, std::int64_t k) {
    TrajectoryRecord end;
    reader.read_record(k, end);
    EXPECT_EQ(end.q, state(2.0 * k).q) << k;
    EXPECT_EQ(end.collisions.size(), static_cast<std::size_t>(2 * k % 3)) << k;
    EXPECT_EQ(end.polynomials.size(), 0u) << k;
    if (k == 0) return;
    TrajectoryRecord sync;
    reader.read_sync_record(k, sync);
    EXPECT_EQ(sync.q, state(2.0 * k - 1).q) << k;
    EXPECT_EQ(sync.collisions.size(), static_cast<std::size_t>((2 * k - 1) % 3)) << k;
    ASSERT_EQ(sync.polynomials.size(), 1u) << k;
    EXPECT_EQ(sync.polynomials[0].coefficients()[0], 2.0 * k - 1) << k;
  };
  for (TrajectoryReader* reader : {&file, &memory}) {
    for (std::int64_t k = 0; k <= kSteps; ++k) check(*reader, k);
    for (std::int64_t k = kSteps; k >= 0; --k) check(*reader, k);
    for (std::int64_t k : {3, 0, 6, 1, 5}) check(*reader, k);
    Vector q, v;
    EXPECT_THROW(reader->read_frame(kSteps + 1, q, v), Error);
    EXPECT_THROW(reader->read_frame(-1, q, v), Error);
  }
}

TEST_F(TrajectoryFile, SphereRecordsAre3DOnlyAndUnknownTypesAreNamed) {
  // A particle-sphere record (type 3) reads back in 3D; in 2D, type 3 is no collision type.
  const CollisionRecord hit{CollisionKind::kParticleSphere, 1, 0, Eigen::Vector3d(0, -1, 0.5), 0.0};
  const Vector q = Vector::LinSpaced(6, 0.0, 5.0), v = Vector::Zero(6);
  {
    TrajectoryWriter writer = TrajectoryWriter::open(path("s.bin"));
    writer.write_record(TrajectoryLayout::kCollisions, q, v, {}, {});
    writer.write_record(TrajectoryLayout::kCollisions, q, v, {hit}, {});
    writer.commit();
  }
  TrajectoryReader reader =
      TrajectoryReader::open(path("s.bin"), 6, 3, TrajectoryLayout::kCollisions);
  TrajectoryRecord record;
  reader.read_record(1, record);
  ASSERT_EQ(record.collisions.size(), 1u);
  EXPECT_TRUE(record.collisions[0].same_pair(hit));
  EXPECT_EQ(record.collisions[0].normal, hit.normal);
  const Error error = thrown_by(
      [&] { TrajectoryReader::open(path("s.bin"), 6, 2, TrajectoryLayout::kCollisions); });
  EXPECT_NE(
      std::string(error.what()).find("has a collision of unknown type 3 (expected 0, 1 or 2)"),
      std::string::npos)
      << error.what();
}

TEST_F(TrajectoryFile, AFileCutInsideACollisionRecordIsNamed) {
  {
    TrajectoryWriter writer = TrajectoryWriter::open(path("c.bin"));
    const State s = state(0);
    const CollisionRecord hit{CollisionKind::kParticleParticle, 0, 1, Eigen::Vector2d(1, 0), 0.0};
    writer.write_record(TrajectoryLayout::kCollisions, s.q, s.v, {}, {});
    writer.write_record(TrajectoryLayout::kCollisions, s.q, s.v, {hit}, {});
    writer.commit();
  }
  fs::resize_file(path("c.bin"), fs::file_size(path("c.bin")) - 10);
  const Error error = thrown_by(
      [&] { TrajectoryReader::open(path("c.bin"), 4, 2, TrajectoryLayout::kCollisions); });
  EXPECT_EQ(error.kind(), ErrorKind::kBadInput);
  EXPECT_NE(
      std::string(error.what()).find("record 1 claims 1 collisions, more than the file holds"),
      std::string::npos)
      << error.what();
}

}  // namespace
}  // namespace fosssim
