#include "outputs/movie_output.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

namespace fosssim {

namespace {

class MovieOutput final : public FrameOutput {
 public:
  MovieOutput(MovieWriter writer, int stride) : writer_(std::move(writer)), stride_(stride) {}
  void write(Frame& frame) override {
    if (frame.state().step % stride_ == 0) {
      writer_.write_frame(frame.image());
      ++frames_;
    }
  }
  void commit() override { writer_.commit(); }
  std::string describe() const override {
    return "the movie " + writer_.path() + " (" + std::to_string(frames_) + " frames)";
  }
  std::string abandon() override {
    const std::string kept = writer_.abandon();
    return kept.empty() ? "" : "the movie so far is in " + kept;
  }

 private:
  MovieWriter writer_;
  int stride_;
  std::int64_t frames_ = 0;
};

void check_movie(const std::string& path, const OutputSettings& settings) {
  check_movie_settings(path, settings.movie);
}

std::unique_ptr<FrameOutput> open_movie(const std::string& path, const OutputContext& context) {
  return std::make_unique<MovieOutput>(
      MovieWriter::open(path, context.settings.movie),
      movie_stride(context.settings, context.scene.model.integrator.dt));
}

}  // namespace

int movie_stride(const OutputSettings& settings, double dt) {
  if (settings.movie_stride) return *settings.movie_stride;
  const double steps_per_frame = 1.0 / (settings.movie.fps * dt);
  return std::isfinite(steps_per_frame)
             ? std::max(1, static_cast<int>(std::lround(steps_per_frame)))
             : 1;
}

constinit const OutputFormat kMovieOutput{
    .name = "movie",
    .flags = "--movie",
    .value_name = "FILE",
    .help = "Render the run headless into this MP4 movie (H.264) with the ffmpeg program;\n"
            "needs no display. Implies -d 0",
    .group = "Pictures (docs/viewing.md)",
    .target = OutputTarget::kFile,
    .headless_reason = "renders headless; leave out -d 1 (the window cannot record movies)",
    .needs = {.pictures = true, .window = false},
    .check = &check_movie,
    .open = &open_movie,
};

}  // namespace fosssim
