#pragma once
// Every output format a run can write, and what a command line asks of them: adding a format
// is its file pair and a line in the .cpp (docs/architecture.md, 'Where a change goes').

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "outputs/output_format.h"

namespace fosssim {

/// All formats, in the order --help, the checks and the run's report list them.
std::span<const OutputFormat* const> output_formats();

/// The format with this name, or nullptr.
const OutputFormat* find_output_format(std::string_view name);

/// One output a command line asks for, and where.
struct OutputRequest {
  const OutputFormat* format;
  std::string destination;
};

/// What a command line says of every format: its destination (empty when not named; the
/// default of a switched format) and, for a switched format (-g), the switch's value.
class OutputChoices {
 public:
  OutputChoices();
  /// The destination of `format`, for the option parser to fill in.
  std::string& destination(const OutputFormat& format) { return choices_[index(format)].destination; }
  const std::string& destination(const OutputFormat& format) const {
    return choices_[index(format)].destination;
  }
  /// The value of `format`'s switch (0 or 1); 0 for formats without one.
  int& switched(const OutputFormat& format) { return choices_[index(format)].switched; }
  /// True when the command line asks for `format`: its switch is 1, or (without a switch) its
  /// destination was given.
  bool requested(const OutputFormat& format) const;
  /// The outputs asked for, in registry order.
  std::vector<OutputRequest> requests() const;

 private:
  struct Choice {
    std::string destination;
    int switched = 0;
  };
  static std::size_t index(const OutputFormat& format);
  std::vector<Choice> choices_;
};

}  // namespace fosssim
