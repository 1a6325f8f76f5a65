// The XML tree the scene readers read (io/xml_tree): names, attributes in document order,
// children, line numbers, and every kind of syntax error named with its line and element.

#include "io/xml_tree.h"

#include <gtest/gtest.h>

#include <string>

#include "io/scene_error.h"

namespace fosssim {
namespace {

std::string error_of(const std::string& xml) {
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
  EXPECT_EQ(error_of("<scene>\n<a>\n</b>\n</scene>"),
            "t.xml:2: error: <a>: not well-formed XML: this element is not closed, or is closed "
            "with a different name");
  EXPECT_EQ(error_of("<scene>\n<a>\n<particle/>\n"),
            "t.xml:2: error: not well-formed XML: an element opened on this line is never closed "
            "(the file ends inside it)");
  // An attribute: the line where the problem is, in a tag over several lines.
  EXPECT_EQ(error_of("<scene>\n<particle\n m=\"1\"\n x=1/>\n</scene>"),
            "t.xml:4: error: <particle>: not well-formed XML: a malformed or repeated attribute "
            "(values need quotes: name=\"value\")");
  EXPECT_EQ(error_of("<scene>\n<particle m=\"1\"\n\n m=\"2\"/>\n</scene>"),
            "t.xml:4: error: <particle>: not well-formed XML: a malformed or repeated attribute "
            "(values need quotes: name=\"value\")");
  EXPECT_EQ(error_of("<scene>\n<particle m=\"1\n\n"),
            "t.xml:2: error: <particle>: not well-formed XML: a malformed or repeated attribute "
            "(values need quotes: name=\"value\")");
  EXPECT_EQ(error_of("<scene>\n<!-- hello\n\n<particle/>\n"),
            "t.xml:2: error: not well-formed XML: a comment is not closed (missing -->)");
  EXPECT_EQ(error_of("<scene>\n<particle m=\"1\" !>\n</scene>"),
            "t.xml:2: error: not well-formed XML: a malformed element");
  EXPECT_EQ(error_of("<scene/>\nhello"),
            "t.xml:2: error: not well-formed XML: text outside of any element (is this an XML "
            "scene file?)");
  EXPECT_EQ(error_of("<scene>\n<p m=\"&#12\"/>\n</scene>"),
            "t.xml:2: error: <p>: not well-formed XML: a malformed character reference (&#number; "
            "or &#xhex;)");
  // Markup inside quotes, comments and CDATA does not confuse the place of an error.
  EXPECT_EQ(error_of("<scene a=\"<b>\">\n<!-- <c> -->\n<![CDATA[<d>]]>\n<e>\n</scene>"),
            "t.xml:4: error: <e>: not well-formed XML: this element is not closed, or is closed "
            "with a different name");
}

TEST(XmlTree, NestingDeeperThanTheLimitIsRefusedBeforeParsing) {
  std::string deep;
  for (int k = 0; k < kMaxXmlDepth; ++k) deep += "<a>\n";
  std::string closed = deep;
  for (int k = 0; k < kMaxXmlDepth; ++k) closed += "</a>";
  EXPECT_EQ(parse_xml(closed, "t.xml").size(), 1u);
  EXPECT_EQ(error_of(deep + "<b>" + "</b>"),
            "t.xml:" + std::to_string(kMaxXmlDepth + 1) +
                ": error: <b>: elements nested more than " + std::to_string(kMaxXmlDepth) +
                " deep (a scene needs three)");
}

}  // namespace
}  // namespace fosssim
