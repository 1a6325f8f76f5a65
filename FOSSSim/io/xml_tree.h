#pragma once
// A read-only tree of the elements of an XML file: what the scene readers see of it. One parser
// (rapidxml, header-only) builds it in every build, native and WebAssembly alike, so that a
// scene reads the same, with the same messages, wherever it is loaded (docs/architecture.md,
// "XML").

#include <cstdint>
#include <functional>
#include <memory>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fosssim {

/// One attribute, as written (entities such as &amp; translated). Both point into the text
/// kept by the XmlDocument the attribute belongs to, and both end with a NUL there.
struct XmlAttribute {
  std::string_view name;
  const char* value = nullptr;
};

/// One element: its name, the line of its '<', its attributes in document order (no name
/// twice: a repeated attribute is a syntax error) and its child elements. Text, comments,
/// processing instructions and the DOCTYPE are not kept. An element lives in its XmlDocument
/// and is valid as long as that document.
class XmlElement {
 public:
  const std::string& name() const { return *name_; }
  /// 1-based line of the element's opening '<'.
  int line() const { return line_; }
  /// The value of the attribute `name`, or nullptr when the element has none.
  const char* attribute(std::string_view name) const;
  std::span<const XmlAttribute> attributes() const { return {attributes_, attribute_count_}; }
  /// The child elements in document order.
  std::span<const XmlElement> children() const { return {children_, child_count_}; }
  /// The child elements called `name`, in document order.
  std::vector<const XmlElement*> children_named(std::string_view name) const;

 private:
  friend class XmlTreeBuilder;
  friend class XmlDirectReader;
  const std::string* name_ = nullptr;  ///< interned in the document: a scene has few names
  const XmlAttribute* attributes_ = nullptr;
  const XmlElement* children_ = nullptr;
  std::uint32_t attribute_count_ = 0;
  std::uint32_t child_count_ = 0;
  int line_ = 0;
};

/// A parsed XML text: its top-level elements in document order (a well-formed file has one),
/// used like a vector of them. It owns everything its elements point to: the text, parsed in
/// place (names and values are read where they are written), one array of all elements (the
/// children of an element are adjacent), one array of all attributes and the distinct names.
/// Each array is allocated once, at a size counted before. Moving a document keeps its elements
/// valid.
class XmlDocument {
 public:
  bool empty() const { return top_count_ == 0; }
  std::size_t size() const { return top_count_; }
  const XmlElement& operator[](std::size_t k) const { return top_[k]; }
  const XmlElement& front() const { return top_[0]; }
  const XmlElement* begin() const { return top_; }
  const XmlElement* end() const { return top_ + top_count_; }

 private:
  friend class XmlTreeBuilder;
  friend class XmlDirectReader;
  friend XmlDocument parse_xml_text(std::string text, const std::string& file);
  std::unique_ptr<std::string> text_;
  std::set<std::string, std::less<>> names_;
  std::vector<XmlAttribute> attributes_;
  std::vector<XmlElement> elements_;  ///< all of them; the children of each are adjacent
  const XmlElement* top_ = nullptr;   ///< the top-level elements, adjacent too
  std::size_t top_count_ = 0;
};

/// Elements nested deeper than this are refused before parsing (the parser recurses once per
/// level; a scene needs three).
constexpr int kMaxXmlDepth = 100;

/// True for the characters of the element and attribute names of plain scene XML: ASCII letters
/// and digits, '_', '-', '.' and ':'.
bool is_xml_name_char(char c);

/// The longest XML text parse_xml reads (the file size limit, --max-file-size, is lower by
/// default): it counts elements and attributes in 32 bits.
constexpr std::size_t kMaxXmlBytes = (std::size_t{4} << 30) - 1;

/// The elements of an XML text. `text` may hold anything but NUL bytes. Throws SceneError
/// naming `file`, the line and, where one is to blame, the element, with a problem that starts "not
/// well-formed XML: " for a syntax error (an element not closed or closed by another name, a
/// malformed or repeated attribute, text outside of any element, a comment not closed, ...) and one
/// for elements nested deeper than kMaxXmlDepth, or for a text longer than kMaxXmlBytes.
XmlDocument parse_xml(std::string_view text, const std::string& file);

/// The same, taking over `text` instead of copying it (a scene file read whole, parsed where it
/// lies: the document keeps it).
XmlDocument parse_xml_text(std::string text, const std::string& file);

}  // namespace fosssim
