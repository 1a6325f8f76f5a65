#pragma once

#include "outputs/output_format.h"

namespace fosssim {

/// Registry entry "movie" (--movie FILE.mp4): every stride-th state as a frame of an H.264 movie
/// made by the ffmpeg program (pictures/movie_writer.h); the stride is movie_stride().
extern const OutputFormat kMovieOutput;

/// The movie stride --movie-stride gives, or the one that plays the run at about real time:
/// max(1, round(1 / (fps · dt))).
int movie_stride(const OutputSettings& settings, double dt);

}  // namespace fosssim
