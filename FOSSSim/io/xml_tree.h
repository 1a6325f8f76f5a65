#pragma once
// A read-only tree of the elements of an XML file: what the scene readers see of it. One parser
// (rapidxml, header-only) builds it in every build, native and WebAssembly alike, so that a
// scene reads the same, with the same messages, wherever it is loaded (docs/architecture.md,
// "XML").

#include <string>
#include <string_view>
#include <vector>

namespace fosssim {

/// One attribute, as written (entities such as &amp; translated).
struct XmlAttribute {
  std::string name;
  std::string value;
};

/// One element: its name, the line of its '<', its attributes in document order (no name
/// twice: a repeated attribute is a syntax error) and its child elements. Text, comments,
/// processing instructions and the DOCTYPE are not kept.
class XmlElement {
 public:
  const std::string& name() const { return name_; }
  /// 1-based line of the element's opening '<'.
  int line() const { return line_; }
  /// The value of the attribute `name`, or nullptr when the element has none.
  const char* attribute(std::string_view name) const;
  const std::vector<XmlAttribute>& attributes() const { return attributes_; }
  /// The child elements in document order.
  const std::vector<XmlElement>& children() const { return children_; }
  /// The child elements called `name`, in document order.
  std::vector<const XmlElement*> children_named(std::string_view name) const;

 private:
  friend class XmlTreeBuilder;
  std::string name_;
  int line_ = 0;
  std::vector<XmlAttribute> attributes_;
  std::vector<XmlElement> children_;
};

/// Elements nested deeper than this are refused before parsing (the parser recurses once per
/// level; a scene needs three).
constexpr int kMaxXmlDepth = 100;

/// The top-level elements of an XML text, in document order (a well-formed file has one).
/// `text` may hold anything but NUL bytes. Throws SceneError naming `file`, the line and, where
/// one is to blame, the element, with a problem that starts "not well-formed XML: " for a
/// syntax error (an element not closed or closed by another name, a malformed or repeated
/// attribute, text outside of any element, a comment not closed, ...) and one for elements
/// nested deeper than kMaxXmlDepth.
std::vector<XmlElement> parse_xml(std::string_view text, const std::string& file);

}  // namespace fosssim
