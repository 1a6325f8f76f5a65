#include "junit_report.h"

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include "printable_text.h"
#include "report_samples.h"

namespace fosssim {
namespace {

using tinyxml2::XMLElement;

std::vector<const XMLElement*> children(const XMLElement* parent, const char* name) {
  std::vector<const XMLElement*> out;
  for (const XMLElement* e = parent->FirstChildElement(name); e; e = e->NextSiblingElement(name)) {
    out.push_back(e);
  }
  return out;
}

TEST(JunitReport, OneSuitePerFolderOneCasePerSceneWithCounts) {
  const std::string xml = junit_xml(testing::sample_run());
  tinyxml2::XMLDocument document;
  ASSERT_EQ(document.Parse(xml.c_str()), tinyxml2::XML_SUCCESS) << xml;
  const XMLElement* root = document.RootElement();
  EXPECT_STREQ(root->Name(), "testsuites");
  EXPECT_EQ(root->IntAttribute("tests"), 6);
  EXPECT_EQ(root->IntAttribute("failures"), 3);
  EXPECT_EQ(root->IntAttribute("errors"), 1);
  const auto suites = children(root, "testsuite");
  ASSERT_EQ(suites.size(), 3u);
  EXPECT_STREQ(suites[0]->Attribute("name"), "assets/a");
  EXPECT_STREQ(suites[1]->Attribute("name"), "assets/b");
  EXPECT_STREQ(suites[2]->Attribute("name"), "extra/c");
  EXPECT_EQ(suites[1]->IntAttribute("failures"), 1);
  EXPECT_EQ(suites[1]->IntAttribute("errors"), 1);
  EXPECT_STREQ(suites[0]->Attribute("time"), "0.750");
  const auto kind = children(suites[2]->FirstChildElement("properties"), "property");
  ASSERT_EQ(kind.size(), 2u);
  EXPECT_STREQ(kind[0]->Attribute("value"), "/path/to/student <bin>");
  EXPECT_STREQ(kind[1]->Attribute("value"), "extra-credit");

  const auto cases = children(suites[0], "testcase");
  ASSERT_EQ(cases.size(), 2u);
  EXPECT_STREQ(cases[0]->Attribute("name"), "one.xml");
  EXPECT_STREQ(cases[0]->Attribute("classname"), "assets.a");
  EXPECT_EQ(cases[0]->FirstChildElement("failure"), nullptr);
  const XMLElement* failure = cases[1]->FirstChildElement("failure");
  ASSERT_NE(failure, nullptr);
  EXPECT_STREQ(failure->Attribute("type"), "failed");
  EXPECT_NE(std::string(failure->Attribute("message")).find("step 17, particle 2"),
            std::string::npos);
  EXPECT_NE(std::string(failure->GetText()).find("First divergence at step 17"), std::string::npos);
  const XMLElement* error = children(suites[1], "testcase")[1]->FirstChildElement("error");
  ASSERT_NE(error, nullptr);
  EXPECT_STREQ(error->Attribute("type"), "scene-error");
}

TEST(JunitReport, EscapesMarkupAndMakesControlBytesPrintable) {
  const std::string xml = junit_xml(testing::sample_run());
  for (unsigned char c : xml) {
    EXPECT_TRUE(c >= 0x20 || c == '\n' || c == '\t') << "raw control byte " << int(c);
  }
  tinyxml2::XMLDocument document;
  ASSERT_EQ(document.Parse(xml.c_str()), tinyxml2::XML_SUCCESS);
  const XMLElement* crash = document.RootElement()
                                ->FirstChildElement("testsuite")
                                ->NextSiblingElement("testsuite")
                                ->FirstChildElement("testcase")
                                ->FirstChildElement("failure");
  ASSERT_NE(crash, nullptr);
  EXPECT_STREQ(crash->Attribute("type"), "crashed");
  EXPECT_EQ(std::string(crash->Attribute("message")), printable_text(testing::kNastyReason));
  EXPECT_EQ(std::string(crash->Attribute("message")),
            "exploded <at> step & \"quoted\" 'single' \xce\xbb\\x01\\xff");
  const XMLElement* stderr_text = crash->Parent()->FirstChildElement("system-err");
  ASSERT_NE(stderr_text, nullptr);
  EXPECT_EQ(std::string(stderr_text->GetText()), "line one\nline <two> & \\x07");
}

}  // namespace
}  // namespace fosssim
