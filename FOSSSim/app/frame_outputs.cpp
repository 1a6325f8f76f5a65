#include "app/frame_outputs.h"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>
#include <utility>

#include "core/analysis/energy.h"
#include "core/error.h"
#include "io/output_file.h"
#include "io/rigid_trajectory.h"
#include "io/trajectory_file.h"
#include "io/trajectory_steps.h"
#include "pictures/cairo_painter.h"
#include "pictures/energy_plot.h"
#include "pictures/movie_writer.h"

namespace fosssim {

const Drawing& Frame::drawing() {
  if (!drawing_) drawing_ = view_.compose(state_);
  return *drawing_;
}

const Image& Frame::image() {
  if (!image_) image_ = render_image(drawing());
  return *image_;
}

namespace {

/// What an abandoned trajectory output kept: `kept` is where its frames are now (the writer's
/// abandon(): empty when nothing was written, `path` itself for a device or FIFO).
std::string trajectory_kept_note(const std::string& kept, const std::string& path,
                                 std::int64_t frames) {
  if (kept.empty()) return path + " was not written";
  if (kept == path) return "";  // a device or FIFO: the frames went there
  return "the " + std::to_string(frames) + " frames computed so far are in " + kept + " (" + path +
         " was not written)";
}

/// -o: the trajectory file (docs/command-line.md, 'Trajectory files'), in the layout of the
/// scene's collision method (docs/collisions.md): continuous-time and hybrid steps write their
/// sync record, then their end-of-step record.
class TrajectoryOutput final : public FrameOutput {
 public:
  TrajectoryOutput(TrajectoryWriter writer, TrajectoryLayout layout)
      : writer_(std::move(writer)), layout_(layout) {}
  void write(Frame& frame) override {
    write_trajectory_state(writer_, layout_, frame.state(), frame.record());
    ++frames_;
  }
  void commit() override { writer_.commit(); }
  std::string describe() const override {
    return "the trajectory " + writer_.path() + " (" + std::to_string(frames_) + " frames)";
  }
  std::string abandon() override {
    return trajectory_kept_note(writer_.abandon(), writer_.path(), frames_);
  }

 private:
  TrajectoryWriter writer_;
  TrajectoryLayout layout_;
  std::int64_t frames_ = 0;
};

/// -o for a rigid-body scene: the course's Theme 3 layout (io/rigid_trajectory.h).
class RigidTrajectoryOutput final : public FrameOutput {
 public:
  RigidTrajectoryOutput(TrajectoryWriter writer, const SceneModel& model)
      : writer_(std::move(writer), model) {}
  void write(Frame& frame) override {
    writer_.write(frame.state());
    ++frames_;
  }
  void commit() override { writer_.commit(); }
  std::string describe() const override {
    return "the trajectory " + writer_.path() + " (" + std::to_string(frames_) + " frames)";
  }
  std::string abandon() override {
    return trajectory_kept_note(writer_.abandon(), writer_.path(), frames_);
  }

 private:
  RigidTrajectoryWriter writer_;
  std::int64_t frames_ = 0;
};

/// -g 1 and -m DIR: one picture per state, DIR/frame_00000.png and so on. Each file is written
/// whole (temporary name, then rename), so a stopped run leaves complete pictures only.
class PictureSequenceOutput final : public FrameOutput {
 public:
  PictureSequenceOutput(std::string directory, PictureFormat format)
      : directory_(std::move(directory)), format_(format) {}
  void write(Frame& frame) override {
    char name[64];
    std::snprintf(name, sizeof name, "/frame_%05lld.%s", static_cast<long long>(frame.state().step),
                  format_ == PictureFormat::kSvg ? "svg" : "png");
    if (format_ == PictureFormat::kSvg) {
      write_svg(frame.drawing(), directory_ + name);
    } else {
      write_png(frame.image(), directory_ + name);
    }
    ++pictures_;
  }
  void commit() override {}
  std::string describe() const override {
    return std::to_string(pictures_) + (format_ == PictureFormat::kSvg ? " SVG" : " PNG") +
           " pictures in " + directory_ + "/";
  }
  std::string abandon() override { return ""; }

 private:
  std::string directory_;
  PictureFormat format_;
  std::int64_t pictures_ = 0;
};

/// --movie: every stride-th state as a movie frame.
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

/// --energy-csv: one line of energies per state, streamed to the file as the run goes, so that
/// nothing grows with the number of steps.
class EnergyCsvOutput final : public FrameOutput {
 public:
  EnergyCsvOutput(const Scene& scene, const std::string& path)
      : scene_(scene), output_(path), file_(output_.take_stream()) {
    std::fputs("time,kinetic,potential,total\n", file_);
  }
  ~EnergyCsvOutput() override { close(); }
  void write(Frame& frame) override {
    const EnergyReport e = compute_energies(scene_.model, frame.state());
    const EnergySample s{frame.state().time, e.kinetic, e.potential};
    if (std::fprintf(file_, "%.17g,%.17g,%.17g,%.17g\n", s.time, s.kinetic, s.potential,
                     s.total()) < 0) {
      fail(errno);
    }
  }
  void commit() override {
    std::FILE* file = std::exchange(file_, nullptr);
    errno = 0;
    const bool flushed = std::fflush(file) == 0 && !std::ferror(file) &&
                         (output_.in_place() || ::fsync(::fileno(file)) == 0);
    const int error = errno != 0 ? errno : EIO;
    if (std::fclose(file) != 0 || !flushed) fail(flushed ? errno : error);
    output_.commit();
  }
  std::string describe() const override { return "the energies " + output_.path(); }
  std::string abandon() override {
    close();
    const std::string kept = output_.keep_unfinished();
    return kept.empty() || output_.in_place() ? "" : "the energies so far are in " + kept;
  }

 private:
  void close() {
    if (file_ != nullptr) std::fclose(std::exchange(file_, nullptr));
  }
  [[noreturn]] void fail(int error) {
    close();
    output_.discard();
    throw Error(ErrorKind::kCannotWrite,
                "cannot write " + output_.path() + ": " + std::strerror(error));
  }

  const Scene& scene_;
  OutputFile output_;
  std::FILE* file_;
};

/// --energy-plot: the energies of every state, kept in bounded memory (EnergyHistory: each
/// bucket's extremes once a run is long), drawn when the run ends.
class EnergyPlotOutput final : public FrameOutput {
 public:
  EnergyPlotOutput(const Scene& scene, std::string plot) : scene_(scene), plot_(std::move(plot)) {}
  void write(Frame& frame) override {
    const EnergyReport e = compute_energies(scene_.model, frame.state());
    history_.add({frame.state().time, e.kinetic, e.potential});
  }
  void commit() override {
    committing_ = true;
    write_plot(plot_);
  }
  std::string describe() const override { return "the energy plot " + plot_; }
  std::string abandon() override {
    // Nothing beside a device or FIFO, and nothing more after a plot that failed to be written.
    if (committing_ || output_is_in_place(plot_)) return "";
    try {
      write_plot(plot_ + ".incomplete");
    } catch (const Error&) {
      return "";
    }
    return "the energies so far are in " + plot_ + ".incomplete";
  }

 private:
  void write_plot(const std::string& path) {
    EnergyPlotStyle style;
    style.title = std::filesystem::path(scene_.source).filename().string() + "  -  " +
                  std::string(scene_.model.integrator.method->name) +
                  ", dt = " + format_dt(scene_.model.integrator.dt);
    write_energy_history_plot(history_, path, style);
  }
  static std::string format_dt(double dt) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", dt);
    return buffer;
  }

  const Scene& scene_;
  std::string plot_;
  EnergyHistory history_;
  bool committing_ = false;
};

void make_directory(const std::string& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) {
    throw Error(ErrorKind::kCannotWrite,
                "cannot create the folder " + directory + ": " + error.message());
  }
}

}  // namespace

int movie_stride(const Options& options, double dt) {
  if (options.movie_stride) return *options.movie_stride;
  const double steps_per_frame = 1.0 / (options.fps * dt);
  return std::isfinite(steps_per_frame)
             ? std::max(1, static_cast<int>(std::lround(steps_per_frame)))
             : 1;
}

FrameOutputs FrameOutputs::open(const Scene& scene, const Options& options) {
  FrameOutputs outputs;
  if (!options.output.empty() && scene.model.rigid_bodies) {
    outputs.outputs_.push_back(std::make_unique<RigidTrajectoryOutput>(
        TrajectoryWriter::open(options.output), scene.model));
  } else if (!options.output.empty()) {
    outputs.outputs_.push_back(std::make_unique<TrajectoryOutput>(
        TrajectoryWriter::open(options.output), trajectory_layout(scene.model)));
  }
  auto add_sequence = [&](const std::string& directory, PictureFormat format) {
    make_directory(directory);
    outputs.outputs_.push_back(std::make_unique<PictureSequenceOutput>(directory, format));
  };
  if (options.png == 1) add_sequence(options.png_directory, PictureFormat::kPng);
  if (!options.svg_directory.empty()) add_sequence(options.svg_directory, PictureFormat::kSvg);
  if (!options.movie.empty()) {
    outputs.outputs_.push_back(
        std::make_unique<MovieOutput>(MovieWriter::open(options.movie, movie_settings(options)),
                                      movie_stride(options, scene.model.integrator.dt)));
  }
  if (!options.energy_plot.empty()) {
    outputs.outputs_.push_back(std::make_unique<EnergyPlotOutput>(scene, options.energy_plot));
  }
  if (!options.energy_csv.empty()) {
    outputs.outputs_.push_back(std::make_unique<EnergyCsvOutput>(scene, options.energy_csv));
  }
  return outputs;
}

void FrameOutputs::write(const State& state, const SceneView& view, const StepRecord* record) {
  Frame frame(state, view, record);
  for (auto& output : outputs_) output->write(frame);
}

void FrameOutputs::commit() {
  for (auto& output : outputs_) output->commit();
}

std::string FrameOutputs::describe() const {
  std::string out;
  for (std::size_t k = 0; k < outputs_.size(); ++k) {
    if (k > 0) out += k + 1 == outputs_.size() ? " and " : ", ";
    out += outputs_[k]->describe();
  }
  return out;
}

std::string FrameOutputs::abandon() {
  std::string notes;
  for (auto& output : outputs_) {
    const std::string note = output->abandon();
    if (note.empty()) continue;
    notes += (notes.empty() ? "" : "; ") + note;
  }
  return notes;
}

ElementColors element_colors(const Options& options) {
  ElementColors colors;
  colors.by = options.color_by == "strain"   ? ElementColoring::kStrain
              : options.color_by == "energy" ? ElementColoring::kEnergy
                                             : ElementColoring::kPlain;
  colors.scale = options.color_scale;
  return colors;
}

}  // namespace fosssim
