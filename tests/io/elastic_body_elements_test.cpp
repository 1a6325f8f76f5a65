// The Theme 4 elements (docs/scene-format.md, 'Elastic bodies'): their attributes and defaults,
// FOSSSim's own strictness (every message asserted in full: it is the user interface), the
// typo warnings, and SPEC-elastica's worked examples E1-E5 run from the scene text through the
// integrators: the course's frame 1 to the bit where the spec says bit-identical (E1, E3, E4),
// else to its stated precision.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/step/simulation.h"
#include "io/scene_error.h"
#include "io/scene_loader.h"
#include "support/thrown.h"

namespace fosssim {
namespace {

/// A valid header (lines 1-2), so that the line of the element under test is predictable.
constexpr const char* kElasticHeader =
    "<scene>\n"
    "<duration time=\"0.01\"/><integrator type=\"symplectic-euler\" dt=\"0.01\"/>\n";
constexpr const char* kThreeParticles =
    "<particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n"
    "<particle m=\"1\" px=\"1\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n"
    "<particle m=\"1\" px=\"1\" py=\"1\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n";

std::string elastic_scene_error(const std::string& xml) {
  try {
    load_scene_text(xml, "bad.xml");
  } catch (const SceneError& error) {
    return error.what();
  }
  return "(loaded without error)";
}

/// The error of a scene of three particles (lines 3-5) and `element` on line 6.
std::string element_error(const std::string& element) {
  return elastic_scene_error(std::string(kElasticHeader) + kThreeParticles + element +
                             "\n</scene>\n");
}

Scene load_with(const std::string& element) {
  return load_scene_text(std::string(kElasticHeader) + kThreeParticles + element + "\n</scene>\n",
                         "ok.xml");
}

struct MalformedElasticCase {
  const char* name;
  const char* element;
  const char* message;
};

class MalformedElasticElement : public ::testing::TestWithParam<MalformedElasticCase> {};

TEST_P(MalformedElasticElement, NamesFileLineElementAndProblem) {
  EXPECT_EQ(element_error(GetParam().element), GetParam().message);
}

const MalformedElasticCase kMalformedElasticCases[] = {
    {"SpringMissingIndex", R"(<elasticbodyspringforce i2="1" alpha="1" l0="1"/>)",
     "bad.xml:6: error: <elasticbodyspringforce> 0: attribute \"i1\" is missing"},
    {"SpringIndexOutOfRange", R"(<elasticbodyspringforce i1="0" i2="7" alpha="1" l0="1"/>)",
     "bad.xml:6: error: <elasticbodyspringforce> 0: attribute \"i2\" refers to particle 7, but "
     "the scene has 3 particles (valid indices are 0 to 2)"},
    {"SpringFractionalIndex", R"(<elasticbodyspringforce i1="0" i2="1.5" alpha="1" l0="1"/>)",
     "bad.xml:6: error: <elasticbodyspringforce> 0: attribute \"i2\" must be an integer, found "
     "\"1.5\""},
    {"SpringRepeatedIndex", R"(<elasticbodyspringforce i1="1" i2="1" alpha="1" l0="1"/>)",
     "bad.xml:6: error: <elasticbodyspringforce> 0: attribute \"i2\" must differ from i1 (both "
     "are 1)"},
    {"SpringJunkNumber", R"(<elasticbodyspringforce i1="0" i2="1" alpha="2.0x" l0="1"/>)",
     "bad.xml:6: error: <elasticbodyspringforce> 0: attribute \"alpha\" must be a finite "
     "number, found \"2.0x\""},
    {"SpringNegativeAlpha", R"(<elasticbodyspringforce i1="0" i2="1" alpha="-1" l0="1"/>)",
     "bad.xml:6: error: <elasticbodyspringforce> 0: attribute \"alpha\" must be non-negative, "
     "found -1"},
    {"SpringZeroRestLength", R"(<elasticbodyspringforce i1="0" i2="1" alpha="1" l0="0"/>)",
     "bad.xml:6: error: <elasticbodyspringforce> 0: attribute \"l0\" must be positive, found 0"},
    {"SpringMisspelledAlpha", R"(<elasticbodyspringforce i1="0" i2="1" alhpa="1" l0="1"/>)",
     "bad.xml:6: error: <elasticbodyspringforce> 0: attribute \"alpha\" is missing (the element "
     "has \"alhpa\", which is not read: a misspelling?)"},
    {"BendingMissingTheta0", R"(<elasticbodybendingforce i1="0" i2="1" i3="2" alpha="1"/>)",
     "bad.xml:6: error: <elasticbodybendingforce> 0: attribute \"theta0\" is missing"},
    {"BendingRepeatedIndex",
     R"(<elasticbodybendingforce i1="0" i2="1" i3="0" alpha="1" theta0="0"/>)",
     "bad.xml:6: error: <elasticbodybendingforce> 0: attribute \"i3\" must differ from i1 (both "
     "are 0)"},
    {"BendingNegativeIndex",
     R"(<elasticbodybendingforce i1="-1" i2="1" i3="2" alpha="1" theta0="0"/>)",
     "bad.xml:6: error: <elasticbodybendingforce> 0: attribute \"i1\" refers to particle -1, but "
     "the scene has 3 particles (valid indices are 0 to 2)"},
    {"CstRepeatedIndex",
     R"(<elasticbodycstforce i1="0" i2="2" i3="2" youngsmodulus="1" poissonratio="0"/>)",
     "bad.xml:6: error: <elasticbodycstforce> 0: attribute \"i3\" must differ from i2 (both are "
     "2)"},
    {"CstZeroModulus",
     R"(<elasticbodycstforce i1="0" i2="1" i3="2" youngsmodulus="0" poissonratio="0"/>)",
     "bad.xml:6: error: <elasticbodycstforce> 0: attribute \"youngsmodulus\" must be positive, "
     "found 0"},
    {"CstPoissonRatioOne",
     R"(<elasticbodycstforce i1="0" i2="1" i3="2" youngsmodulus="1" poissonratio="1"/>)",
     "bad.xml:6: error: <elasticbodycstforce> 0: attribute \"poissonratio\" must lie strictly "
     "between -1 and 1 (the plane-stress energy divides by 1 - ν²), found 1"},
    {"CstPoissonRatioMinusOne",
     R"(<elasticbodycstforce i1="0" i2="1" i3="2" youngsmodulus="1" poissonratio="-1"/>)",
     "bad.xml:6: error: <elasticbodycstforce> 0: attribute \"poissonratio\" must lie strictly "
     "between -1 and 1 (the plane-stress energy divides by 1 - ν²), found -1"},
    {"CstMisspelledPoissonRatio",
     R"(<elasticbodycstforce i1="0" i2="1" i3="2" youngsmodulus="1" poisonratio="0.3"/>)",
     "bad.xml:6: error: <elasticbodycstforce> 0: attribute \"poissonratio\" is missing (the "
     "element has \"poisonratio\", which is not read: a misspelling?)"},
    {"CstCollinearRest",
     R"(<elasticbodycstforce i1="0" i2="1" i3="2" youngsmodulus="1" poissonratio="0" xb3x="2" xb3y="0"/>)",
     "bad.xml:6: error: <elasticbodycstforce> 0: the rest triangle (xb1, xb2, xb3, defaulting to "
     "the particles' initial positions) has zero area, so its strain is undefined"},
    {"CstNonNumericRestCorner",
     R"(<elasticbodycstforce i1="0" i2="1" i3="2" youngsmodulus="1" poissonratio="0" xb1x="abc"/>)",
     "bad.xml:6: error: <elasticbodycstforce> 0: attribute \"xb1x\" must be a finite number, "
     "found \"abc\""},
};

INSTANTIATE_TEST_SUITE_P(ElasticBodyElements, MalformedElasticElement,
                         ::testing::ValuesIn(kMalformedElasticCases),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(ElasticBodyElements, RejectsCoincidentParticles) {
  const std::string coincident =
      std::string(kElasticHeader) + kThreeParticles +
      "<particle m=\"1\" px=\"1\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n";
  EXPECT_EQ(elastic_scene_error(coincident +
                                R"(<elasticbodyspringforce i1="1" i2="3" alpha="1" l0="1"/>)" +
                                "\n</scene>\n"),
            "bad.xml:7: error: <elasticbodyspringforce> 0: particles 1 and 3 start at the same "
            "point, where the spring's direction is undefined");
  EXPECT_EQ(
      elastic_scene_error(
          coincident + R"(<elasticbodybendingforce i1="0" i2="1" i3="3" alpha="1" theta0="0"/>)" +
          "\n</scene>\n"),
      "bad.xml:7: error: <elasticbodybendingforce> 0: particles 1 and 3 start at the same point: "
      "the hinge's edge has no direction");
  // A CST whose particles coincide is fine when its rest corners are given and distinct.
  EXPECT_NO_THROW((void)load_scene_text(
      coincident +
          R"(<elasticbodycstforce i1="0" i2="1" i3="3" youngsmodulus="1" poissonratio="0" xb3x="0" xb3y="1"/>)" +
          "\n</scene>\n",
      "ok.xml"));
}

TEST(ElasticBodyElements, BendingIsRefusedInThreeDimensions) {
  const std::string scene =
      "<scene dim=\"3\">\n"
      "<duration time=\"0.01\"/><integrator type=\"symplectic-euler\" dt=\"0.01\"/>\n"
      "<particle m=\"1\" px=\"0\" py=\"0\" pz=\"0\" vx=\"0\" vy=\"0\" vz=\"0\" fixed=\"0\"/>\n"
      "<particle m=\"1\" px=\"1\" py=\"0\" pz=\"0\" vx=\"0\" vy=\"0\" vz=\"0\" fixed=\"0\"/>\n"
      "<particle m=\"1\" px=\"1\" py=\"1\" pz=\"0\" vx=\"0\" vy=\"0\" vz=\"0\" fixed=\"0\"/>\n"
      "<elasticbodybendingforce i1=\"0\" i2=\"1\" i3=\"2\" alpha=\"1\" theta0=\"0\"/>\n"
      "</scene>\n";
  EXPECT_EQ(elastic_scene_error(scene),
            "bad.xml:6: error: <elasticbodybendingforce> 0: a bending force needs a plane for its "
            "signed angle, so it exists in 2D scenes only (this scene has dim=\"3\")");
}

TEST(ElasticBodyElements, SpringAndCstLoadInThreeDimensions) {
  const Scene scene = load_scene_text(
      "<scene dim=\"3\">\n"
      "<duration time=\"0.01\"/><integrator type=\"implicit-euler\" dt=\"0.01\"/>\n"
      "<particle m=\"1\" px=\"0\" py=\"0\" pz=\"0\" vx=\"0\" vy=\"0\" vz=\"0\" fixed=\"0\"/>\n"
      "<particle m=\"1\" px=\"1\" py=\"0\" pz=\"0.5\" vx=\"0\" vy=\"0\" vz=\"0\" fixed=\"0\"/>\n"
      "<particle m=\"1\" px=\"1\" py=\"1\" pz=\"0\" vx=\"0\" vy=\"0\" vz=\"1\" fixed=\"0\"/>\n"
      "<elasticbodyspringforce i1=\"0\" i2=\"1\" alpha=\"3\" l0=\"1\"/>\n"
      "<elasticbodycstforce i1=\"0\" i2=\"1\" i3=\"2\" youngsmodulus=\"10\" poissonratio=\"0.3\" "
      "xb2z=\"0\"/>\n"
      "</scene>\n",
      "ok.xml");
  EXPECT_EQ(scene.model.forces.size(), 2u);
  EXPECT_TRUE(scene.warnings.empty());
  EXPECT_EQ(scene.grading_theme, 4);
  Simulation simulation(scene.model, scene.initial);
  simulation.step();
  EXPECT_TRUE(simulation.state().q.allFinite());
}

TEST(ElasticBodyElements, WarnsAboutUnsupportedAttributesAndUnusualRatios) {
  const Scene scene = load_with(
      R"(<elasticbodycstforce i1="0" i2="1" i3="2" youngsmodulus="1" poissonratio="0.7" ebxx="0.5"/>)");
  ASSERT_EQ(scene.warnings.size(), 2u);
  EXPECT_EQ(scene.warnings[0],
            "ok.xml:6: warning: <elasticbodycstforce> 0: poissonratio 0.7 is unusual (common "
            "materials lie in [0, 0.5]); loaded as given");
  EXPECT_EQ(scene.warnings[1],
            "ok.xml:6: warning: <elasticbodycstforce> 0: attribute \"ebxx\" is not supported (a "
            "rest strain, which the course's program never read); ignored");
}

// The handout's spellings next to the right ones are errors with what they probably mean: the
// value written under the misspelt name would be silently ignored (no course scene has them).
TEST(ElasticBodyElements, HandoutMisspellingsAreErrorsNamingTheAttributeMeant) {
  EXPECT_EQ(
      std::string(
          thrown_by<SceneError>([] {
            load_with(
                R"(<elasticbodycstforce i1="0" i2="1" i3="2" youngsmodulus="1" poissonratio="0.3" poisonratio="0.45" youngsmodullus="2"/>)");
          }).what()),
      "ok.xml:6: error: <elasticbodycstforce> 0: unknown attributes \"poisonratio\" (did you "
      "mean \"poissonratio\"?), \"youngsmodullus\" (did you mean \"youngsmodulus\"?)");
  EXPECT_EQ(
      std::string(thrown_by<SceneError>([] {
                    load_with(
                        R"(<elasticbodyspringforce i1="0" i2="1" alpha="1" alhpa="2" l0="1"/>)");
                  }).what()),
      "ok.xml:6: error: <elasticbodyspringforce> 0: unknown attribute \"alhpa\" (did you "
      "mean \"alpha\"?)");
}

TEST(ElasticBodyElements, CourseRatiosLoadSilentlyAndSelectTheme4Grading) {
  for (const char* nu : {"0", "0.5"}) {
    const Scene scene = load_with(
        std::string(
            R"(<elasticbodycstforce i1="0" i2="1" i3="2" youngsmodulus="1" poissonratio=")") +
        nu + "\"/>");
    EXPECT_TRUE(scene.warnings.empty()) << nu;
    EXPECT_EQ(scene.grading_theme, 4);
  }
  const Scene theme1 = load_with(R"(<simplegravity fx="0" fy="-1"/>)");
  EXPECT_EQ(theme1.grading_theme, 1);
}

// The course's order of kinds (SPEC-elastica section 3): after every Theme 1 kind, the elastic
// springs, then the hinges, then the triangles, each kind in document order, wherever the
// elements stand in the file.
TEST(ElasticBodyElements, KindsAreSummedAfterTheTheme1KindsWhateverTheFileOrder) {
  const Scene scene = load_scene_text(std::string(kElasticHeader) + kThreeParticles +
                                          R"(<particle m="1" px="0" py="1" vx="0" vy="0" fixed="0"/>
<elasticbodycstforce i1="1" i2="2" i3="3" youngsmodulus="1" poissonratio="0"/>
<elasticbodybendingforce i1="1" i2="2" i3="3" alpha="1" theta0="0"/>
<elasticbodyspringforce i1="2" i2="3" alpha="1" l0="1"/>
<vortexforce i="0" j="1" kbs="1" kvc="1"/>
<elasticbodycstforce i1="0" i2="1" i3="2" youngsmodulus="1" poissonratio="0"/>
<elasticbodyspringforce i1="0" i2="1" alpha="1" l0="1"/>
<simplegravity fx="0" fy="-1"/>
<elasticbodybendingforce i1="0" i2="1" i3="2" alpha="1" theta0="0"/>
</scene>
)",
                                      "order.xml");
  std::vector<std::string> labels;
  for (const auto& force : scene.model.forces) labels.push_back(force->label());
  EXPECT_EQ(labels, (std::vector<std::string>{
                        "simplegravity", "vortexforce(0, 1)", "elasticbodyspringforce(2, 3)",
                        "elasticbodyspringforce(0, 1)", "elasticbodybendingforce(1, 2, 3)",
                        "elasticbodybendingforce(0, 1, 2)", "elasticbodycstforce(1, 2, 3)",
                        "elasticbodycstforce(0, 1, 2)"}));
}

// SPEC-elastica 1.1 (compat): the course's program reads a number after leading blanks, so
// " 2.0" is 2.0 and " 1" is particle 1; course scenes may be written that way.
TEST(ElasticBodyElements, LeadingBlanksInValuesReadAsTheCourseReadsThem) {
  const auto first_step = [](const std::string& element) {
    const Scene scene = load_with(element);
    EXPECT_TRUE(scene.warnings.empty()) << element;
    Simulation simulation(scene.model, scene.initial);
    simulation.step();
    return simulation.state();
  };
  const State clean = first_step(
      R"(<elasticbodycstforce i1="0" i2="1" i3="2" youngsmodulus="3.5" poissonratio="0.3" xb2x="1.2"/>)");
  const State blanks = first_step(
      R"(<elasticbodycstforce i1=" 0" i2="  1" i3=" 2" youngsmodulus=" 3.5" poissonratio="  0.3" xb2x=" 1.2"/>)");
  ASSERT_FALSE(clean.v.isZero(0.0));  // the rest corner moved, so the triangle pushes
  EXPECT_TRUE(blanks.q == clean.q);
  EXPECT_TRUE(blanks.v == clean.v);
}

// ---------------------------------------------------------------------------------------------
// SPEC-elastica section 7: the course program's frame 1.

/// Frame 1 of `body` (particles and forces) inside a scene of one step, with `integrator`.
State frame_one(const std::string& integrator, const std::string& body) {
  const Scene scene = load_scene_text("<scene>\n<duration time=\"0.01\"/>\n<integrator type=\"" +
                                          integrator + "\" dt=\"0.01\"/>\n" + body + "</scene>\n",
                                      "example.xml");
  Simulation simulation(scene.model, scene.initial);
  simulation.step();
  return simulation.state();
}

/// Expects each value within `tolerance` (0: the same bits).
void expect_values(const Vector& actual, std::initializer_list<double> expected, double tolerance,
                   const char* what) {
  ASSERT_EQ(actual.size(), static_cast<Eigen::Index>(expected.size()));
  int k = 0;
  for (double value : expected) {
    if (tolerance == 0.0) {
      EXPECT_EQ(actual[k], value) << what << " [" << k << "]";
    } else {
      EXPECT_NEAR(actual[k], value, tolerance) << what << " [" << k << "]";
    }
    ++k;
  }
}

TEST(ElasticBodyWorkedExamples, E1SpringSymplecticIsBitIdentical) {
  const State s = frame_one("symplectic-euler", R"(
    <particle m="1.0" px="0.0" py="0.0" vx="0.0" vy="0.0" fixed="0"/>
    <particle m="2.0" px="1.2" py="0.5" vx="0.1" vy="-0.3" fixed="0"/>
    <elasticbodyspringforce i1="0" i2="1" alpha="3.0" l0="1.0"/>
  )");
  expect_values(
      s.q,
      {8.3076923076923074e-05, 3.4615384615384619e-05, 1.2009584615384614, 0.49698269230769232},
      0.0, "x1");
  expect_values(
      s.v,
      {0.0083076923076923076, 0.0034615384615384621, 0.095846153846153859, -0.30173076923076925},
      0.0, "v1");
}

TEST(ElasticBodyWorkedExamples, E2BendingSymplectic) {
  const State s = frame_one("symplectic-euler", R"(
    <particle m="1.0" px="0.0" py="0.0" vx="0.0" vy="0.0" fixed="0"/>
    <particle m="1.0" px="1.0" py="0.0" vx="0.0" vy="0.0" fixed="0"/>
    <particle m="1.0" px="1.5" py="0.8" vx="0.0" vy="0.0" fixed="0"/>
    <elasticbodybendingforce i1="0" i2="1" i3="2" alpha="2.0" theta0="0.5"/>
  )");
  // The spec's model agrees with the course within 1.8e-18.
  expect_values(s.q,
                {0, -5.2711485924668163e-05, 0.99995261888905651, 8.2324680264369364e-05,
                 1.5000473811109436, 0.79997038680566035},
                4e-16, "x1");
  expect_values(s.v,
                {0, -0.0052711485924668159, -0.0047381110943521942, 0.0082324680264369357,
                 0.0047381110943521942, -0.0029613194339701211},
                4e-18, "v1");
}

TEST(ElasticBodyWorkedExamples, E3CstWithDefaultedRestCornersIsBitIdentical) {
  const State s = frame_one("symplectic-euler", R"(
    <particle m="1.0" px="0.0" py="0.0" vx="0.0" vy="0.0" fixed="0"/>
    <particle m="1.0" px="1.1" py="0.1" vx="0.0" vy="0.0" fixed="0"/>
    <particle m="1.0" px="0.0" py="0.9" vx="0.0" vy="0.0" fixed="0"/>
    <elasticbodycstforce i1="0" i2="1" i3="2" youngsmodulus="10.0" poissonratio="0.3" xb2x="1.0" xb2y="0.0" xb3y="1.0"/>
  )");
  expect_values(s.q,
                {0.00027318681318681348, -3.5494505494505367e-05, 1.0998029670329672,
                 0.099919780219780222, -7.6153846153846156e-05, 0.90011571428571435},
                0.0, "x1");
  expect_values(s.v,
                {0.027318681318681346, -0.0035494505494505367, -0.019703296703296728,
                 -0.0080219780219780244, -0.007615384615384615, 0.011571428571428562},
                0.0, "v1");
}

TEST(ElasticBodyWorkedExamples, E4AllThreeForcesImplicit) {
  const State s = frame_one("implicit-euler", R"(
    <simplegravity fx="0.0" fy="-9.81"/>
    <particle m="1.0" px="0.0" py="0.0" vx="0.0" vy="0.0" fixed="1"/>
    <particle m="1.0" px="1.0" py="0.0" vx="0.0" vy="0.0" fixed="0"/>
    <particle m="1.0" px="1.0" py="1.0" vx="0.0" vy="0.0" fixed="0"/>
    <particle m="1.0" px="2.0" py="0.6" vx="0.5" vy="0.0" fixed="0"/>
    <elasticbodyspringforce i1="1" i2="3" alpha="50.0" l0="1.0"/>
    <elasticbodybendingforce i1="0" i2="1" i3="3" alpha="5.0" theta0="0.0"/>
    <elasticbodycstforce i1="0" i2="1" i3="2" youngsmodulus="100.0" poissonratio="0.45" xb3x="0.0"/>
  )");
  // Six free unknowns: FOSSSim solves the Newton systems with the course's dense LU in the
  // course's order (docs/solvers.md, 'The course-exact dense path'), so frame 1 is the course's
  // to the bit, as the spec says of this example.
  expect_values(s.q,
                {0, 0, 0.98921589742861082, -0.0068323558490214695, 0.9819693349114732,
                 0.98754961639381644, 2.004273618931685, 0.59846200528308802},
                0.0, "x1");
  expect_values(s.v,
                {0, 0, -1.078410257138916, -0.68323558490214698, -1.8030665088526747,
                 -1.2450383606183526, 0.42736189316848211, -0.15379947169119518},
                0.0, "v1");
}

TEST(ElasticBodyWorkedExamples, E5FoldedHingeDoesNotWrap) {
  const State s = frame_one("symplectic-euler", R"(
    <particle m="1.0" px="-1.0" py="0.0" vx="0.0" vy="0.0" fixed="0"/>
    <particle m="1.0" px="0.0" py="0.0" vx="0.0" vy="0.0" fixed="0"/>
    <particle m="1.0" px="-0.9991351502732795" py="-0.04158066243329049" vx="0.0" vy="0.0" fixed="0"/>
    <elasticbodybendingforce i1="0" i2="1" i3="2" alpha="1.0" theta0="3.0"/>
  )");
  expect_values(s.q,
                {-1, 0.00030499999999999999, -1.2682102042153601e-05, -2.6377916664976643e-07,
                 -0.99912246817123729, -0.041885398654123843},
                4e-16, "x1");
  expect_values(s.v,
                {0, 0.030499999999999999, -0.0012682102042153602, -2.637791666497664e-05,
                 0.0012682102042153598, -0.030473622083335022},
                4e-18, "v1");
}

}  // namespace
}  // namespace fosssim
