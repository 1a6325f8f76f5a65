#include "outputs/energy_plot_output.h"

#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>

#include "core/analysis/energy.h"
#include "core/error.h"
#include "io/output_file.h"
#include "pictures/energy_plot.h"

namespace fosssim {

namespace {

/// The energies of every state, kept in bounded memory (EnergyHistory: each bucket's extremes
/// once a run is long), drawn when the run ends.
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

std::unique_ptr<FrameOutput> open_energy_plot(const std::string& path,
                                              const OutputContext& context) {
  return std::make_unique<EnergyPlotOutput>(context.scene, path);
}

}  // namespace

constinit const OutputFormat kEnergyPlotOutput{
    .name = "energy-plot",
    .flags = "--energy-plot",
    .value_name = "FILE",
    .help = "Plot kinetic, potential and total energy over the run into this PNG (or .svg)",
    .group = "Pictures (docs/viewing.md)",
    .target = OutputTarget::kFile,
    .needs = {},
    .open = &open_energy_plot,
};

}  // namespace fosssim
