#include "pictures/movie_writer.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>

#include "pictures/cairo_painter.h"
#include "support/run_program.h"
#include "support/scratch_folder.h"
#include "support/thrown.h"
#include "support/tiny_scenes.h"

namespace fosssim {
namespace {

/// The number of video frames ffprobe decodes in `path`, or -1.
int count_frames(const testing::ScratchFolder& folder, const std::string& path) {
  const auto result =
      testing::run_command(folder,
                           "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                           "stream=nb_read_frames -of csv=p=0 '" +
                               path + "'");
  if (result.status != 0) return -1;
  return std::atoi(result.out.c_str());
}

/// Sets PATH for the life of the object.
class ScopedPath {
 public:
  explicit ScopedPath(const std::string& value) : saved_(std::getenv("PATH")) {
    ::setenv("PATH", value.c_str(), 1);
  }
  ~ScopedPath() { ::setenv("PATH", saved_.c_str(), 1); }

 private:
  std::string saved_;
};

/// An MP4 box: 32-bit big-endian size, type, then `body`.
std::string box(const std::string& type, const std::string& body) {
  const auto n = static_cast<std::uint32_t>(8 + body.size());
  const std::string size = {static_cast<char>(n >> 24), static_cast<char>(n >> 16),
                            static_cast<char>(n >> 8), static_cast<char>(n)};
  return size + type + body;
}

/// mp4_damage of a file holding `bytes`.
std::string damage_of(const std::string& bytes) {
  const testing::ScratchFolder folder;
  const std::string path = folder.write("m.mp4", bytes);
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  const std::string out = mp4_damage(fd);
  ::close(fd);
  return out;
}

TEST(Mp4Damage, AWholeFileIsFineAndACutOneIsNot) {
  const std::string ftyp = box("ftyp", "isom0200");
  const std::string whole = ftyp + box("moov", std::string(20, 'm')) + box("mdat", "frames");
  EXPECT_EQ(damage_of(whole), "");
  EXPECT_EQ(damage_of(whole.substr(0, whole.size() - 2)), "its 'mdat' box at byte 44 is cut short");
  EXPECT_EQ(damage_of(whole.substr(0, 30)), "its 'moov' box at byte 16 is cut short");
  EXPECT_EQ(damage_of(whole.substr(0, 19)), "it ends inside a box header at byte 16");
  EXPECT_EQ(damage_of(ftyp + box("mdat", "frames")),
            "it has no 'moov' box (the index of its frames)");
  EXPECT_EQ(damage_of(box("mdat", "frames") + ftyp), "it does not begin with an 'ftyp' box");
  EXPECT_EQ(damage_of(""), "it is empty");
}

TEST(MovieWriter, WritesAnMp4WithOneFramePerImage) {
  if (!testing::on_path("ffmpeg") || !testing::on_path("ffprobe")) {
    GTEST_SKIP() << "ffmpeg and ffprobe are not installed (tools/install-deps.sh installs them)";
  }
  const testing::ScratchFolder folder;
  const Scene scene = testing::tiny_scene();
  MovieSettings settings;
  settings.width = 512;
  settings.height = 512;
  settings.fps = 24;
  auto movie = MovieWriter::open(folder / "tiny.mp4", settings);
  const Image frame = render_image(testing::tiny_drawing(scene));
  for (int k = 0; k < 17; ++k) movie.write_frame(frame);
  EXPECT_FALSE(std::filesystem::exists(folder / "tiny.mp4"));  // not before commit
  movie.commit();
  EXPECT_FALSE(std::filesystem::exists(folder / "tiny.mp4.partial"));
  EXPECT_EQ(count_frames(folder, folder / "tiny.mp4"), 17);
  const auto probe = testing::run_command(
      folder,
      "ffprobe -v error -select_streams v:0 -show_entries stream=codec_name,width,height,"
      "r_frame_rate -of csv=p=0 tiny.mp4");
  EXPECT_EQ(probe.out, "h264,512,512,24/1\n");
}

TEST(MovieWriter, AnAbandonedMovieIsKeptAsIncomplete) {
  if (!testing::on_path("ffmpeg") || !testing::on_path("ffprobe")) {
    GTEST_SKIP() << "ffmpeg and ffprobe are not installed (tools/install-deps.sh installs them)";
  }
  const testing::ScratchFolder folder;
  const Scene scene = testing::tiny_scene();
  auto movie = MovieWriter::open(folder / "cut.mp4", MovieSettings{});
  const Image frame = render_image(testing::tiny_drawing(scene));
  for (int k = 0; k < 5; ++k) movie.write_frame(frame);
  EXPECT_EQ(movie.abandon(), folder / "cut.mp4.incomplete");
  EXPECT_FALSE(std::filesystem::exists(folder / "cut.mp4"));
  EXPECT_EQ(count_frames(folder, folder / "cut.mp4.incomplete"), 5);
}

TEST(MovieWriter, SaysSoWhenFfmpegIsMissing) {
  const testing::ScratchFolder folder;
  const ScopedPath empty_path(folder.path().string());
  const Error error = thrown_by([&] { MovieWriter::open(folder / "x.mp4", MovieSettings{}); });
  EXPECT_EQ(error.kind(), ErrorKind::kCannotWrite);
  EXPECT_NE(std::string(error.what()).find("ffmpeg"), std::string::npos);
  EXPECT_NE(std::string(error.what()).find("not on PATH"), std::string::npos);
}

TEST(CheckMovieSettings, RejectsOddSizesOtherFormatsAndBadRates) {
  MovieSettings ok;
  EXPECT_NO_THROW(check_movie_settings("a.mp4", ok));
  EXPECT_NO_THROW(check_movie_settings("A.MP4", ok));
  EXPECT_THROW(check_movie_settings("a.avi", ok), Error);
  EXPECT_THROW(check_movie_settings("a", ok), Error);
  MovieSettings odd = ok;
  odd.width = 511;
  const Error error = thrown_by([&] { check_movie_settings("a.mp4", odd); });
  EXPECT_EQ(error.kind(), ErrorKind::kBadInput);
  EXPECT_NE(std::string(error.what()).find("even"), std::string::npos);
  MovieSettings slow = ok;
  slow.fps = 0.0;
  EXPECT_THROW(check_movie_settings("a.mp4", slow), Error);
}

TEST(FindProgram, FindsExecutablesOnPath) {
  const testing::ScratchFolder folder;
  const std::string tool = folder.write("tool", "#!/bin/sh\n");
  std::filesystem::permissions(tool, std::filesystem::perms::owner_all);
  std::filesystem::create_directory(folder / "dir");
  const ScopedPath path("/nonexistent:" + folder.path().string());
  EXPECT_EQ(find_program("tool"), tool);
  EXPECT_FALSE(find_program("dir").has_value());
  EXPECT_FALSE(find_program("no-such-tool").has_value());
}

}  // namespace
}  // namespace fosssim
