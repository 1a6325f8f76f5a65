#pragma once

#include "outputs/output_format.h"

namespace fosssim {

/// Registry entry "png-sequence" (the course's -g 1, into --png-dir DIR, default pngs): a PNG
/// of every state, DIR/frame_00000.png for the initial state, frame_00001.png after step 1, ...
extern const OutputFormat kPngSequenceOutput;

/// Registry entry "svg-sequence" (the course's -m DIR): an SVG of every state, named as the PNGs.
extern const OutputFormat kSvgSequenceOutput;

}  // namespace fosssim
