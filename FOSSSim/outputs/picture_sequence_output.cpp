#include "outputs/picture_sequence_output.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>
#include <utility>

#include "core/error.h"
#include "pictures/cairo_painter.h"

namespace fosssim {

namespace {

enum class PictureFormat { kPng, kSvg };

/// One picture per state, DIR/frame_00000.png and so on. Each file is written whole (temporary
/// name, then rename), so a stopped run leaves complete pictures only.
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

void make_directory(const std::string& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) {
    throw Error(ErrorKind::kCannotWrite,
                "cannot create the folder " + directory + ": " + error.message());
  }
}

std::unique_ptr<FrameOutput> open_png_sequence(const std::string& directory,
                                               const OutputContext&) {
  make_directory(directory);
  return std::make_unique<PictureSequenceOutput>(directory, PictureFormat::kPng);
}

std::unique_ptr<FrameOutput> open_svg_sequence(const std::string& directory,
                                               const OutputContext&) {
  make_directory(directory);
  return std::make_unique<PictureSequenceOutput>(directory, PictureFormat::kSvg);
}

constexpr const char* kGroup = "Pictures (docs/viewing.md)";

}  // namespace

constinit const OutputFormat kPngSequenceOutput{
    .name = "png-sequence",
    .flags = "--png-dir",
    .value_name = "DIR",
    .help = "The PNG folder of -g 1",
    .group = kGroup,
    .target = OutputTarget::kFolder,
    .picture_extension = "png",
    .switch_flags = "-g,--png",
    .switch_help = "1: write a PNG of every state into the PNG folder (frame_00000.png is the\n"
                   "initial state, frame_00001.png the state after step 1, ...)",
    .default_destination = "pngs",
    .needs = {.pictures = true},
    .open = &open_png_sequence,
};

constinit const OutputFormat kSvgSequenceOutput{
    .name = "svg-sequence",
    .flags = "-m,--svg",
    .value_name = "DIR",
    .help = "Write an SVG of every state into this folder (frame_00000.svg, ...)",
    .group = kGroup,
    .target = OutputTarget::kFolder,
    .picture_extension = "svg",
    .needs = {.pictures = true},
    .open = &open_svg_sequence,
};

}  // namespace fosssim
