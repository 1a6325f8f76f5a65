// The contact elements of scene files: what they read, every malformed input with its message,
// the warnings for values the course accepts but that are probably mistakes, and the
// vx="0"vy="0" pre-pass.

#include "io/collision_elements.h"

#include <gtest/gtest.h>

#include <string>

#include "core/collisions/contact_registry.h"
#include "io/scene_loader.h"

namespace fosssim {
namespace {

constexpr const char* kOneParticleHeader =
    "<scene>\n"
    "<duration time=\"1\"/><integrator type=\"explicit-euler\" dt=\"0.1\"/>\n"
    "<particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n";

Scene load_with_collisions(const std::string& body) {
  return load_scene_text(kOneParticleHeader + body + "</scene>\n", "c.xml");
}

std::string collision_error(const std::string& body, const char* header = kOneParticleHeader) {
  try {
    load_scene_text(header + body + "</scene>\n", "c.xml");
  } catch (const SceneError& error) {
    return error.what();
  }
  return "(loaded without error)";
}

TEST(CollisionElements, ReadsHalfPlanesColoursAndTheCoursesDefaults) {
  const Scene scene = load_with_collisions(
      "<halfplane px=\"0\" py=\"-1\" nx=\"0\" ny=\"2\"/>\n"
      "<halfplanecolor i=\"0\" r=\"0.5\" g=\"0.25\" b=\"1\"/>\n"
      "<collision type=\"hybrid\"/>\n");
  ASSERT_EQ(scene.model.half_planes.size(), 1u);
  EXPECT_EQ(scene.model.half_planes[0].normal[1], 2.0);  // kept unnormalised
  EXPECT_EQ(scene.appearance.half_plane_color[0], (Color{0.5, 0.25, 1.0}));
  const CollisionSettings& s = scene.model.collisions;
  EXPECT_EQ(s.method->name, "hybrid");
  EXPECT_EQ(s.cor, 1.0);
  EXPECT_EQ(s.stiffness, 10.0);
  EXPECT_EQ(s.thickness, 0.1);
  EXPECT_EQ(s.max_iterations, 10);
  EXPECT_TRUE(scene.warnings.empty());
  const Scene penalty = load_with_collisions("<collision type=\"penalty\"/>\n");
  EXPECT_EQ(penalty.model.collisions.stiffness, 100.0);
  EXPECT_EQ(penalty.model.collisions.thickness, 0.01);
  EXPECT_EQ(penalty.model.collisions.penalty_jacobian, PenaltyJacobian::kNone);
  EXPECT_EQ(load_with_collisions("<collision type=\"penalty\" penalty-jacobian=\"exact\"/>\n")
                .model.collisions.penalty_jacobian,
            PenaltyJacobian::kExact);
  EXPECT_EQ(load_with_collisions("").model.collisions.method->name, "none");
}

TEST(CollisionElements, EveryRegisteredMethodLoadsWithTheDefaultsOfItsOptions) {
  for (const ContactMethod* method : contact_methods()) {
    if (!method->scope.particles || !method->scope.runs_2d) continue;
    SCOPED_TRACE(std::string(method->name));
    const Scene scene =
        load_with_collisions("<collision type=\"" + std::string(method->name) + "\"/>\n");
    const CollisionSettings& s = scene.model.collisions;
    EXPECT_EQ(s.method, method);
    EXPECT_TRUE(scene.warnings.empty());
    ASSERT_EQ(s.options.specs().size(), method->options.size());
    for (const OptionSpec& option : method->options) {
      if (option.type == OptionSpec::Type::kChoice) {
        EXPECT_EQ(s.options.choice(option.name), option.choices.front());
      } else {
        EXPECT_EQ(s.options.number(option.name), option.default_value) << option.name;
      }
    }
  }
}

TEST(CollisionElements, OptionsGivenAreReadIntoTheSettings) {
  const Scene scene = load_with_collisions(
      "<collision type=\"hybrid\" COR=\"0.5\" k=\"7\" thickness=\"0.2\" "
      "penalty-jacobian=\"exact\" maxiters=\"3\"/>\n");
  const CollisionSettings& s = scene.model.collisions;
  EXPECT_EQ(s.options.number("COR"), 0.5);
  EXPECT_EQ(s.cor, 0.5);
  EXPECT_EQ(s.stiffness, 7.0);
  EXPECT_EQ(s.thickness, 0.2);
  EXPECT_EQ(s.penalty_jacobian, PenaltyJacobian::kExact);
  EXPECT_EQ(s.max_iterations, 3);
  EXPECT_TRUE(scene.warnings.empty());
  // An empty penalty-jacobian is the course's none, as it always was; an empty number is not.
  EXPECT_EQ(load_with_collisions("<collision type=\"penalty\" penalty-jacobian=\"\"/>\n")
                .model.collisions.penalty_jacobian,
            PenaltyJacobian::kNone);
  EXPECT_EQ(collision_error("<collision type=\"penalty\" k=\"\"/>\n"),
            "c.xml:4: error: <collision>: attribute \"k\" must be a finite number, found \"\"");
}

TEST(CollisionElements, MaxitersIsTruncatedTowardZeroWithAWarning) {
  const Scene scene = load_with_collisions("<collision type=\"hybrid\" maxiters=\"2.7\"/>\n");
  EXPECT_EQ(scene.model.collisions.max_iterations, 2);
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_EQ(scene.warnings[0],
            "c.xml:4: warning: <collision>: maxiters = 2.7 is read as 2 impulse passes, as the "
            "course reads it");
}

TEST(CollisionElements, MaxitersAboveTheLimitIsCappedWithAWarning) {
  // A hostile campaign's scene asked for two billion passes a step: each pass logs every pair's
  // polynomials, so the step grew its log by 40 MB a second for hours.
  const Scene scene =
      load_with_collisions("<collision type=\"hybrid\" maxiters=\"2000000000\"/>\n");
  EXPECT_EQ(scene.model.collisions.max_iterations, 1000);
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_EQ(scene.warnings[0],
            "c.xml:4: warning: <collision>: maxiters = 2e+09 is more than the limit of 1000 "
            "impulse passes a step; 1000 are made (raise it with --max-hybrid-passes N; "
            "docs/limits-and-failures.md, \"Hybrid passes\")");
  // The limit itself, and the course's values, are taken as they are.
  for (const int passes : {0, 1, 10, 1000}) {
    const Scene at = load_with_collisions("<collision type=\"hybrid\" maxiters=\"" +
                                          std::to_string(passes) + "\"/>\n");
    EXPECT_EQ(at.model.collisions.max_iterations, passes);
    EXPECT_TRUE(at.warnings.empty()) << passes;
  }
}

// Issue 24: the cap is a limit like the others, which the command line raises or lowers.
TEST(CollisionElements, TheLimitOfHybridPassesCanBeRaisedAndLowered) {
  const std::string text = std::string(kOneParticleHeader) +
                           "<collision type=\"hybrid\" maxiters=\"5000\"/>\n</scene>\n";
  Limits raised;
  raised.max_hybrid_passes = 10000;
  InputFiles more(raised);
  const Scene scene = load_scene_text(text, "c.xml", more);
  EXPECT_EQ(scene.model.collisions.max_iterations, 5000);
  EXPECT_TRUE(scene.warnings.empty());
  Limits lowered;
  lowered.max_hybrid_passes = 20;
  InputFiles fewer(lowered);
  const Scene capped = load_scene_text(text, "c.xml", fewer);
  EXPECT_EQ(capped.model.collisions.max_iterations, 20);
  ASSERT_EQ(capped.warnings.size(), 1u);
  EXPECT_NE(capped.warnings[0].find("more than the limit of 20 impulse passes a step; 20 are made"),
            std::string::npos)
      << capped.warnings[0];
}

struct BadContactCase {
  const char* name;
  const char* body;  // its first line is line 4
  const char* message;
};

class BadContactElement : public ::testing::TestWithParam<BadContactCase> {};

TEST_P(BadContactElement, NamesFileLineElementAndProblem) {
  EXPECT_EQ(collision_error(GetParam().body), GetParam().message);
}

const BadContactCase kBadContactCases[] = {
    {"HalfPlaneAttributeMissing", "<halfplane px=\"0\" py=\"0\" nx=\"0\"/>\n",
     "c.xml:4: error: <halfplane> 0: attribute \"ny\" is missing"},
    {"HalfPlaneAttributeNotANumber", "<halfplane px=\"a\" py=\"0\" nx=\"0\" ny=\"1\"/>\n",
     "c.xml:4: error: <halfplane> 0: attribute \"px\" must be a finite number, found \"a\""},
    {"HalfPlaneColorWithoutHalfPlanes", "<halfplanecolor i=\"0\" r=\"0\" g=\"0\" b=\"0\"/>\n",
     "c.xml:4: error: <halfplanecolor> 0: attribute \"i\" refers to half-plane 0, but the scene "
     "has no half-planes"},
    {"HalfPlaneColorIndexOutOfRange",
     "<halfplane px=\"0\" py=\"0\" nx=\"0\" ny=\"1\"/>\n"
     "<halfplanecolor i=\"1\" r=\"0\" g=\"0\" b=\"0\"/>\n",
     "c.xml:5: error: <halfplanecolor> 0: attribute \"i\" refers to half-plane 1, but the scene "
     "has 1 half-plane (valid indices are 0 to 0)"},
    {"HalfPlaneColorOutsideZeroOne",
     "<halfplane px=\"0\" py=\"0\" nx=\"0\" ny=\"1\"/>\n"
     "<halfplanecolor i=\"0\" r=\"2\" g=\"0\" b=\"0\"/>\n",
     "c.xml:5: error: <halfplanecolor> 0: attribute \"r\" must be between 0 and 1, found 2"},
    {"CollisionWithoutType", "<collision COR=\"1\"/>\n",
     "c.xml:4: error: <collision>: attribute \"type\" is missing"},
    {"CollisionTypeWrongCase", "<collision type=\"SIMPLE\"/>\n",
     "c.xml:4: error: <collision>: attribute \"type\" names an unknown collision handling "
     "\"SIMPLE\" (expected one of none, simple, penalty, continuous-time, hybrid; exact "
     "spelling, lower case)"},
    {"CollisionTypeMisspelt", "<collision type=\"hybird\"/>\n",
     "c.xml:4: error: <collision>: attribute \"type\" names an unknown collision handling "
     "\"hybird\" (did you mean \"hybrid\"? expected one of none, simple, penalty, "
     "continuous-time, hybrid; exact spelling, lower case)"},
    {"CollisionTypeOfRigidBodies", "<collision type=\"gr-lcp\" maxreflections=\"0\"/>\n",
     "c.xml:4: error: <collision>: attribute \"type\" \"gr-lcp\" does not handle particles (it "
     "is a method of rigid bodies, named by <rigidbodycollisionhandling response=\"...\">)"},
    {"CollisionTypeMisspeltOnlyAmongParticleMethods", "<collision type=\"lcpp\"/>\n",
     "c.xml:4: error: <collision>: attribute \"type\" names an unknown collision handling "
     "\"lcpp\" (expected one of none, simple, penalty, continuous-time, hybrid; exact "
     "spelling, lower case)"},
    {"CorNotANumber", "<collision type=\"simple\" COR=\"bouncy\"/>\n",
     "c.xml:4: error: <collision>: attribute \"COR\" must be a finite number, found \"bouncy\""},
    {"StiffnessNotANumber", "<collision type=\"penalty\" k=\"stiff\"/>\n",
     "c.xml:4: error: <collision>: attribute \"k\" must be a finite number, found \"stiff\""},
    {"UnknownPenaltyJacobian", "<collision type=\"penalty\" penalty-jacobian=\"yes\"/>\n",
     "c.xml:4: error: <collision>: attribute \"penalty-jacobian\" must be \"none\" (the "
     "course's) or \"exact\", found \"yes\""},
    {"UnknownDetection", "<collisiondetection type=\"grid\"/>\n",
     "c.xml:4: error: <collisiondetection>: attribute \"type\" must be \"allpairs\" or "
     "\"contest\", found \"grid\""},
    {"SphereIn2D", "<sphere px=\"0\" py=\"0\" pz=\"0\" radius=\"1\"/>\n",
     "c.xml:4: error: <sphere> 0: spheres are obstacles of 3D scenes only (<scene "
     "dim=\"3\">)"},
};

INSTANTIATE_TEST_SUITE_P(Cases, BadContactElement, ::testing::ValuesIn(kBadContactCases),
                         [](const auto& info) { return std::string(info.param.name); });

constexpr const char* kHeader3D =
    "<scene dim=\"3\">\n"
    "<duration time=\"1\"/><integrator type=\"local-global\" dt=\"0.01\"/>\n"
    "<particle m=\"1\" px=\"0\" py=\"0\" pz=\"0\" vx=\"0\" vy=\"0\" vz=\"0\" fixed=\"0\"/>\n";

TEST(CollisionElements, ReadsSpheresAndTheirColoursIn3D) {
  const Scene scene =
      load_scene_text(std::string(kHeader3D) +
                          "<halfplane px=\"0\" py=\"-1\" pz=\"0\" nx=\"0\" ny=\"1\" nz=\"0\"/>\n"
                          "<sphere px=\"1\" py=\"2\" pz=\"3\" radius=\"0.5\"/>\n"
                          "<sphere px=\"0\" py=\"0\" pz=\"-4\" radius=\"2\"/>\n"
                          "<spherecolor i=\"1\" r=\"1\" g=\"0.5\" b=\"0\"/>\n"
                          "<collision type=\"penalty\"/>\n</scene>\n",
                      "c.xml");
  ASSERT_EQ(scene.model.spheres.size(), 2u);
  EXPECT_EQ(scene.model.spheres[0].center, (Vector(Eigen::Vector3d(1, 2, 3))));
  EXPECT_EQ(scene.model.spheres[0].radius, 0.5);
  EXPECT_EQ(scene.model.spheres[1].radius, 2.0);
  ASSERT_EQ(scene.appearance.sphere_color.size(), 2u);
  EXPECT_EQ(scene.appearance.sphere_color[0], Appearance::kDefaultSphereColor);
  EXPECT_EQ(scene.appearance.sphere_color[1], (Color{1.0, 0.5, 0.0}));
  EXPECT_EQ(scene.model.half_planes[0].normal.size(), 3);
  EXPECT_TRUE(scene.warnings.empty());
}

TEST(CollisionElements, BadSpheresNameFileLineAndProblem) {
  EXPECT_EQ(collision_error("<sphere px=\"0\" py=\"0\" pz=\"0\" radius=\"0\"/>\n", kHeader3D),
            "c.xml:4: error: <sphere> 0: attribute \"radius\" must be positive, found 0");
  EXPECT_EQ(collision_error("<sphere px=\"0\" py=\"0\" radius=\"1\"/>\n", kHeader3D),
            "c.xml:4: error: <sphere> 0: attribute \"pz\" is missing");
  EXPECT_EQ(collision_error("<sphere px=\"0\" py=\"0\" pz=\"0\" radius=\"1\"/>\n"
                            "<spherecolor i=\"1\" r=\"0\" g=\"0\" b=\"0\"/>\n",
                            kHeader3D),
            "c.xml:5: error: <spherecolor> 0: attribute \"i\" refers to sphere 1, but the scene "
            "has 1 sphere (valid indices are 0 to 0)");
  EXPECT_EQ(collision_error("<spherecolor i=\"0\" r=\"0\" g=\"0\" b=\"0\"/>\n", kHeader3D),
            "c.xml:4: error: <spherecolor> 0: attribute \"i\" refers to sphere 0, but the scene "
            "has no spheres");
}

TEST(CollisionElements, ProbableMistakesAreWarnedAbout) {
  const Scene scene = load_with_collisions(
      "<halfplane px=\"0\" py=\"0\" nx=\"0\" ny=\"0\"/>\n"
      "<collision type=\"penalty\" COR=\"1.5\" k=\"-1\" thickness=\"-0.1\"/>\n"
      "<collision type=\"simple\"/>\n");
  EXPECT_EQ(scene.model.collisions.method->name, "penalty");  // the first one
  ASSERT_EQ(scene.warnings.size(), 5u);
  EXPECT_EQ(scene.warnings[0],
            "c.xml:4: warning: <halfplane> 0: the normal is zero, so this half-plane never "
            "collides and exerts no force (the course accepts it silently)");
  EXPECT_EQ(scene.warnings[1],
            "c.xml:5: warning: <collision>: COR = 1.5 is outside [0, 1]: collisions will add "
            "energy (the course accepts it)");
  EXPECT_NE(scene.warnings[2].find("k = -1 is negative"), std::string::npos);
  EXPECT_NE(scene.warnings[3].find("thickness = -0.1 is negative"), std::string::npos);
  EXPECT_EQ(scene.warnings[4],
            "c.xml:6: warning: <collision> 1: a second <collision> element is ignored, as the "
            "course ignores it (the first, at line 5, applies)");
}

TEST(CollisionElements, AttributesWithoutABlankBetweenThemAreSeparated) {
  // An official course scene has vx="0"vy="0", which XML forbids.
  const Scene scene = load_scene_text(
      "<scene>\n<duration time=\"1\"/><integrator type=\"explicit-euler\" dt=\"0.1\"/>\n"
      "<particle m=\"1\" px=\"0\" py=\"0\" vx=\"2\"vy=\"3\" fixed=\"0\"/>\n</scene>\n",
      "quirk.xml");
  EXPECT_EQ(scene.initial.v[0], 2.0);
  EXPECT_EQ(scene.initial.v[1], 3.0);
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_EQ(scene.warnings[0],
            "quirk.xml:3: warning: two attributes without a blank between them (such as "
            "vx=\"0\"vy=\"0\"), read as if separated, as the course reads them");
  // Only that pattern changes: text in comments and values is left alone.
  std::vector<std::string> warnings;
  EXPECT_EQ(separate_run_together_attributes("<!-- a=\"1\"b --><e t=\"x\"/>", "f", warnings),
            "<!-- a=\"1\"b --><e t=\"x\"/>");
  EXPECT_TRUE(warnings.empty());
}

}  // namespace
}  // namespace fosssim
