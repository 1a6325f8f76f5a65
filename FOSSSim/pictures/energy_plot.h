#pragma once
// A picture of kinetic, potential and total energy over a run.

#include <string>
#include <vector>

namespace fosssim {

/// The energies of one state (see core/analysis/energy.h).
struct EnergySample {
  double time = 0.0;       ///< seconds
  double kinetic = 0.0;    ///< T = ½ Σ m |v|²
  double potential = 0.0;  ///< U of the conservative forces
  double total() const { return kinetic + potential; }
};

struct EnergyPlotStyle {
  int width = 800, height = 500;  ///< pixels
  std::string title;              ///< drawn above the plot, e.g. the scene and integrator
};

/// Plots kinetic, potential and total energy against time (a LinePlot, pictures/line_plot.h),
/// with axes, ticks, labels and a legend, as a PNG, or an SVG when `path` ends in ".svg". Written
/// under a temporary name and renamed. Non-finite samples are left out. Throws Error (kCannotWrite)
/// on an I/O error.
void write_energy_plot(const std::vector<EnergySample>& samples, const std::string& path,
                       const EnergyPlotStyle& style = {});

}  // namespace fosssim
