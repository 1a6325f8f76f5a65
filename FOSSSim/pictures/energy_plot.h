#pragma once
// A picture of kinetic, potential and total energy over a run.

#include <array>
#include <cstdint>
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

/// The energies of a run of any length in bounded memory, for the plot: at most kBuckets
/// buckets of consecutive samples, each keeping, per curve (kinetic, potential, total), its
/// lowest value (the earliest of equals) and highest value (the latest) with their times, so that a spike of one step stays visible however
/// long the run. A bucket holds one sample at first; when kBuckets are full, neighbours merge
/// and buckets hold twice as many. A run of up to 2 kBuckets states is therefore kept exactly
/// (a bucket of two samples keeps both as its extremes).
class EnergyHistory {
 public:
  static constexpr int kBuckets = 4096;
  static constexpr int kCurves = 3;  ///< kinetic, potential, total

  void add(const EnergySample& sample);
  std::int64_t count() const { return count_; }
  /// Samples per bucket (1, 2, 4, ...).
  std::int64_t bucket_size() const { return width_; }
  /// The points of curve `c` in time order: each bucket's extremes, its lowest and highest
  /// finite values (one point when they are the same sample), then a NaN point (which breaks
  /// the line) when the bucket held a non-finite sample. At most 3 kBuckets points.
  std::vector<std::array<double, 2>> points(int c) const;

 private:
  struct Extremes {
    double low_time = 0.0, low = 0.0, high_time = 0.0, high = 0.0;
    bool any = false;  // a finite value was seen
  };
  struct Bucket {
    std::array<Extremes, kCurves> curves;
    std::int64_t samples = 0;
    bool broken = false;  // held a non-finite sample
  };
  static void merge(Bucket& into, const Bucket& from);

  std::vector<Bucket> buckets_;
  std::int64_t width_ = 1;
  std::int64_t count_ = 0;
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
/// The same from a bounded history (what --energy-plot keeps of a run).
void write_energy_history_plot(const EnergyHistory& history, const std::string& path,
                               const EnergyPlotStyle& style = {});

}  // namespace fosssim
