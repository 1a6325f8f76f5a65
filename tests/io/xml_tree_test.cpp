// The XML tree the scene readers read (io/xml_tree): names, attributes in document order,
// children, line numbers, and every kind of syntax error named with its line and element.

#include "io/xml_tree.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "io/scene_error.h"

namespace fosssim {
namespace {

std::string parse_error(const std::string& xml) {
  try {
    parse_xml(xml, "t.xml");
  } catch (const SceneError& error) {
    return error.what();
  }
  return "(parsed without error)";
}

TEST(XmlTree, ElementsAttributesAndLines) {
  const std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<!-- a comment\n with <tags/> inside -->\n"
      "<scene a=\"1\" b='two'>\n"
      "  <particle m=\"&lt;&amp;&#65;\"\n px=\"0\"/>text\n"
      "  <mesh><pin i=\"3\"/><![CDATA[<notanelement/>]]></mesh>\n"
      "</scene>\n";
  const XmlDocument top = parse_xml(xml, "t.xml");
  ASSERT_EQ(top.size(), 1u);
  const XmlElement& scene = top[0];
  EXPECT_EQ(scene.name(), "scene");
  EXPECT_EQ(scene.line(), 4);
  ASSERT_EQ(scene.attributes().size(), 2u);
  EXPECT_EQ(scene.attributes()[0].name, "a");
  EXPECT_EQ(scene.attributes()[1].name, "b");
  EXPECT_STREQ(scene.attribute("b"), "two");
  EXPECT_EQ(scene.attribute("c"), nullptr);
  ASSERT_EQ(scene.children().size(), 2u);
  const XmlElement& particle = scene.children()[0];
  EXPECT_EQ(particle.line(), 5);
  EXPECT_STREQ(particle.attribute("m"), "<&A");
  EXPECT_STREQ(particle.attribute("px"), "0");
  const XmlElement& mesh = scene.children()[1];
  EXPECT_EQ(mesh.line(), 7);
  ASSERT_EQ(mesh.children().size(), 1u);
  EXPECT_EQ(mesh.children()[0].name(), "pin");
  EXPECT_EQ(mesh.children()[0].line(), 7);
  ASSERT_EQ(scene.children_named("mesh").size(), 1u);
  EXPECT_EQ(scene.children_named("mesh")[0], &mesh);
  EXPECT_TRUE(scene.children_named("edge").empty());
}

TEST(XmlTree, SeveralTopLevelElementsAreReturned) {
  const XmlDocument top = parse_xml("<a/>\n\n<b/>", "t.xml");
  ASSERT_EQ(top.size(), 2u);
  EXPECT_EQ(top[1].name(), "b");
  EXPECT_EQ(top[1].line(), 3);
  EXPECT_TRUE(parse_xml("  \n<!-- only a comment -->\n", "t.xml").empty());
}

TEST(XmlTree, SyntaxErrorsNameLineAndElement) {
  // The innermost open element, where it was opened, for a wrong closing tag and at the end.
  EXPECT_EQ(parse_error("<scene>\n<a>\n</b>\n</scene>"),
            "t.xml:2: error: <a>: not well-formed XML: this element is not closed, or is closed "
            "with a different name");
  EXPECT_EQ(parse_error("<scene>\n<a>\n<particle/>\n"),
            "t.xml:2: error: not well-formed XML: an element opened on this line is never closed "
            "(the file ends inside it)");
  // An attribute: the line where the problem is, in a tag over several lines.
  EXPECT_EQ(parse_error("<scene>\n<particle\n m=\"1\"\n x=1/>\n</scene>"),
            "t.xml:4: error: <particle>: not well-formed XML: a malformed or repeated attribute "
            "(values need quotes: name=\"value\")");
  EXPECT_EQ(parse_error("<scene>\n<particle m=\"1\"\n\n m=\"2\"/>\n</scene>"),
            "t.xml:4: error: <particle>: not well-formed XML: a malformed or repeated attribute "
            "(values need quotes: name=\"value\")");
  EXPECT_EQ(parse_error("<scene>\n<particle m=\"1\n\n"),
            "t.xml:2: error: <particle>: not well-formed XML: a malformed or repeated attribute "
            "(values need quotes: name=\"value\")");
  EXPECT_EQ(parse_error("<scene>\n<!-- hello\n\n<particle/>\n"),
            "t.xml:2: error: not well-formed XML: a comment is not closed (missing -->)");
  EXPECT_EQ(parse_error("<scene>\n<particle m=\"1\" !>\n</scene>"),
            "t.xml:2: error: not well-formed XML: a malformed element");
  EXPECT_EQ(parse_error("<scene/>\nhello"),
            "t.xml:2: error: not well-formed XML: text outside of any element (is this an XML "
            "scene file?)");
  EXPECT_EQ(parse_error("<scene>\n<p m=\"&#12\"/>\n</scene>"),
            "t.xml:2: error: <p>: not well-formed XML: a malformed character reference (&#number; "
            "or &#xhex;)");
  // Markup inside quotes, comments and CDATA does not confuse the place of an error.
  EXPECT_EQ(parse_error("<scene a=\"<b>\">\n<!-- <c> -->\n<![CDATA[<d>]]>\n<e>\n</scene>"),
            "t.xml:4: error: <e>: not well-formed XML: this element is not closed, or is closed "
            "with a different name");
}

/// Whether two trees have the same names, lines, attributes (in order) and children.
void expect_same_tree(const XmlElement& a, const XmlElement& b) {
  EXPECT_EQ(a.name(), b.name());
  EXPECT_EQ(a.line(), b.line()) << a.name();
  ASSERT_EQ(a.attributes().size(), b.attributes().size()) << a.name();
  for (std::size_t k = 0; k < a.attributes().size(); ++k) {
    EXPECT_EQ(a.attributes()[k].name, b.attributes()[k].name);
    EXPECT_STREQ(a.attributes()[k].value, b.attributes()[k].value);
  }
  ASSERT_EQ(a.children().size(), b.children().size()) << a.name();
  for (std::size_t k = 0; k < a.children().size(); ++k) {
    expect_same_tree(a.children()[k], b.children()[k]);
  }
}

TEST(XmlTree, PlainXmlReadsAsRapidxmlReadsIt) {
  // Plain scene XML is read without rapidxml; an entity reference anywhere sends the whole text
  // to rapidxml. "&#49;" is "1", so both texts hold the same tree, read two ways.
  const std::string plain =
      "<?xml version=\"1.0\"?>\n<!-- a <comment/> -->\n"
      "<scene a=\"1\" b = 'two' c=\"\"\n   d=\"x y\">text <?pi x?>\n"
      "  <particle m=\"0.5\"\n px=\"0\"/>\n"
      "  <mesh><pin i=\"3\"/>\n<pin i=\"4\"><x/></pin  ></mesh>\n"
      "  <edge i=\"0\" j=\"1\"/>\n"
      "</scene>\n<second last=\"LAST\"/>\n";
  std::string via_rapidxml = plain;
  via_rapidxml.replace(via_rapidxml.find("LAST"), 4, "&#49;");
  std::string direct_text = plain;
  direct_text.replace(direct_text.find("LAST"), 4, "1");
  const XmlDocument direct = parse_xml(direct_text, "t.xml");
  const XmlDocument rapid = parse_xml(via_rapidxml, "t.xml");
  ASSERT_EQ(direct.size(), 2u);
  ASSERT_EQ(rapid.size(), 2u);
  expect_same_tree(direct[0], rapid[0]);
  expect_same_tree(direct[1], rapid[1]);
  // What the scene readers rely on, checked on the direct reading.
  const XmlElement& scene = direct[0];
  EXPECT_EQ(scene.line(), 3);
  EXPECT_STREQ(scene.attribute("b"), "two");
  EXPECT_STREQ(scene.attribute("c"), "");
  EXPECT_STREQ(scene.attribute("d"), "x y");
  for (const XmlAttribute& a : scene.attributes()) {
    EXPECT_EQ(a.name.data()[a.name.size()], '\0') << "names end with a NUL";
  }
  ASSERT_EQ(scene.children().size(), 3u);
  EXPECT_EQ(scene.children()[1].children().size(), 2u);
  EXPECT_EQ(scene.children()[1].children()[1].children()[0].name(), "x");
  EXPECT_EQ(scene.children()[2].line(), 9);
  EXPECT_EQ(&scene.children()[0].name(), &direct[0].children()[0].name());
  EXPECT_EQ(&scene.children()[1].children()[0].name(), &scene.children()[1].children()[1].name())
      << "a name is kept once";
  // Moving the document keeps its elements where they are.
  XmlDocument moved = parse_xml(direct_text, "t.xml");
  const XmlElement* moved_before = &moved[0];
  const XmlDocument kept = std::move(moved);
  EXPECT_EQ(&kept[0], moved_before);
  EXPECT_STREQ(kept[1].attribute("last"), "1");
}

TEST(XmlTree, ARepeatedAttributeIsAnErrorInPlainXmlToo) {
  EXPECT_EQ(parse_error("<scene>\n<a x=\"1\"\n x=\"2\"/>\n</scene>"),
            "t.xml:3: error: <a>: not well-formed XML: a malformed or repeated attribute (values "
            "need quotes: name=\"value\")");
}

TEST(XmlTree, NestingDeeperThanTheLimitIsRefusedBeforeParsing) {
  std::string deep;
  for (int k = 0; k < kMaxXmlDepth; ++k) deep += "<a>\n";
  std::string closed = deep;
  for (int k = 0; k < kMaxXmlDepth; ++k) closed += "</a>";
  EXPECT_EQ(parse_xml(closed, "t.xml").size(), 1u);
  EXPECT_EQ(parse_error(deep + "<b>" + "</b>"), "t.xml:" + std::to_string(kMaxXmlDepth + 1) +
                                                    ": error: <b>: elements nested more than " +
                                                    std::to_string(kMaxXmlDepth) +
                                                    " deep (a scene needs three)");
}

}  // namespace
}  // namespace fosssim
