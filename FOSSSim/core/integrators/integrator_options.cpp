#include "core/integrators/integrator_options.h"

#include <cmath>
#include <stdexcept>

#include "core/text.h"

namespace fosssim {

namespace {

/// A whole number as digits (to_text writes 1000000 as "1e+06").
std::string whole_text(double value) { return std::to_string(static_cast<long long>(value)); }

std::string quoted_list(std::span<const std::string_view> choices) {
  std::string out;
  for (std::size_t k = 0; k < choices.size(); ++k) {
    if (k > 0) out += k + 1 == choices.size() ? " or " : ", ";
    out += "\"" + std::string(choices[k]) + "\"";
  }
  return out;
}

}  // namespace

std::string OptionSpec::describe_values() const {
  if (!values_text.empty()) return std::string(values_text);
  switch (type) {
    case Type::kChoice:
      return quoted_list(choices);
    case Type::kInteger:
      if (std::isinf(highest)) return "a whole number of at least " + whole_text(lowest);
      return "a whole number from " + whole_text(lowest) + " to " + whole_text(highest);
    case Type::kNumber:
      if (std::isinf(lowest)) return "a number";
      if (lowest == 0.0) return lowest_excluded ? "a positive number" : "a non-negative number";
      return std::string("a number ") + (lowest_excluded ? "> " : ">= ") + to_text(lowest);
  }
  return "";
}

std::string OptionSpec::default_text() const {
  if (type == Type::kChoice) return choices.empty() ? "" : std::string(choices.front());
  if (type == Type::kInteger) return whole_text(default_value);
  return to_text(default_value);
}

OptionValues::OptionValues(std::span<const OptionSpec> specs) : specs_(specs) {
  values_.resize(specs.size());
  for (std::size_t k = 0; k < specs.size(); ++k) {
    values_[k].number = specs[k].default_value;
    if (!specs[k].choices.empty()) values_[k].choice = specs[k].choices.front();
  }
}

const OptionSpec* OptionValues::find(std::string_view name) const {
  for (const OptionSpec& spec : specs_) {
    if (spec.name == name) return &spec;
  }
  return nullptr;
}

const OptionSpec& OptionValues::spec(std::string_view name) const {
  const OptionSpec* found = find(name);
  if (found == nullptr) {
    throw std::logic_error("the integrator has no option \"" + std::string(name) + "\"");
  }
  return *found;
}

std::string OptionValues::number_problem(const OptionSpec& spec, double value) {
  const bool whole = spec.type != OptionSpec::Type::kInteger || value == std::floor(value);
  const bool above = spec.lowest_excluded ? value > spec.lowest : value >= spec.lowest;
  if (std::isfinite(value) && whole && above && value <= spec.highest) return "";
  return "must be " + spec.describe_values() + ", found " + to_text(value);
}

void OptionValues::read(OptionSource& source) {
  for (const OptionSpec& spec : specs_) {
    if (!source.has(spec.name)) continue;
    Value& value = values_[index(spec)];
    if (spec.type == OptionSpec::Type::kChoice) {
      const std::string text = source.text(spec.name);
      value.choice = {};
      for (std::string_view choice : spec.choices) {
        if (choice == text) value.choice = choice;
      }
      if (value.choice.empty()) {
        source.fail(spec.name, "must be " + spec.describe_values() + ", found \"" + text + "\"");
      }
    } else {
      value.number = source.number(spec.name);
      if (const std::string problem = number_problem(spec, value.number); !problem.empty()) {
        source.fail(spec.name, problem);
      }
    }
  }
}

double OptionValues::number(std::string_view name) const {
  const OptionSpec& option = spec(name);
  if (option.type == OptionSpec::Type::kChoice) {
    throw std::logic_error("option \"" + std::string(name) + "\" is a choice, not a number");
  }
  return values_[index(option)].number;
}

int OptionValues::integer(std::string_view name) const {
  const OptionSpec& option = spec(name);
  if (option.type != OptionSpec::Type::kInteger) {
    throw std::logic_error("option \"" + std::string(name) + "\" is not a whole number");
  }
  return static_cast<int>(values_[index(option)].number);
}

std::string_view OptionValues::choice(std::string_view name) const {
  const OptionSpec& option = spec(name);
  if (option.type != OptionSpec::Type::kChoice) {
    throw std::logic_error("option \"" + std::string(name) + "\" is not a choice");
  }
  return values_[index(option)].choice;
}

void OptionValues::set(std::string_view name, double value) {
  const OptionSpec& option = spec(name);
  const std::string problem = option.type == OptionSpec::Type::kChoice
                                  ? std::string("is a choice")
                                  : number_problem(option, value);
  if (!problem.empty()) {
    throw std::logic_error("option \"" + std::string(name) + "\" " + problem);
  }
  values_[index(option)].number = value;
}

void OptionValues::set(std::string_view name, std::string_view choice) {
  const OptionSpec& option = spec(name);
  for (std::string_view allowed : option.choices) {
    if (allowed == choice) {
      values_[index(option)].choice = allowed;
      return;
    }
  }
  throw std::logic_error("option \"" + std::string(name) + "\" must be " +
                         option.describe_values() + ", not \"" + std::string(choice) + "\"");
}

}  // namespace fosssim
