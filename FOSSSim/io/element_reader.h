#pragma once
// Typed, validated access to the attributes of one XML element.

#include <string>
#include <string_view>
#include <vector>

#include "core/force_parameters.h"
#include "core/integrators/integrator_options.h"  // OptionSource
#include "core/misspelling.h"  // looks_like_misspelling, for the did-you-mean of attributes
#include "core/scene.h"
#include "io/xml_tree.h"


namespace fosssim {

/// The particles and edges whose elements had an error: an element that refers to one of them
/// is skipped (DependsOnBrokenElement) rather than reported, since its problem is the other's.
struct BrokenElements {
  std::vector<char> particles;  ///< 1 for a particle whose element had an error
  std::vector<char> edges;      ///< 1 for an edge whose element had an error
};

/// Reads attributes of one element and throws SceneError naming the file, line, element and
/// attribute on any problem. It remembers which attributes were asked for, so that the rest can
/// be reported as unknown. It is also the ForceParameters a force factory reads from.
class ElementReader final : public ForceParameters {
 public:
  /// index: the element's 0-based position among elements of its kind, or -1 for singletons.
  ElementReader(const XmlElement& element, const std::string& file, int index,
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
  /// Makes finish() warn about likely misspelt attributes instead of refusing the element, for
  /// formats whose course files may hold them (Theme 3).
  void warn_about_misspellings() { misspellings_are_errors_ = false; }

  /// A warning about this element, located like errors: "file:line: warning: <element> k: text".
  std::string warning(const std::string& text) const;
  /// Ends reading the element: throws SceneError when attributes that no accessor asked for are
  /// within two edits of an asked one (likely misspellings, named with the attribute they
  /// probably mean: "raduis": did you mean "radius"?); otherwise returns the warnings recorded
  /// by warn() and unsupported(), then one for each other attribute that no accessor asked for.
  std::vector<std::string> finish() const;
  /// From now on, particle_index() and edge_index() throw DependsOnBrokenElement for an index
  /// marked in `broken` (which must outlive the reader).
  void skip_broken(const BrokenElements* broken) { broken_ = broken; }
  int line() const;

 private:
  const char* raw(const char* name);  // required, records the name
  std::string location() const;

  const XmlElement& element_;
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
  const BrokenElements* broken_ = nullptr;
  bool course_numbers_ = false;
  bool misspellings_are_errors_ = true;
  /// The number at the start of `text` (course_numbers_ mode), warning about what follows it;
  /// false when there is none.
  template <typename T>
  bool parse_prefix(const char* name, const char* text, T& value);
};

/// A registry entry's options (an integrator's, a contact method's) as attributes of the element
/// `reader` reads: has/number/text/fail by the option's name.
class AttributeOptions : public OptionSource {
 public:
  explicit AttributeOptions(ElementReader& reader) : reader_(reader) {}
  bool has(std::string_view name) override { return reader_.has(std::string(name).c_str()); }
  double number(std::string_view name) override {
    return reader_.number(std::string(name).c_str());
  }
  std::string text(std::string_view name) override {
    return reader_.text(std::string(name).c_str());
  }
  [[noreturn]] void fail(std::string_view name, const std::string& problem) override {
    reader_.fail(std::string(name).c_str(), problem);
  }

 protected:
  ElementReader& reader_;
};

}  // namespace fosssim
