// Every malformed input of issue 2 gives one message naming file, line, element and problem.
// The messages are asserted in full: they are the user interface.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>

#include "core/integrators/integrator_registry.h"
#include "io/scene_error.h"
#include "io/scene_loader.h"
#include "support/scratch_folder.h"
#include "support/thrown.h"

namespace fosssim {
namespace {

/// A valid header (line 1-2) so that the line of the element under test is predictable.
constexpr const char* kValidHeader =
    "<scene>\n"
    "<duration time=\"1\"/><integrator type=\"explicit-euler\" dt=\"0.1\"/>\n";
constexpr const char* kTwoParticles =
    "<particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n"
    "<particle m=\"1\" px=\"1\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n"
    "<edge i=\"0\" j=\"1\"/>\n";

std::string loading_error(const std::string& xml) {
  try {
    load_scene_text(xml, "bad.xml");
  } catch (const SceneError& error) {
    return error.what();
  }
  return "(loaded without error)";
}

struct MalformedSceneCase {
  const char* name;
  std::string body;  // after the header; its first line is line 3
  const char* message;
};

class MalformedScene : public ::testing::TestWithParam<MalformedSceneCase> {};

TEST_P(MalformedScene, NamesFileLineElementAndProblem) {
  const MalformedSceneCase& c = GetParam();
  EXPECT_EQ(loading_error(kValidHeader + c.body + "</scene>\n"), c.message);
}

const MalformedSceneCase kMalformedSceneCases[] = {
    {"MissingAttribute", "<particle m=\"1\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n",
     "bad.xml:3: error: <particle> 0: attribute \"px\" is missing"},
    {"NonNumericAttribute",
     "<particle m=\"heavy\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n",
     "bad.xml:3: error: <particle> 0: attribute \"m\" must be a finite number, found \"heavy\""},
    {"TrailingGarbage", "<particle m=\"1.5kg\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n",
     "bad.xml:3: error: <particle> 0: attribute \"m\" must be a finite number, found \"1.5kg\""},
    {"EmptyNumber", "<particle m=\"\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n",
     "bad.xml:3: error: <particle> 0: attribute \"m\" must be a finite number, found \"\""},
    {"NotFinite", "<particle m=\"1\" px=\"inf\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n",
     "bad.xml:3: error: <particle> 0: attribute \"px\" must be a finite number, found \"inf\""},
    {"NaN", "<particle m=\"1\" px=\"0\" py=\"nan\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n",
     "bad.xml:3: error: <particle> 0: attribute \"py\" must be a finite number, found \"nan\""},
    {"ZeroMass", "<particle m=\"0\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n",
     "bad.xml:3: error: <particle> 0: attribute \"m\" must be positive, found 0"},
    {"NegativeMass", "<particle m=\"-2\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"1\"/>\n",
     "bad.xml:3: error: <particle> 0: attribute \"m\" must be positive, found -2"},
    {"FixedTwo", "<particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"2\"/>\n",
     "bad.xml:3: error: <particle> 0: attribute \"fixed\" must be 0 or 1, found \"2\""},
    {"FixedWord", "<particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"true\"/>\n",
     "bad.xml:3: error: <particle> 0: attribute \"fixed\" must be 0 or 1, found \"true\""},
    {"EdgeIndexOutOfRange", std::string(kTwoParticles) + "<edge i=\"0\" j=\"2\"/>\n",
     "bad.xml:6: error: <edge> 1: attribute \"j\" refers to particle 2, but the scene has 2 "
     "particles (valid indices are 0 to 1)"},
    {"NegativeIndex", std::string(kTwoParticles) + "<edge i=\"-1\" j=\"0\"/>\n",
     "bad.xml:6: error: <edge> 1: attribute \"i\" refers to particle -1, but the scene has 2 "
     "particles (valid indices are 0 to 1)"},
    {"FractionalIndex", std::string(kTwoParticles) + "<edge i=\"0.5\" j=\"0\"/>\n",
     "bad.xml:6: error: <edge> 1: attribute \"i\" must be an integer, found \"0.5\""},
    {"EdgeToItself", std::string(kTwoParticles) + "<edge i=\"1\" j=\"1\"/>\n",
     "bad.xml:6: error: <edge> 1: attribute \"j\" must differ from i (both are 1)"},
    {"SpringOnMissingEdge",
     std::string(kTwoParticles) + "<springforce edge=\"1\" k=\"1\" l0=\"1\"/>\n",
     "bad.xml:6: error: <springforce> 0: attribute \"edge\" refers to edge 1, but the scene has 1 "
     "edge (valid indices are 0 to 0)"},
    {"SpringWithoutEdges", "<springforce edge=\"0\" k=\"1\" l0=\"1\"/>\n",
     "bad.xml:3: error: <springforce> 0: attribute \"edge\" refers to edge 0, but the scene has 0 "
     "edges"},
    {"ZeroLengthSpring",
     "<particle m=\"1\" px=\"0.5\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n"
     "<particle m=\"1\" px=\"0.5\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n"
     "<edge i=\"0\" j=\"1\"/>\n<springforce edge=\"0\" k=\"1\" l0=\"1\"/>\n",
     "bad.xml:6: error: <springforce> 0: edge 0 has zero length (particles 0 and 1 coincide), so "
     "the spring's direction is undefined"},
    {"NegativeStiffness",
     std::string(kTwoParticles) + "<springforce edge=\"0\" k=\"-1\" l0=\"1\"/>\n",
     "bad.xml:6: error: <springforce> 0: attribute \"k\" must be non-negative, found -1"},
    {"NegativeDamping",
     std::string(kTwoParticles) + "<springforce edge=\"0\" k=\"1\" l0=\"1\" b=\"-0.5\"/>\n",
     "bad.xml:6: error: <springforce> 0: attribute \"b\" must be non-negative, found -0.5"},
    {"GravityOnItself",
     std::string(kTwoParticles) + "<gravitationalforce i=\"1\" j=\"1\" G=\"1\"/>\n",
     "bad.xml:6: error: <gravitationalforce> 0: attribute \"j\" must differ from i (both are 1)"},
    {"GravityIndexOutOfRange",
     std::string(kTwoParticles) + "<gravitationalforce i=\"0\" j=\"7\" G=\"1\"/>\n",
     "bad.xml:6: error: <gravitationalforce> 0: attribute \"j\" refers to particle 7, but the "
     "scene has 2 particles (valid indices are 0 to 1)"},
    {"VortexMissingParameter",
     std::string(kTwoParticles) + "<vortexforce i=\"0\" j=\"1\" kbs=\"1\"/>\n",
     "bad.xml:6: error: <vortexforce> 0: attribute \"kvc\" is missing"},
    {"GravityMissingComponent", "<simplegravity fx=\"0\"/>\n",
     "bad.xml:3: error: <simplegravity> 0: attribute \"fy\" is missing"},
    {"UnknownElement", "<particles m=\"1\"/>\n",
     "bad.xml:3: error: <particles>: unknown element (did you mean <particle>?)"},
    {"UnknownElementFarFromAny", "<wind speed=\"1\"/>\n",
     "bad.xml:3: error: <wind>: unknown element"},
    {"MisspeltAttribute",
     "<particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\" raduis=\"0.5\"/>\n",
     "bad.xml:3: error: <particle> 0: unknown attribute \"raduis\" (did you mean \"radius\"?)"},
    {"ColorOutOfRange",
     std::string(kTwoParticles) + "<particlecolor i=\"0\" r=\"1.5\" g=\"0\" b=\"0\"/>\n",
     "bad.xml:6: error: <particlecolor> 0: attribute \"r\" must be between 0 and 1, found 1.5"},
    {"EdgeColorIndex",
     std::string(kTwoParticles) + "<edgecolor i=\"3\" r=\"1\" g=\"0\" b=\"0\"/>\n",
     "bad.xml:6: error: <edgecolor> 0: attribute \"i\" refers to edge 3, but the scene has 1 edge "
     "(valid indices are 0 to 0)"},
    {"DuplicateDuration", "<duration time=\"2\"/>\n",
     "bad.xml:3: error: <duration>: may appear only once (first at line 2)"},
    {"NonPositiveViewport", "<viewport cx=\"0\" cy=\"0\" size=\"0\"/>\n",
     "bad.xml:3: error: <viewport>: attribute \"size\" must be positive, found 0"},
    // Elements nested in one that holds none were dropped without a word.
    {"ElementInsideParticle",
     "<particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\">\n"
     "<simplegravity fx=\"0\" fy=\"-9.81\"/>\n</particle>\n",
     "bad.xml:4: error: <simplegravity>: inside <particle>, which holds no elements: close "
     "<particle .../> before it"},
    {"SpringInsideEdge",
     std::string(kTwoParticles, std::strlen(kTwoParticles) - 20) +
         "<edge i=\"0\" j=\"1\"><springforce edge=\"0\" k=\"1\" l0=\"1\"/></edge>\n",
     "bad.xml:5: error: <springforce>: inside <edge>, which holds no elements: close <edge .../> "
     "before it"},
};

INSTANTIATE_TEST_SUITE_P(SceneLoader, MalformedScene, ::testing::ValuesIn(kMalformedSceneCases),
                         [](const ::testing::TestParamInfo<MalformedSceneCase>& info) {
                           return info.param.name;
                         });

TEST(SceneLoaderErrors, ANulByteIsRefusedWithItsLine) {
  const std::string text = std::string(kValidHeader) + kTwoParticles + std::string(1, '\0') +
                           "<simplegravity fx=\"0\" fy=\"-9.81\"/>\n</scene>\n";
  const std::size_t at = std::string(kValidHeader).size() + std::string(kTwoParticles).size();
  EXPECT_EQ(loading_error(text), "bad.xml:6: error: a NUL byte (at byte " + std::to_string(at) +
                                     "): a scene file is text, and nothing after it would be read");
}

TEST(SceneLoaderErrors, AnElementOfTooManyAttributesIsRefusedBeforeParsing) {
  std::string many = "<particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"";
  for (int k = 0; k < 300000; ++k) many += " a" + std::to_string(k) + "='='";
  const std::string text =
      std::string(kValidHeader) + "<!-- a=1 b=2 -->\n" + many + "/>\n</scene>\n";
  // Refused at once (tinyxml2 alone takes quadratic time: 60,000 attributes took 16 s).
  EXPECT_EQ(loading_error(text),
            "bad.xml:4: error: an element with more than the limit of 100 attributes (raise it "
            "with --max-attributes N)");
  // The limit counts '=' outside quotes within a tag, and can be raised.
  Limits limits;
  limits.max_attributes = 6;
  InputFiles files(limits);
  const std::string six = std::string(kValidHeader) +
                          "<description text=\"a=1, b=2, c=3, d=4, e=5, f=6, g=7\"/>\n"
                          "<particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n"
                          "</scene>\n";
  EXPECT_EQ(load_scene_text(six, "six.xml", files).model.num_particles(), 1);
  limits.max_attributes = 5;
  InputFiles fewer(limits);
  EXPECT_THROW(load_scene_text(six, "six.xml", fewer), SceneError);
}

TEST(SceneLoaderErrors, UnknownIntegratorListsEveryTypeOfTheRegistry) {
  const std::string error = loading_error(
      "<scene>\n<duration time=\"1\"/>\n<integrator type=\"rk4\" dt=\"0.1\"/>\n</scene>");
  // The course's four first, with their aliases; then FOSSSim's own, whatever the registry holds.
  const std::string start =
      "bad.xml:3: error: <integrator>: attribute \"type\" names an unknown integrator \"rk4\" "
      "(expected one of explicit-euler, symplectic-euler (or forward-backward-euler, "
      "semi-implicit-euler), linearized-implicit-euler (or linearized-implicit), "
      "implicit-euler (or implicit), ";
  EXPECT_EQ(error.substr(0, start.size()), start);
  EXPECT_EQ(error.back(), ')');
  for (const IntegratorMethod* method : integrator_methods()) {
    EXPECT_NE(error.find(std::string(method->name)), std::string::npos) << method->name;
  }
}

TEST(SceneLoaderErrors, NonPositiveTimeStep) {
  EXPECT_EQ(
      loading_error(
          "<scene>\n<duration time=\"1\"/>\n<integrator type=\"implicit\" dt=\"0\"/>\n</scene>"),
      "bad.xml:3: error: <integrator>: attribute \"dt\" must be positive, found 0");
}

TEST(SceneLoaderErrors, NegativeDuration) {
  EXPECT_EQ(
      loading_error(
          "<scene>\n<duration time=\"-1\"/>\n<integrator type=\"implicit\" dt=\"1\"/>\n</scene>"),
      "bad.xml:2: error: <duration>: attribute \"time\" must be non-negative, found -1");
}

TEST(SceneLoaderErrors, MissingRequiredElements) {
  EXPECT_EQ(loading_error("<scene>\n<integrator type=\"implicit\" dt=\"1\"/>\n</scene>"),
            "bad.xml:1: error: <scene>: the required element <duration> is missing");
  EXPECT_EQ(loading_error("<scene>\n<duration time=\"1\"/>\n</scene>"),
            "bad.xml:1: error: <scene>: the required element <integrator> is missing");
}

TEST(SceneLoaderErrors, WrongRootElement) {
  EXPECT_EQ(loading_error("<?xml version=\"1.0\"?>\n<world>\n</world>"),
            "bad.xml:2: error: <world>: the root element must be <scene>");
}

TEST(SceneLoaderErrors, BadDimension) {
  EXPECT_EQ(loading_error("<scene dim=\"4\">\n</scene>"),
            "bad.xml:1: error: <scene>: attribute \"dim\" must be 2 or 3, found 4");
}

TEST(SceneLoaderErrors, NotXml) {
  EXPECT_EQ(loading_error("<scene>\n<duration time=\"1\">\n</scene>"),
            "bad.xml:2: error: <duration>: not well-formed XML: this element is not closed, or is "
            "closed with a different name");
  EXPECT_EQ(loading_error("<scene>\n<particle m=1/>\n</scene>"),
            "bad.xml:2: error: <particle>: not well-formed XML: a malformed or repeated attribute "
            "(values need quotes: name=\"value\")");
  EXPECT_EQ(loading_error("<scene>\n<edge i=\"0\" i=\"1\"/>\n</scene>"),
            "bad.xml:2: error: <edge>: not well-formed XML: a malformed or repeated attribute "
            "(values need quotes: name=\"value\")");
  EXPECT_EQ(loading_error("this is not XML"),
            "bad.xml:1: error: not well-formed XML: text outside of any element (is this an XML "
            "scene file?)");
  EXPECT_EQ(loading_error("<scene>\n<particle/>\n"),
            "bad.xml:1: error: not well-formed XML: an element opened on this line is never closed "
            "(the file ends inside it)");
  EXPECT_EQ(
      loading_error("<scene>\n</scene>\n<scene>\n</scene>"),
      "bad.xml:3: error: <scene>: a second top-level element; a scene file holds one <scene>");
}

TEST(SceneLoaderErrors, EmptyText) {
  EXPECT_EQ(loading_error(""), "bad.xml: error: the file is empty (expected a <scene> element)");
  EXPECT_EQ(loading_error(" \n\t\n"),
            "bad.xml: error: the file is empty (expected a <scene> element)");
}

TEST(SceneLoaderErrors, MissingFileAndDirectory) {
  const SceneError missing =
      thrown_by<SceneError>([] { load_scene_file("/nonexistent/scene.xml"); });
  EXPECT_STREQ(missing.what(),
               "/nonexistent/scene.xml: error: cannot open the file: No such file or directory");
  EXPECT_EQ(missing.kind(), ErrorKind::kBadInput);
  const SceneError directory = thrown_by<SceneError>(
      [] { load_scene_file(std::filesystem::temp_directory_path().string()); });
  EXPECT_EQ(directory.problem(), "is a directory, not a file");
}

TEST(SceneLoaderErrors, EmptyFileOnDisk) {
  const testing::ScratchFolder folder;
  const std::string path = folder.write("empty.xml", "");
  const SceneError error = thrown_by<SceneError>([&] { load_scene_file(path); });
  EXPECT_EQ(error.file(), path);
  EXPECT_EQ(error.line(), 0);
  EXPECT_EQ(error.problem(), "the file is empty (expected a <scene> element)");
}

TEST(SceneLoaderErrors, ErrorCarriesItsParts) {
  const SceneError error = thrown_by<SceneError>([] {
    load_scene_text(
        std::string(kValidHeader) +
            "<particle m=\"x\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/></scene>",
        "parts.xml");
  });
  EXPECT_EQ(error.file(), "parts.xml");
  EXPECT_EQ(error.line(), 3);
  EXPECT_EQ(error.element(), "<particle> 0");
  EXPECT_EQ(error.problem(), "attribute \"m\" must be a finite number, found \"x\"");
}

}  // namespace
}  // namespace fosssim

namespace fosssim {
namespace {

// Issue 23: one run reports the problems of every element, in the order of their lines.
TEST(SceneLoaderErrors, EveryElementsProblemIsReportedInOneRunInLineOrder) {
  const std::string text = std::string(kValidHeader) +
                           "<particle m=\"-1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n"
                           "<particle m=\"1\" px=\"1\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"2\"/>\n"
                           "<simplegravity fx=\"0\"/>\n"
                           "<sprnigforce edge=\"0\" k=\"1\" l0=\"1\"/>\n"
                           "<duration time=\"2\"/>\n"
                           "</scene>\n";
  const SceneErrors error = thrown_by<SceneErrors>([&] { load_scene_text(text, "bad.xml"); });
  EXPECT_EQ(std::string(error.what()),
            "bad.xml:3: error: <particle> 0: attribute \"m\" must be positive, found -1\n"
            "bad.xml:4: error: <particle> 1: attribute \"fixed\" must be 0 or 1, found \"2\"\n"
            "bad.xml:5: error: <simplegravity> 0: attribute \"fy\" is missing\n"
            "bad.xml:6: error: <sprnigforce>: unknown element (did you mean <springforce>?)\n"
            "bad.xml:7: error: <duration>: may appear only once (first at line 2)");
  // The structured parts are those of the first line.
  EXPECT_EQ(error.line(), 3);
  EXPECT_EQ(error.element(), "<particle> 0");
  EXPECT_EQ(error.kind(), ErrorKind::kBadInput);
  EXPECT_EQ(error.total(), 5u);
  EXPECT_EQ(error.errors().size(), 5u);
}

// An element that refers to one whose own element failed is skipped, not reported: its problem
// is the other's. Elements after it keep their indices.
TEST(SceneLoaderErrors, ElementsReferringToBrokenOnesAreSkippedWithoutAReport) {
  const std::string text = std::string(kValidHeader) +
                           "<particle m=\"0\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n"
                           "<particle m=\"1\" px=\"1\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n"
                           "<particle m=\"1\" px=\"2\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n"
                           "<edge i=\"0\" j=\"1\"/>\n"                      // broken: particle 0
                           "<edge i=\"1\" j=\"2\" radius=\"-1\"/>\n"        // broken itself
                           "<edge i=\"1\" j=\"2\"/>\n"                      // edge 2, fine
                           "<springforce edge=\"0\" k=\"1\" l0=\"1\"/>\n"   // skipped
                           "<springforce edge=\"1\" k=\"1\" l0=\"1\"/>\n"   // skipped
                           "<springforce edge=\"2\" k=\"-1\" l0=\"1\"/>\n"  // its own problem
                           "<particlecolor i=\"0\" r=\"1\" g=\"0\" b=\"0\"/>\n"  // skipped
                           "</scene>\n";
  const SceneError error = thrown_by<SceneError>([&] { load_scene_text(text, "bad.xml"); });
  EXPECT_EQ(std::string(error.what()),
            "bad.xml:3: error: <particle> 0: attribute \"m\" must be positive, found 0\n"
            "bad.xml:7: error: <edge> 1: attribute \"radius\" must be non-negative, found -1\n"
            "bad.xml:11: error: <springforce> 2: attribute \"k\" must be non-negative, found -1");
}

// Bounded: a generated file with a problem on every line prints the first 20 and a count.
TEST(SceneLoaderErrors, ReportsAtMostTwentyProblemsAndCountsTheRest) {
  std::string text = kValidHeader;
  for (int k = 0; k < 1000; ++k) {
    text += "<particle m=\"-1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n";
  }
  text += "</scene>\n";
  const std::string message = loading_error(text);
  EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 20);
  EXPECT_EQ(message.substr(0, message.find('\n')),
            "bad.xml:3: error: <particle> 0: attribute \"m\" must be positive, found -1");
  EXPECT_EQ(message.substr(message.rfind('\n') + 1),
            "... and 980 more errors (only the first 20 are shown)");
}

// A problem that leaves nothing to go on with ends reading at once, after those found before.
TEST(SceneLoaderErrors, ABadDimensionEndsReading) {
  EXPECT_EQ(loading_error("<scene dim=\"4\">\n<particle m=\"-1\"/>\n</scene>\n"),
            "bad.xml:1: error: <scene>: attribute \"dim\" must be 2 or 3, found 4");
}

}  // namespace
}  // namespace fosssim
