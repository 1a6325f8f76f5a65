#include "io/element_reader.h"

#include "io/xml_tree.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <type_traits>
#include <vector>

#include "core/text.h"
#include "io/scene_error.h"
#include "io/text_lines.h"

namespace fosssim {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

/// The attribute's text without surrounding whitespace.
std::string_view trimmed(const char* text) {
  std::string_view s(text);
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

}  // namespace

ElementReader::ElementReader(const XmlElement& element, const std::string& file,
                             int index, int num_particles, int num_edges)
    : element_(element),
      file_(file),
      index_(index),
      num_particles_(num_particles),
      num_edges_(num_edges) {
  asked_.reserve(16);  // one allocation for the names an element is asked for
}

int ElementReader::line() const { return element_.line(); }

std::string ElementReader::location() const {
  std::string where = std::string("<") + element_.name() + ">";
  if (index_ >= 0) where += " " + std::to_string(index_);
  return where;
}

void ElementReader::fail(const std::string& problem) {
  throw SceneError(file_, line(), location(), problem);
}

void ElementReader::fail(const char* name, const std::string& problem) {
  fail(std::string("attribute \"") + name + "\" " + problem);
}

bool ElementReader::has(const char* name) const { return element_.attribute(name) != nullptr; }

bool ElementReader::was_asked(const char* name) const {
  const std::string_view wanted(name);  // compared by length first
  for (const std::string& asked : asked_) {
    if (asked == wanted) return true;
  }
  return false;
}

void ElementReader::remember(const char* name) {
  if (!was_asked(name)) asked_.emplace_back(name);
}

const char* ElementReader::raw(const char* name) {
  remember(name);
  const char* value = element_.attribute(name);
  if (value == nullptr) {
    if (const char* typo = likely_misspelling_of(name)) {
      fail(name, std::string("is missing (the element has \"") + typo +
                     "\", which is not read: a misspelling?)");
    }
    fail(name, "is missing");
  }
  return value;
}

template <typename T>
bool ElementReader::parse_prefix(const char* name, const char* text, T& value) {
  std::string_view s = trimmed(text);
  if (s.size() > 1 && s.front() == '+' && s[1] != '-') s.remove_prefix(1);
  const auto [end, error] = [&] {
    if constexpr (std::is_floating_point_v<T>) {
      return double_from_chars(s.data(), s.data() + s.size(), value);
    } else {
      return std::from_chars(s.data(), s.data() + s.size(), value);
    }
  }();
  if (error != std::errc()) return false;
  if constexpr (std::is_floating_point_v<T>) {
    if (!std::isfinite(value)) return false;
  }
  if (end != s.data() + s.size()) {
    warn(std::string("attribute \"") + name + "\" has text after its number, " + quote(text) +
         ", which is ignored (read as " + std::string(s.data(), end) + ", as the course does)");
  }
  return true;
}

double ElementReader::number(const char* name) {
  const char* text = raw(name);
  double value = 0.0;
  if (course_numbers_) {
    if (!parse_prefix(name, text, value)) fail(name, "must be a number, found " + quote(text));
    return value;
  }
  if (!parse_finite(trimmed(text), value)) {
    fail(name, "must be a finite number, found " + quote(text));
  }
  return value;
}

double ElementReader::number_or(const char* name, double fallback) {
  remember(name);
  return has(name) ? number(name) : fallback;
}

double ElementReader::positive(const char* name) {
  const double value = number(name);
  if (value <= 0.0) fail(name, "must be positive, found " + to_text(value));
  return value;
}

int ElementReader::integer(const char* name) {
  const char* text = raw(name);
  int value = 0;
  if (course_numbers_) {
    if (!parse_prefix(name, text, value)) fail(name, "must be an integer, found " + quote(text));
    return value;
  }
  if (!parse_int(trimmed(text), value)) fail(name, "must be an integer, found " + quote(text));
  return value;
}

bool ElementReader::flag(const char* name) {
  const char* text = raw(name);
  int value = -1;
  const bool read = course_numbers_ ? parse_prefix(name, text, value) : parse_int(trimmed(text), value);
  if (!read || (value != 0 && value != 1)) {
    fail(name, "must be 0 or 1, found " + quote(text));
  }
  return value == 1;
}

int ElementReader::particle_index(const char* name) {
  const int value = integer(name);
  if (value < 0 || value >= num_particles_) {
    fail(name, "refers to particle " + std::to_string(value) + ", but the scene has " +
                   std::to_string(num_particles_) + " particle" + (num_particles_ == 1 ? "" : "s") +
                   " (valid indices are 0 to " + std::to_string(num_particles_ - 1) + ")");
  }
  if (broken_ != nullptr && static_cast<std::size_t>(value) < broken_->particles.size() &&
      broken_->particles[value] != 0) {
    throw DependsOnBrokenElement{};
  }
  return value;
}

int ElementReader::edge_index(const char* name) {
  const int value = integer(name);
  if (value < 0 || value >= num_edges_) {
    fail(name,
         "refers to edge " + std::to_string(value) + ", but the scene has " +
             std::to_string(num_edges_) + " edge" + (num_edges_ == 1 ? "" : "s") +
             (num_edges_ > 0 ? " (valid indices are 0 to " + std::to_string(num_edges_ - 1) + ")"
                             : ""));
  }
  if (broken_ != nullptr && static_cast<std::size_t>(value) < broken_->edges.size() &&
      broken_->edges[value] != 0) {
    throw DependsOnBrokenElement{};
  }
  return value;
}

std::string ElementReader::text(const char* name) { return raw(name); }

std::string ElementReader::text_or_empty(const char* name) {
  remember(name);
  const char* value = element_.attribute(name);
  return value ? value : "";
}

Color ElementReader::color() {
  Color c;
  double* parts[] = {&c.r, &c.g, &c.b};
  const char* names[] = {"r", "g", "b"};
  for (int k = 0; k < 3; ++k) {
    *parts[k] = number(names[k]);
    if (*parts[k] < 0.0 || *parts[k] > 1.0) {
      fail(names[k], "must be between 0 and 1, found " + to_text(*parts[k]));
    }
  }
  return c;
}

std::string ElementReader::warning(const std::string& text) const {
  return file_ + ":" + std::to_string(line()) + ": warning: " + location() + ": " + text;
}

void ElementReader::warn(const std::string& problem) { notes_.push_back(warning(problem)); }

void ElementReader::unsupported(const char* name, const std::string& why) {
  if (!has(name) || was_asked(name)) return;
  remember(name);
  notes_.push_back(
      warning(std::string("attribute \"") + name + "\" is not supported (" + why + "); ignored"));
}

const std::string* ElementReader::likely_meant(std::string_view unknown) const {
  for (const std::string& asked : asked_) {
    if (looks_like_misspelling(unknown, asked)) return &asked;
  }
  return nullptr;
}

const char* ElementReader::likely_misspelling_of(std::string_view name) const {
  for (const XmlAttribute& a : element_.attributes()) {
    // The name ends with a NUL in the document's text.
    if (!was_asked(a.name.data()) && looks_like_misspelling(a.name, name)) return a.name.data();
  }
  return nullptr;
}

std::vector<std::string> ElementReader::finish() const {
  std::vector<std::string> warnings = notes_;
  std::string misspelt;  // "attribute "raduis" (did you mean "radius"?)", one per misspelling
  int count = 0;
  for (const XmlAttribute& a : element_.attributes()) {
    if (was_asked(a.name.data())) continue;
    const std::string* meant = likely_meant(a.name);
    if (meant != nullptr && !misspellings_are_errors_) {
      warnings.push_back(warning(std::string("unknown attribute \"") + std::string(a.name) +
                                 "\" ignored (did you mean \"" + *meant + "\"?)"));
    } else if (meant != nullptr) {
      if (count++ > 0) misspelt += ", ";
      misspelt += "\"" + std::string(a.name) + "\" (did you mean \"" + *meant + "\"?)";
    } else {
      warnings.push_back(
          warning(std::string("unknown attribute \"") + std::string(a.name) + "\" ignored"));
    }
  }
  if (count > 0) {
    throw SceneError(
        file_, line(), location(),
        std::string(count == 1 ? "unknown attribute " : "unknown attributes ") + misspelt);
  }
  return warnings;
}

}  // namespace fosssim
