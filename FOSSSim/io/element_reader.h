#pragma once
// Typed, validated access to the attributes of one XML element.

#include <string>
#include <vector>

#include "core/force_parameters.h"
#include "core/scene.h"

namespace tinyxml2 {
class XMLElement;
}

namespace fosssim {

/// Reads attributes of one element and throws SceneError naming the file, line, element and
/// attribute on any problem. It remembers which attributes were asked for, so that the rest can
/// be reported as unknown. It is also the ForceParameters a force factory reads from.
class ElementReader final : public ForceParameters {
 public:
  /// index: the element's 0-based position among elements of its kind, or -1 for singletons.
  ElementReader(const tinyxml2::XMLElement& element, const std::string& file, int index,
                int num_particles, int num_edges);

  double number(const char* name) override;
  double number_or(const char* name, double fallback) override;
  int particle_index(const char* name) override;
  int edge_index(const char* name) override;
  [[noreturn]] void fail(const std::string& problem) override;
  [[noreturn]] void fail(const char* name, const std::string& problem) override;
  void warn(const std::string& problem) override;
  void unsupported(const char* name, const std::string& why) override;

  /// A required number > 0.
  double positive(const char* name);
  /// A required integer.
  int integer(const char* name);
  /// A required 0 or 1.
  bool flag(const char* name);
  /// A required string.
  std::string text(const char* name);
  /// An optional string, empty when absent.
  std::string text_or_empty(const char* name);
  /// Required "r", "g", "b" components in [0, 1].
  Color color();
  /// True when the element has this attribute.
  bool has(const char* name) const;

  /// Reads numbers as the course's Theme 3 program does (stream extraction): leading blanks
  /// skipped and anything after the longest number ignored, with a warning (x="-1abc" is −1,
  /// an integer "6.7" is 6). Text with no number at its start is still an error.
  void read_numbers_as_course() { course_numbers_ = true; }

  /// A warning about this element, located like errors: "file:line: warning: <element> k: text".
  std::string warning(const std::string& text) const;
  /// The warnings recorded by warn() and unsupported(), then one for each attribute that no
  /// accessor asked for; an unknown attribute within two edits of an asked one is named as its
  /// likely misspelling ("alhpa": did you mean "alpha"?).
  std::vector<std::string> unknown_attribute_warnings() const;
  int line() const;

 private:
  const char* raw(const char* name);  // required, records the name
  std::string location() const;

  const tinyxml2::XMLElement& element_;
  const std::string& file_;
  int index_;
  int num_particles_;
  int num_edges_;
  bool was_asked(const char* name) const;
  void remember(const char* name);

  /// The asked-for attribute that `unknown` most likely misspells, or nullptr.
  const std::string* likely_meant(std::string_view unknown) const;
  /// An attribute of the element that is likely a misspelling of `name`, or nullptr.
  const char* likely_misspelling_of(std::string_view name) const;

  std::vector<std::string> asked_;  // a handful: a list is faster than a set
  std::vector<std::string> notes_;  // warnings recorded by warn() and unsupported()
  bool course_numbers_ = false;
  /// The number at the start of `text` (course_numbers_ mode), warning about what follows it;
  /// false when there is none.
  template <typename T>
  bool parse_prefix(const char* name, const char* text, T& value);
};

}  // namespace fosssim
