#include "outputs/energy_csv_output.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>

#include "core/analysis/energy.h"
#include "core/error.h"
#include "io/output_file.h"
#include "pictures/energy_plot.h"

namespace fosssim {

namespace {

/// One line of energies per state, streamed to the file as the run goes, so that nothing grows
/// with the number of steps.
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

std::unique_ptr<FrameOutput> open_energy_csv(const std::string& path,
                                             const OutputContext& context) {
  return std::make_unique<EnergyCsvOutput>(context.scene, path);
}

}  // namespace

constinit const OutputFormat kEnergyCsvOutput{
    .name = "energy-csv",
    .flags = "--energy-csv",
    .value_name = "FILE",
    .help = "Write time, kinetic, potential and total energy of every state as CSV",
    .group = "Pictures (docs/viewing.md)",
    .target = OutputTarget::kFile,
    .needs = {},
    .open = &open_energy_csv,
};

}  // namespace fosssim
