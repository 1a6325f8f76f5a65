#include "io/xml_tree.h"

#include <algorithm>
#include <cstring>
#include <rapidxml/rapidxml.hpp>
#include <utility>

#include "io/page_population.h"
#include "io/scene_error.h"

namespace fosssim {

// Named, not anonymous: XmlTreeBuilder (declared in the header) holds one, and in a unity
// build a member of an anonymous-namespace type is a linkage warning.
namespace xml_tree_detail {

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

}  // namespace xml_tree_detail
using xml_tree_detail::LineTable;

namespace {

/// Where a position of the text is, as the markup before it says: the elements still open, the
/// start tag or comment being read. A plain linear reading of the tags, used only to check the
/// nesting depth before rapidxml (which recurses) reads the text and to name the place of an
/// error rapidxml found; rapidxml alone decides what is well-formed.
struct XmlPlace {
  struct Open {
    std::string name;
    int line;
  };
  std::vector<Open> open;  ///< elements opened and not yet closed, outermost first
  bool in_tag = false;     ///< inside a start tag (`tag`, `tag_line`)
  std::string tag;
  int tag_line = 0;
  bool in_comment = false;  ///< inside a comment that began on `comment_line`
  int comment_line = 0;
  bool too_deep = false;  ///< stopped at an element nested deeper than kMaxXmlDepth
  int line = 1;           ///< the line reached
};

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

XmlPlace place_at(std::string_view text, std::size_t stop) {
  XmlPlace place;
  stop = std::min(stop, text.size());
  std::size_t k = 0;
  const auto advance = [&](std::size_t to) {
    place.line +=
        static_cast<int>(std::count(text.begin() + static_cast<std::ptrdiff_t>(k),
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

bool is_xml_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-' || c == '.' || c == ':';
}

/// Reads the plain XML that scenes are written in straight into an XmlDocument, without
/// rapidxml's node pool (which costs about five times the text): elements whose names are
/// letters, digits and _-.:, attributes whose values hold no '&', text without '&', comments,
/// declarations and processing instructions. Anything else, well-formed or not (an entity, a
/// CDATA section, a DOCTYPE, a repeated attribute, a syntax error, ...), makes read() return
/// false, and the caller lets rapidxml read the text instead; what read() accepts, rapidxml
/// accepts too and reads into the same tree (same names, values, lines and order).
class XmlDirectReader {
 public:
  /// The document's text is its own and NUL-terminated. read() leaves it as it is until it
  /// has read it all: only then does it end each name and value with a NUL, so that on a
  /// false return rapidxml gets the text as it was, without a copy.
  explicit XmlDirectReader(XmlDocument& document) : document_(document) {}

  /// The name `name`, kept once in `document`.
  static const std::string& intern(XmlDocument& document, std::string_view name) {
    const auto found = document.names_.find(name);
    return found != document.names_.end() ? *found : *document.names_.emplace(name).first;
  }

  bool read(std::size_t size) {
    char* p = document_.text_->data();
    line_at_ = p;
    // Each element has its own '<' and each attribute its own '=': bounds known before
    // allocating, so that the arrays never move and elements may point into them.
    // Both are written whole: their pages are mapped at once (io/page_population.h).
    document_.elements_.reserve(static_cast<std::size_t>(std::count(p, p + size, '<')));
    document_.attributes_.reserve(static_cast<std::size_t>(std::count(p, p + size, '=')));
    populate_pages(document_.elements_.data(),
                   document_.elements_.capacity() * sizeof(XmlElement));
    populate_pages(document_.attributes_.data(),
                   document_.attributes_.capacity() * sizeof(XmlAttribute));
    // The elements not yet placed never outnumber the elements: one allocation, no copies.
    pending_.reserve(document_.elements_.capacity());
    populate_pages(pending_.data(), pending_.capacity() * sizeof(XmlElement));
    while (true) {
      skip_blanks(p);
      if (*p == '\0') break;
      if (*p != '<') {
        if (open_.empty()) return false;  // text outside of any element
        for (; *p != '<'; ++p) {
          if (*p == '\0' || *p == '&') return false;
        }
        continue;
      }
      if (p[1] == '!') {
        if (p[2] != '-' || p[3] != '-') return false;
        p = std::strstr(p + 4, "-->");
        if (p == nullptr) return false;
        p += 3;
      } else if (p[1] == '?') {
        p = std::strstr(p + 2, "?>");
        if (p == nullptr) return false;
        p += 2;
      } else if (p[1] == '/') {
        if (!close(p)) return false;
      } else if (!start_tag(p)) {
        return false;
      }
    }
    if (!open_.empty()) return false;
    const std::vector<XmlElement>& top = pending_;  // all open elements are closed
    if (document_.elements_.size() + top.size() > document_.elements_.capacity()) return false;
    document_.top_ = document_.elements_.data() + document_.elements_.size();
    document_.top_count_ = top.size();
    document_.elements_.insert(document_.elements_.end(), top.begin(), top.end());
    end_names_and_values();
    return true;
  }

 private:
  static void skip_blanks(char*& p) {
    while (is_blank(*p)) ++p;
  }

  /// A start tag at p ('<'), with its attributes; an element that is not empty stays open.
  bool start_tag(char*& p) {
    char* name = p + 1;
    char* q = name;
    while (is_xml_name_char(*q)) ++q;
    if (q == name || !(is_blank(*q) || *q == '/' || *q == '>')) return false;
    XmlElement e;
    e.name_ = &intern(document_, {name, static_cast<std::size_t>(q - name)});
    e.line_ = line_of(name);
    std::vector<XmlAttribute>& attributes = document_.attributes_;
    e.attributes_ = attributes.data() + attributes.size();
    skip_blanks(q);
    while (is_xml_name_char(*q)) {
      char* attribute = q;
      while (is_xml_name_char(*q)) ++q;
      char* attribute_end = q;
      skip_blanks(q);
      if (*q != '=') return false;
      ++q;
      skip_blanks(q);
      const char quote = *q;
      if (quote != '"' && quote != '\'') return false;
      char* value = ++q;
      for (; *q != quote; ++q) {
        if (*q == '\0' || *q == '&') return false;
      }
      ++q;
      const std::string_view attribute_name(attribute,
                                            static_cast<std::size_t>(attribute_end - attribute));
      for (const XmlAttribute* a = e.attributes_; a != attributes.data() + attributes.size(); ++a) {
        if (a->name == attribute_name) return false;  // repeated: rapidxml's reading says so
      }
      if (attributes.size() == attributes.capacity()) return false;
      attributes.push_back({attribute_name, value});
      ++e.attribute_count_;
      skip_blanks(q);
    }
    if (q[0] == '/' && q[1] == '>') {
      pending_.push_back(e);
      p = q + 2;
      return true;
    }
    if (q[0] != '>') return false;
    pending_.push_back(e);
    open_.push_back({name, static_cast<std::size_t>(e.name_->size())});
    children_start_.push_back(pending_.size());
    if (open_.size() > static_cast<std::size_t>(kMaxXmlDepth)) return false;
    p = q + 1;
    return true;
  }

  /// The closing tag at p ("</") of the innermost open element: its children join the
  /// document's array, adjacent.
  bool close(char*& p) {
    if (open_.empty()) return false;
    char* name = p + 2;
    char* q = name;
    while (is_xml_name_char(*q)) ++q;
    if (!(is_blank(*q) || *q == '>')) return false;
    if (std::string_view(name, static_cast<std::size_t>(q - name)) != open_.back()) return false;
    skip_blanks(q);
    if (*q != '>') return false;
    p = q + 1;
    const std::size_t start = children_start_.back();
    const auto children = pending_.begin() + static_cast<std::ptrdiff_t>(start);
    std::vector<XmlElement>& all = document_.elements_;
    if (all.size() + (pending_.size() - start) > all.capacity()) return false;
    XmlElement& parent = pending_[start - 1];
    parent.children_ = all.data() + all.size();
    parent.child_count_ = static_cast<std::uint32_t>(pending_.size() - start);
    all.insert(all.end(), children, pending_.end());
    pending_.resize(start);
    children_start_.pop_back();
    open_.pop_back();
    return true;
  }

  /// Ends every attribute's name and value with a NUL, where the '=' (or a blank) after the
  /// name and the closing quote of the value were: the text has been read whole.
  void end_names_and_values() {
    for (XmlAttribute& a : document_.attributes_) {
      char* const name_end = const_cast<char*>(a.name.data()) + a.name.size();
      char* const value = const_cast<char*>(a.value);
      const char quote = value[-1];  // the value holds no such quote (start_tag)
      *std::strchr(value, quote) = '\0';
      *name_end = '\0';
    }
  }

  /// The line of p; p never goes back.
  int line_of(const char* p) {
    line_ += static_cast<int>(std::count(line_at_, p, '\n'));
    line_at_ = p;
    return line_;
  }

  XmlDocument& document_;
  std::vector<std::string_view> open_;  ///< names of the elements open, outermost first
  /// The elements read and not yet placed: the top-level ones, then the children read so far
  /// of each open element, outermost first (an element's children are placed, adjacent, when
  /// it closes).
  std::vector<XmlElement> pending_;
  std::vector<std::size_t> children_start_;  ///< [k]: where open_[k]'s children start
  const char* line_at_ = nullptr;
  int line_ = 1;
};

/// Copies rapidxml's nodes into one XmlDocument: a first walk, in document order, counts the
/// elements and attributes and refuses a repeated attribute; a second fills arrays of exactly
/// that size, level by level, so that the children of an element are adjacent.
class XmlTreeBuilder {
 public:
  using Node = rapidxml::xml_node<char>;

  XmlTreeBuilder(XmlDocument& document, const LineTable& lines, const std::string& file)
      : document_(document), lines_(lines), file_(file) {}

  void build(const Node& root) {
    std::size_t elements = 0;
    std::size_t attributes = 0;
    for (const Node* top = first_element(root); top != nullptr; top = next_element(*top)) {
      ++document_.top_count_;
      count(*top, elements, attributes);
    }
    document_.elements_.resize(elements);
    document_.top_ = document_.elements_.data();
    document_.attributes_.reserve(attributes);
    std::vector<const Node*> nodes;  // nodes[k] is the source of element k
    nodes.reserve(elements);
    for (const Node* top = first_element(root); top != nullptr; top = next_element(*top)) {
      nodes.push_back(top);
    }
    for (std::size_t k = 0; k < nodes.size(); ++k) {  // nodes grows behind k, level by level
      const Node& node = *nodes[k];
      XmlElement& e = document_.elements_[k];
      e.name_ = &intern({node.name(), node.name_size()});
      e.line_ = line_of(node.name());
      e.attributes_ = document_.attributes_.data() + document_.attributes_.size();
      for (const auto* a = node.first_attribute(); a != nullptr; a = a->next_attribute()) {
        document_.attributes_.push_back({{a->name(), a->name_size()}, a->value()});
      }
      e.attribute_count_ = static_cast<std::uint32_t>(document_.attributes_.data() +
                                                      document_.attributes_.size() - e.attributes_);
      e.children_ = document_.elements_.data() + nodes.size();
      for (const Node* c = first_element(node); c != nullptr; c = next_element(*c)) {
        nodes.push_back(c);
      }
      e.child_count_ =
          static_cast<std::uint32_t>(document_.elements_.data() + nodes.size() - e.children_);
    }
  }

 private:
  static const Node* first_element(const Node& parent) {
    const Node* n = parent.first_node();
    while (n != nullptr && n->type() != rapidxml::node_element) n = n->next_sibling();
    return n;
  }
  static const Node* next_element(const Node& node) {
    const Node* n = node.next_sibling();
    while (n != nullptr && n->type() != rapidxml::node_element) n = n->next_sibling();
    return n;
  }

  /// Counts `node` and the elements below it (the depth is at most kMaxXmlDepth), with their
  /// attributes, and refuses the first repeated attribute in document order.
  void count(const Node& node, std::size_t& elements, std::size_t& attributes) const {
    ++elements;
    for (const auto* a = node.first_attribute(); a != nullptr; a = a->next_attribute()) {
      ++attributes;
      const std::string_view name(a->name(), a->name_size());
      for (const auto* b = node.first_attribute(); b != a; b = b->next_attribute()) {
        if (std::string_view(b->name(), b->name_size()) != name) continue;
        // Few per element: the loader bounds their number.
        throw SceneError(
            file_, line_of(a->name()), "<" + std::string(node.name(), node.name_size()) + ">",
            "not well-formed XML: a malformed or repeated attribute (values need quotes: "
            "name=\"value\")");
      }
    }
    for (const Node* c = first_element(node); c != nullptr; c = next_element(*c)) {
      count(*c, elements, attributes);
    }
  }

  const std::string& intern(std::string_view name) {
    return XmlDirectReader::intern(document_, name);
  }

  int line_of(const char* p) const {
    return lines_.line_of(static_cast<std::size_t>(p - document_.text_->data()));
  }

  XmlDocument& document_;
  const LineTable& lines_;
  const std::string& file_;
};

const char* XmlElement::attribute(std::string_view name) const {
  for (const XmlAttribute& a : attributes()) {
    if (a.name == name) return a.value;
  }
  return nullptr;
}

std::vector<const XmlElement*> XmlElement::children_named(std::string_view name) const {
  std::vector<const XmlElement*> found;
  for (const XmlElement& child : children()) {
    if (*child.name_ == name) found.push_back(&child);
  }
  return found;
}

XmlDocument parse_xml(std::string_view text, const std::string& file) {
  return parse_xml_text(std::string(text), file);
}

XmlDocument parse_xml_text(std::string text, const std::string& file) {
  if (text.size() > kMaxXmlBytes) {  // element and attribute counts are 32-bit
    throw SceneError(file, 0, "",
                     "the XML text is larger than " + std::to_string(kMaxXmlBytes >> 20) +
                         " MiB, the most the XML reader reads");
  }
  // The document keeps the text: names and values are read where they are written. The
  // string is held through a pointer, so that moving the document never moves its characters
  // (a short string's are inside the string object).
  XmlDocument direct;
  direct.text_ = std::make_unique<std::string>(std::move(text));
  if (XmlDirectReader(direct).read(direct.text_->size())) return direct;
  // Something the direct reading leaves to rapidxml (which reads in place, up to the string's
  // terminating NUL), on the same text, untouched by the direct reading; the original stays
  // for the messages.
  XmlDocument out;
  out.text_ = std::move(direct.text_);
  direct = XmlDocument();
  const std::string original = *out.text_;
  const XmlPlace whole = place_at(original, original.size());
  if (whole.too_deep) {
    const XmlPlace::Open& deepest = whole.open.back();
    throw SceneError(file, deepest.line, element_name(deepest.name),
                     "elements nested more than " + std::to_string(kMaxXmlDepth) +
                         " deep (a scene needs three)");
  }
  const LineTable lines(original);
  constexpr int kFlags = rapidxml::parse_validate_closing_tags | rapidxml::parse_no_data_nodes |
                         rapidxml::parse_no_element_values;
  {  // rapidxml's nodes are freed as soon as the document is built
    rapidxml::xml_document<char> parsed;
    char* const start = out.text_->data();
    try {
      parsed.parse<kFlags>(start);
    } catch (const rapidxml::parse_error& e) {
      const char* where = e.where<char>() != nullptr ? e.where<char>() : start;
      const auto offset = static_cast<std::size_t>(where - start);
      throw syntax_error(original, file, e.what(), offset, lines);
    }
    XmlTreeBuilder(out, lines, file).build(parsed);
  }
  return out;
}

}  // namespace fosssim
