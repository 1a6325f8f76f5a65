#include "io/xml_tree.h"

#include <rapidxml/rapidxml.hpp>

#include <algorithm>
#include <cstring>
#include <utility>

#include "io/scene_error.h"

namespace fosssim {

namespace {

/// The 1-based line of each offset of one text, by binary search over its line ends.
class LineTable {
 public:
  explicit LineTable(std::string_view text) {
    for (std::size_t k = 0; k < text.size(); ++k) {
      if (text[k] == '\n') newlines_.push_back(k);
    }
  }
  int line_of(std::size_t offset) const {
    return 1 + static_cast<int>(std::lower_bound(newlines_.begin(), newlines_.end(), offset) -
                                newlines_.begin());
  }

 private:
  std::vector<std::size_t> newlines_;
};

/// Where a position of the text is, as the markup before it says: the elements still open, the
/// start tag or comment being read. A plain linear reading of the tags, used only to check the
/// nesting depth before rapidxml (which recurses) reads the text and to name the place of an
/// error rapidxml found; rapidxml alone decides what is well-formed.
struct XmlPlace {
  struct Open {
    std::string name;
    int line;
  };
  std::vector<Open> open;     ///< elements opened and not yet closed, outermost first
  bool in_tag = false;        ///< inside a start tag (`tag`, `tag_line`)
  std::string tag;
  int tag_line = 0;
  bool in_comment = false;    ///< inside a comment that began on `comment_line`
  int comment_line = 0;
  bool too_deep = false;      ///< stopped at an element nested deeper than kMaxXmlDepth
  int line = 1;               ///< the line reached
};

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

XmlPlace place_at(std::string_view text, std::size_t stop) {
  XmlPlace place;
  stop = std::min(stop, text.size());
  std::size_t k = 0;
  const auto advance = [&](std::size_t to) {
    place.line += static_cast<int>(std::count(text.begin() + static_cast<std::ptrdiff_t>(k),
                                              text.begin() + static_cast<std::ptrdiff_t>(to), '\n'));
    k = to;
  };
  // The end of a construct that starts at k and ends with `close`, or npos when it does not end
  // before `stop`.
  const auto end_of = [&](std::size_t from, std::string_view close) {
    const std::size_t end = text.find(close, from);
    return end == std::string_view::npos || end + close.size() > stop ? std::string_view::npos
                                                                      : end + close.size();
  };
  while (k < stop) {
    if (text[k] != '<') {
      advance(k + 1);
      continue;
    }
    const std::string_view rest = text.substr(k);
    std::size_t end = 0;
    if (rest.starts_with("<!--")) {
      end = end_of(k + 4, "-->");
      if (end == std::string_view::npos) {
        place.in_comment = true;
        place.comment_line = place.line;
        return place;
      }
    } else if (rest.starts_with("<![CDATA[")) {
      end = end_of(k + 9, "]]>");
    } else if (rest.starts_with("<?")) {
      end = end_of(k + 2, "?>");
    } else if (rest.starts_with("<!")) {
      end = end_of(k + 2, ">");
    } else if (rest.starts_with("</")) {
      end = end_of(k + 2, ">");
      if (end != std::string_view::npos && !place.open.empty()) place.open.pop_back();
    } else {  // a start tag: its name, then up to the '>' outside quotes
      const int tag_line = place.line;
      std::size_t j = k + 1;
      while (j < text.size() && !is_blank(text[j]) && text[j] != '/' && text[j] != '>') ++j;
      std::string name(text.substr(k + 1, j - k - 1));
      char quote = 0;
      for (; j < stop; ++j) {
        if (quote != 0) {
          if (text[j] == quote) quote = 0;
        } else if (text[j] == '"' || text[j] == '\'') {
          quote = text[j];
        } else if (text[j] == '>') {
          break;
        }
      }
      if (j >= stop) {
        advance(stop);
        place.in_tag = true;
        place.tag = std::move(name);
        place.tag_line = tag_line;
        return place;
      }
      end = j + 1;
      if (text[j - 1] != '/') {
        place.open.push_back({std::move(name), tag_line});
        if (place.open.size() > static_cast<std::size_t>(kMaxXmlDepth)) {
          place.too_deep = true;
          return place;
        }
      }
    }
    if (end == std::string_view::npos) {
      advance(stop);
      return place;
    }
    advance(end);
  }
  return place;
}

std::string element_name(const std::string& name) { return name.empty() ? "" : "<" + name + ">"; }

/// The SceneError for what rapidxml reported at `offset`, in the words of FOSSSim's messages.
SceneError syntax_error(std::string_view text, const std::string& file, const std::string& what,
                        std::size_t offset, const LineTable& lines) {
  const XmlPlace place = place_at(text, offset);
  const int line = lines.line_of(offset);
  const auto error = [&](int at, const std::string& element, const std::string& problem) {
    return SceneError(file, at, element, "not well-formed XML: " + problem);
  };
  const std::string innermost = place.open.empty() ? "" : element_name(place.open.back().name);
  const int innermost_line = place.open.empty() ? line : place.open.back().line;
  if (place.in_comment) {
    return error(place.comment_line, "", "a comment is not closed (missing -->)");
  }
  if (what == "expected <") {
    return error(line, "", "text outside of any element (is this an XML scene file?)");
  }
  if (what == "invalid closing tag name") {
    return error(innermost_line, innermost,
                 "this element is not closed, or is closed with a different name");
  }
  if (what == "expected =" || what == "expected ' or \"") {
    // A value whose quote never closes ends at the end of the text: its tag's line says more.
    return error(offset >= text.size() ? place.tag_line : line, element_name(place.tag),
                 "a malformed or repeated attribute (values need quotes: name=\"value\")");
  }
  if (what == "unexpected end of data") {
    if (place.in_tag) {
      return error(place.tag_line, element_name(place.tag),
                   "a malformed or repeated attribute (values need quotes: name=\"value\")");
    }
    return error(innermost_line, "",
                 "an element opened on this line is never closed (the file ends inside it)");
  }
  if (what == "expected element name" || what == "expected >") {
    return error(line, "", "a malformed element");
  }
  if (what == "expected ;" || what == "invalid numeric character entity") {
    return error(line, element_name(place.tag),
                 "a malformed character reference (&#number; or &#xhex;)");
  }
  if (what == "expected ?>" || what == "expected PI target") {
    return error(line, "", "a malformed declaration or processing instruction (<?...?>)");
  }
  return error(line, innermost, "unreadable (" + what + ")");
}

}  // namespace

/// Copies rapidxml's nodes into XmlElements, with lines from the names' offsets in the buffer.
class XmlTreeBuilder {
 public:
  XmlTreeBuilder(const char* buffer, const LineTable& lines, const std::string& file)
      : buffer_(buffer), lines_(lines), file_(file) {}

  std::vector<XmlElement> children_of(const rapidxml::xml_node<char>& node) const {
    std::vector<XmlElement> children;
    for (const auto* child = node.first_node(); child != nullptr; child = child->next_sibling()) {
      if (child->type() == rapidxml::node_element) children.push_back(element(*child));
    }
    return children;
  }

 private:
  XmlElement element(const rapidxml::xml_node<char>& node) const {
    XmlElement e;
    e.name_.assign(node.name(), node.name_size());
    e.line_ = line_of(node.name());
    for (const auto* a = node.first_attribute(); a != nullptr; a = a->next_attribute()) {
      XmlAttribute attribute{std::string(a->name(), a->name_size()),
                             std::string(a->value(), a->value_size())};
      if (e.attribute(attribute.name) != nullptr) {  // few: the loader bounds their number
        throw SceneError(
            file_, line_of(a->name()), "<" + e.name_ + ">",
            "not well-formed XML: a malformed or repeated attribute (values need quotes: "
            "name=\"value\")");
      }
      e.attributes_.push_back(std::move(attribute));
    }
    e.children_ = children_of(node);
    return e;
  }
  int line_of(const char* p) const { return lines_.line_of(static_cast<std::size_t>(p - buffer_)); }

  const char* buffer_;
  const LineTable& lines_;
  const std::string& file_;
};

const char* XmlElement::attribute(std::string_view name) const {
  for (const XmlAttribute& a : attributes_) {
    if (a.name == name) return a.value.c_str();
  }
  return nullptr;
}

std::vector<const XmlElement*> XmlElement::children_named(std::string_view name) const {
  std::vector<const XmlElement*> found;
  for (const XmlElement& child : children_) {
    if (child.name_ == name) found.push_back(&child);
  }
  return found;
}

std::vector<XmlElement> parse_xml(std::string_view text, const std::string& file) {
  const XmlPlace whole = place_at(text, text.size());
  if (whole.too_deep) {
    const XmlPlace::Open& deepest = whole.open.back();
    throw SceneError(file, deepest.line, element_name(deepest.name),
                     "elements nested more than " + std::to_string(kMaxXmlDepth) +
                         " deep (a scene needs three)");
  }
  // rapidxml parses in place and reads up to a terminating NUL: it gets a copy.
  std::vector<char> buffer(text.begin(), text.end());
  buffer.push_back('\0');
  const LineTable lines(text);
  constexpr int kFlags = rapidxml::parse_validate_closing_tags | rapidxml::parse_no_data_nodes |
                         rapidxml::parse_no_element_values;
  rapidxml::xml_document<char> document;
  try {
    document.parse<kFlags>(buffer.data());
  } catch (const rapidxml::parse_error& e) {
    const char* where = e.where<char>() != nullptr ? e.where<char>() : buffer.data();
    const auto offset = static_cast<std::size_t>(where - buffer.data());
    throw syntax_error(text, file, e.what(), offset, lines);
  }
  return XmlTreeBuilder(buffer.data(), lines, file).children_of(document);
}

}  // namespace fosssim
