#include "app/frame_outputs.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "core/analysis/energy.h"
#include "io/output_file.h"
#include "io/trajectory_file.h"
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

/// -o: the trajectory file (docs/command-line.md, 'Trajectory files'), in the layout of the
/// scene's collision method (docs/collisions.md): continuous-time and hybrid steps write their
/// sync record, then their end-of-step record.
class TrajectoryOutput final : public FrameOutput {
 public:
  TrajectoryOutput(TrajectoryWriter writer, TrajectoryLayout layout)
      : writer_(std::move(writer)), layout_(layout) {}
  void write(Frame& frame) override {
    const State& state = frame.state();
    const StepRecord* record = frame.record();
    if (record == nullptr) {
      writer_.write_record(layout_, state.q, state.v, {}, {});
    } else {
      if (layout_ == TrajectoryLayout::kCollisionsAndPolynomials) {
        const SyncPoint sync =
            record->sync.value_or(SyncPoint{state.q, state.v, record->polynomials.size()});
        const std::vector<Polynomial> logged(
            record->polynomials.begin(),
            record->polynomials.begin() + static_cast<std::ptrdiff_t>(sync.polynomials_logged));
        writer_.write_record(layout_, sync.q, sync.v, record->collisions, logged);
      }
      writer_.write_record(layout_, state.q, state.v, record->collisions, record->polynomials);
    }
    ++frames_;
  }
  void commit() override { writer_.commit(); }
  std::string abandon() override {
    return "the " + std::to_string(frames_) + " frames computed so far are in " +
           writer_.abandon() + " (" + writer_.path() + " was not written)";
  }

 private:
  TrajectoryWriter writer_;
  TrajectoryLayout layout_;
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
  }
  void commit() override {}
  std::string abandon() override { return ""; }

 private:
  std::string directory_;
  PictureFormat format_;
};

/// --movie: every stride-th state as a movie frame.
class MovieOutput final : public FrameOutput {
 public:
  MovieOutput(MovieWriter writer, int stride) : writer_(std::move(writer)), stride_(stride) {}
  void write(Frame& frame) override {
    if (frame.state().step % stride_ == 0) writer_.write_frame(frame.image());
  }
  void commit() override { writer_.commit(); }
  std::string abandon() override {
    const std::string kept = writer_.abandon();
    return kept.empty() ? "" : "the movie so far is in " + kept;
  }

 private:
  MovieWriter writer_;
  int stride_;
};

/// --energy-plot and --energy-csv: the energies of every state, written when the run ends.
class EnergyOutput final : public FrameOutput {
 public:
  EnergyOutput(const Scene& scene, std::string plot, std::string csv)
      : scene_(scene), plot_(std::move(plot)), csv_(std::move(csv)) {}
  void write(Frame& frame) override {
    const EnergyReport e = compute_energies(scene_.model, frame.state());
    samples_.push_back({frame.state().time, e.kinetic, e.potential});
  }
  void commit() override { write_files(""); }
  std::string abandon() override {
    try {
      write_files(".incomplete");
    } catch (const std::runtime_error&) {
      return "";
    }
    return "the energies so far are in " + join_names(".incomplete");
  }

 private:
  void write_files(const std::string& suffix) {
    if (!plot_.empty()) {
      EnergyPlotStyle style;
      style.title = std::filesystem::path(scene_.source).filename().string() + "  -  " +
                    std::string(scene_.model.integrator.method->name) +
                    ", dt = " + format_dt(scene_.model.integrator.dt);
      write_energy_plot(samples_, plot_ + suffix, style);
    }
    if (!csv_.empty()) write_csv(csv_ + suffix);
  }
  std::string join_names(const std::string& suffix) const {
    if (plot_.empty()) return csv_ + suffix;
    return csv_.empty() ? plot_ + suffix : plot_ + suffix + " and " + csv_ + suffix;
  }
  static std::string format_dt(double dt) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", dt);
    return buffer;
  }
  void write_csv(const std::string& path) const {
    const auto problem = write_output_file(path, [this](std::ostream& out) {
      out << "time,kinetic,potential,total\n";
      char line[128];
      for (const EnergySample& s : samples_) {
        std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%.17g\n", s.time, s.kinetic,
                      s.potential, s.total());
        out << line;
      }
    });
    if (problem) throw std::runtime_error(*problem);
  }

  const Scene& scene_;
  std::string plot_, csv_;
  std::vector<EnergySample> samples_;
};

std::optional<std::string> make_directory(const std::string& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) return "cannot create the folder " + directory + ": " + error.message();
  return std::nullopt;
}

}  // namespace

int movie_stride(const Options& options, double dt) {
  if (options.movie_stride) return *options.movie_stride;
  const double steps_per_frame = 1.0 / (options.fps * dt);
  return std::isfinite(steps_per_frame)
             ? std::max(1, static_cast<int>(std::lround(steps_per_frame)))
             : 1;
}

Expected<FrameOutputs, std::string> FrameOutputs::open(const Scene& scene, const Options& options) {
  FrameOutputs outputs;
  if (!options.output.empty()) {
    auto writer = TrajectoryWriter::open(options.output);
    if (!writer) return writer.error();
    outputs.outputs_.push_back(std::make_unique<TrajectoryOutput>(std::move(writer).value(),
                                                                  trajectory_layout(scene.model)));
  }
  auto add_sequence = [&](const std::string& directory,
                          PictureFormat format) -> std::optional<std::string> {
    if (auto problem = make_directory(directory)) return problem;
    outputs.outputs_.push_back(std::make_unique<PictureSequenceOutput>(directory, format));
    return std::nullopt;
  };
  if (options.png == 1) {
    if (auto problem = add_sequence(options.png_directory, PictureFormat::kPng)) return *problem;
  }
  if (!options.svg_directory.empty()) {
    if (auto problem = add_sequence(options.svg_directory, PictureFormat::kSvg)) return *problem;
  }
  if (!options.movie.empty()) {
    auto writer = MovieWriter::open(options.movie, movie_settings(options));
    if (!writer) return writer.error();
    outputs.outputs_.push_back(std::make_unique<MovieOutput>(
        std::move(writer).value(), movie_stride(options, scene.model.integrator.dt)));
  }
  if (!options.energy_plot.empty() || !options.energy_csv.empty()) {
    outputs.outputs_.push_back(
        std::make_unique<EnergyOutput>(scene, options.energy_plot, options.energy_csv));
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

std::string FrameOutputs::abandon() {
  std::string notes;
  for (auto& output : outputs_) {
    const std::string note = output->abandon();
    if (note.empty()) continue;
    notes += (notes.empty() ? "" : "; ") + note;
  }
  return notes;
}

}  // namespace fosssim
