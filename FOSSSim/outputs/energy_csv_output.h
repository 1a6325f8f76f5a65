#pragma once

#include "outputs/output_format.h"

namespace fosssim {

/// Registry entry "energy-csv" (--energy-csv FILE): "time,kinetic,potential,total", then one
/// line per state (each value with 17 significant digits), streamed as the run goes.
extern const OutputFormat kEnergyCsvOutput;

}  // namespace fosssim
