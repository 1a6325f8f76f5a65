#pragma once

#include "outputs/output_format.h"

namespace fosssim {

/// Registry entry "energy-plot" (--energy-plot FILE.png|FILE.svg): kinetic, potential and total
/// energy over the run, kept in bounded memory and drawn when the run ends.
extern const OutputFormat kEnergyPlotOutput;

}  // namespace fosssim
