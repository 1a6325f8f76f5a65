#pragma once
// The settings of an integrator, declared once and read the same way from every source.

#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fosssim {

/// One setting of an integrator, as scene files and the command line name it: an attribute of
/// <integrator>, a key of a JSON scene, or `--integrator-option NAME=VALUE`. The declaration
/// says what values are allowed and the default, so that every source validates alike and the
/// documentation (--help, docs/integrators.md) lists the same thing.
struct OptionSpec {
  enum class Type {
    kNumber,   ///< a finite real number in [lowest, highest] (lowest excluded if asked)
    kInteger,  ///< a whole number in [lowest, highest]
    kChoice,   ///< one of `choices`, compared exactly; the first is the default
  };

  std::string_view name;
  Type type = Type::kNumber;
  std::string_view help;  ///< one line: what it does, with its unit
  double default_value = 0.0;
  double lowest = -std::numeric_limits<double>::infinity();
  bool lowest_excluded = false;
  double highest = std::numeric_limits<double>::infinity();
  std::span<const std::string_view> choices;
  /// How messages and help describe the accepted values, when the generic description
  /// (describe_values) does not say enough: "\"none\" (the course's) or \"exact\"".
  std::string_view values_text;

  /// A real number ≥ lowest (> lowest when `excluded`).
  static constexpr OptionSpec number(std::string_view name, double default_value, double lowest,
                                     bool excluded, std::string_view help) {
    OptionSpec spec;
    spec.name = name;
    spec.type = Type::kNumber;
    spec.help = help;
    spec.default_value = default_value;
    spec.lowest = lowest;
    spec.lowest_excluded = excluded;
    return spec;
  }
  /// A whole number in [lowest, highest].
  static constexpr OptionSpec integer(std::string_view name, int default_value, int lowest,
                                      int highest, std::string_view help) {
    OptionSpec spec;
    spec.name = name;
    spec.type = Type::kInteger;
    spec.help = help;
    spec.default_value = default_value;
    spec.lowest = lowest;
    spec.highest = highest;
    return spec;
  }
  /// One of `choices` (which must outlive the spec); the first is the default.
  static constexpr OptionSpec choice(std::string_view name,
                                     std::span<const std::string_view> choices,
                                     std::string_view help) {
    OptionSpec spec;
    spec.name = name;
    spec.type = Type::kChoice;
    spec.help = help;
    spec.choices = choices;
    return spec;
  }

  /// What the option accepts, for messages and help: "a whole number from 1 to 1000000",
  /// "\"elimination\" or \"penalty\"" (values_text when it is set).
  std::string describe_values() const;
  /// The default as text ("10", "1e-09", "elimination").
  std::string default_text() const;
};

/// Where option values are written: implemented by the scene readers (XML attributes, JSON
/// keys) and the command line, which know how to locate a problem in their own terms.
class OptionSource {
 public:
  virtual ~OptionSource() = default;
  /// True when the source gives a value for `name`.
  virtual bool has(std::string_view name) = 0;
  /// The value of `name` as a finite number; fails (fail()) when it is not one.
  virtual double number(std::string_view name) = 0;
  /// The value of `name` as text.
  virtual std::string text(std::string_view name) = 0;
  /// Reports a problem with the value of `name` (throws; never returns).
  [[noreturn]] virtual void fail(std::string_view name, const std::string& problem) = 0;
};

/// The values of every option of one integrator, defaults included.
class OptionValues {
 public:
  OptionValues() = default;
  /// Every option at its default.
  explicit OptionValues(std::span<const OptionSpec> specs);

  /// Replaces the values of the options `source` has, validated against their specs; options
  /// the source lacks keep their value. Throws through source.fail on the first bad value.
  void read(OptionSource& source);

  /// The value of a kNumber or kInteger option.
  double number(std::string_view name) const;
  /// The value of a kInteger option.
  int integer(std::string_view name) const;
  /// The value of a kChoice option.
  std::string_view choice(std::string_view name) const;
  /// Sets an option from code (a format that fixes it, such as the JSON scenes' penalty pins).
  /// The value must be valid for the option: an invalid one is a programming error
  /// (std::logic_error).
  void set(std::string_view name, double value);
  void set(std::string_view name, std::string_view choice);

  std::span<const OptionSpec> specs() const { return specs_; }
  /// True when the integrator has an option of this name.
  bool has(std::string_view name) const { return find(name) != nullptr; }

 private:
  struct Value {
    double number = 0.0;
    std::string_view choice;  // points into the spec's choices
  };
  const OptionSpec* find(std::string_view name) const;
  const OptionSpec& spec(std::string_view name) const;  // throws std::logic_error if unknown
  std::size_t index(const OptionSpec& spec) const { return &spec - specs_.data(); }
  /// Why `value` is not allowed for `spec`, or empty.
  static std::string number_problem(const OptionSpec& spec, double value);

  std::span<const OptionSpec> specs_;
  std::vector<Value> values_;
};

}  // namespace fosssim
