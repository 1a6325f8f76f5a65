#include "outputs/stats_json_output.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>

#include "core/error.h"
#include "io/output_file.h"
#include "outputs/run_summary.h"

namespace fosssim {

namespace {

/// Totals the run as it goes (nothing grows with the number of steps) and writes the summary
/// at the end; the file is opened at once, so that an unwritable name fails before the run.
class StatsJsonOutput final : public FrameOutput {
 public:
  StatsJsonOutput(const Scene& scene, const std::string& path) : summary_(scene), output_(path) {}
  void write(Frame& frame) override {
    summary_.add(frame.state(), frame.record(), frame.integrator());
  }
  void commit() override {
    const std::string text = summary_.json();
    std::FILE* file = output_.take_stream();
    errno = 0;
    const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size() &&
                         std::fflush(file) == 0 && !std::ferror(file) &&
                         (output_.in_place() || ::fsync(::fileno(file)) == 0);
    const int error = errno != 0 ? errno : EIO;
    if (std::fclose(file) != 0 || !written) {
      output_.discard();
      throw Error(ErrorKind::kCannotWrite, "cannot write " + output_.path() + ": " +
                                               std::strerror(written ? errno : error));
    }
    output_.commit();
  }
  std::string describe() const override {
    return "the run summary " + output_.path() + " (" + std::to_string(summary_.steps()) +
           " steps)";
  }
  std::string abandon() override {
    output_.discard();  // a summary of part of a run is not written at all
    return "";
  }

 private:
  RunSummary summary_;
  OutputFile output_;
};

std::unique_ptr<FrameOutput> open_stats_json(const std::string& path,
                                             const OutputContext& context) {
  return std::make_unique<StatsJsonOutput>(context.scene, path);
}

}  // namespace

constinit const OutputFormat kStatsJsonOutput{
    .name = "stats-json",
    .flags = "--stats-json",
    .value_name = "FILE",
    .help = "Write a summary of the run as JSON: steps, solver statistics, collisions per step,\n"
            "energy drift and timings (schema in docs/command-line.md). Written only when the\n"
            "run completes",
    .group = "Run summaries (docs/command-line.md)",
    .target = OutputTarget::kFile,
    .needs = {},
    .open = &open_stats_json,
};

}  // namespace fosssim
