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

/// Plots kinetic, potential and total energy against time, with axes, ticks, labels and a
/// legend, as a PNG, or an SVG when `path` ends in ".svg". Written under a temporary name and
/// renamed. Non-finite samples are left out. Throws std::runtime_error on an I/O error.
void write_energy_plot(const std::vector<EnergySample>& samples, const std::string& path,
                       const EnergyPlotStyle& style = {});

/// Tick positions for an axis from `low` to `high`: multiples of 1, 2 or 5 × 10^k chosen so that
/// there are about `target` of them inside [low, high].
std::vector<double> nice_ticks(double low, double high, int target = 6);

}  // namespace fosssim
