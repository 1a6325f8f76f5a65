#include "outputs/output_registry.h"

#include <array>
#include <stdexcept>

#include "outputs/energy_csv_output.h"
#include "outputs/energy_plot_output.h"
#include "outputs/movie_output.h"
#include "outputs/picture_sequence_output.h"
#include "outputs/stats_json_output.h"
#include "outputs/trajectory_output.h"

namespace fosssim {

namespace {
/// The course's outputs first (-o, -g, -m), then FOSSSim's own.
const std::array kFormats = {
    &kTrajectoryOutput, &kPngSequenceOutput,  &kSvgSequenceOutput,
    &kMovieOutput,      &kEnergyPlotOutput,   &kEnergyCsvOutput,
    &kStatsJsonOutput,
};
}  // namespace

std::span<const OutputFormat* const> output_formats() { return kFormats; }

const OutputFormat* find_output_format(std::string_view name) {
  for (const OutputFormat* format : kFormats) {
    if (format->name == name) return format;
  }
  return nullptr;
}

OutputChoices::OutputChoices() : choices_(kFormats.size()) {
  for (std::size_t k = 0; k < kFormats.size(); ++k) {
    choices_[k].destination = std::string(kFormats[k]->default_destination);
  }
}

std::size_t OutputChoices::index(const OutputFormat& format) {
  for (std::size_t k = 0; k < kFormats.size(); ++k) {
    if (kFormats[k] == &format) return k;
  }
  throw std::logic_error("the output format \"" + std::string(format.name) +
                         "\" is not in the registry");
}

bool OutputChoices::requested(const OutputFormat& format) const {
  const Choice& choice = choices_[index(format)];
  return format.switch_flags.empty() ? !choice.destination.empty() : choice.switched == 1;
}

std::vector<OutputRequest> OutputChoices::requests() const {
  std::vector<OutputRequest> out;
  for (const OutputFormat* format : kFormats) {
    if (requested(*format)) out.push_back({format, destination(*format)});
  }
  return out;
}

}  // namespace fosssim
