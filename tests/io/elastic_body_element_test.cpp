// <elasticbody> (io/elastic_body_element.h): what each shape adds to a scene, the rest state
// (zero elastic force to round-off, since rest shapes are the initial positions), where its
// forces sum, every refusal with its full message, and OBJ meshes with their file and line.

#include "io/elastic_body_element.h"

#include <gtest/gtest.h>

#include <string>

#include "core/force_evaluation.h"
#include "core/force_set.h"
#include "io/scene_error.h"
#include "io/scene_loader.h"
#include "mesh/elastic_shapes.h"
#include "support/scratch_folder.h"
#include "support/thrown.h"

namespace fosssim {
namespace {

/// A valid header (lines 1-2), so that the element under test is on line 3.
constexpr const char* kBodyHeader =
    "<scene>\n"
    "<duration time=\"0.01\"/><integrator type=\"implicit-euler\" dt=\"0.01\"/>\n";

Scene load_body(const std::string& element, const std::string& more = "",
                const std::string& name = "ok.xml") {
  return load_scene_text(std::string(kBodyHeader) + element + "\n" + more + "</scene>\n", name);
}

std::string body_error(const std::string& element) {
  try {
    load_body(element, "", "bad.xml");
  } catch (const SceneError& error) {
    return error.what();
  }
  return "(loaded without error)";
}

int count_forces(const Scene& scene, const std::string& prefix) {
  int count = 0;
  for (const auto& force : scene.model.forces) count += force->label().rfind(prefix, 0) == 0;
  return count;
}

double total_mass(const Scene& scene) { return scene.model.mass.sum() / scene.model.dim; }

/// The largest |∇U| component at the initial state over the body's forces, and |∇U|'s scale.
double rest_gradient(const Scene& scene) {
  const ForceSet forces(scene.model);
  return compute_gradient(forces, scene.initial.q, scene.initial.v).cwiseAbs().maxCoeff();
}

TEST(ElasticBodyElement, ASheetBecomesParticlesEdgesAndOneCstPerTriangle) {
  const Scene scene = load_body(
      R"(<elasticbody shape="sheet" nx="4" ny="2" width="2" height="1" youngsmodulus="1000" poissonratio="0.3" totalmass="2" fix="left" x="1" y="2"/>)");
  EXPECT_EQ(scene.model.num_particles(), 15);
  EXPECT_EQ(scene.model.edges.size(), 4u * 3 + 5u * 2 + 8u);
  EXPECT_EQ(count_forces(scene, "elasticbodycstforce"), 16);
  EXPECT_EQ(count_forces(scene, "elasticbodyspringforce"), 0);
  EXPECT_NEAR(total_mass(scene), 2.0, 1e-14);
  EXPECT_EQ(scene.grading_theme, 4);
  for (int p = 0; p < 15; ++p) EXPECT_EQ(scene.model.fixed[p], p % 5 == 0) << p;
  EXPECT_EQ(scene.initial.q.segment<2>(2 * 14), Eigen::Vector2d(3.0, 3.0));
}

TEST(ElasticBodyElement, ARodHasSpringsAndHingesAndEveryParticleTheGivenMass) {
  const Scene scene = load_body(
      R"(<elasticbody shape="rod" segments="5" length="1" stretch="100" bend="1" m="0.1" fix="left" vx="1"/>)");
  EXPECT_EQ(scene.model.num_particles(), 6);
  EXPECT_EQ(count_forces(scene, "elasticbodyspringforce"), 5);
  EXPECT_EQ(count_forces(scene, "elasticbodybendingforce"), 4);
  EXPECT_EQ(scene.model.mass, Vector::Constant(12, 0.1));
  EXPECT_EQ(scene.initial.v[0], 0.0);  // fixed particles start at rest
  EXPECT_EQ(scene.initial.v[2], 1.0);
}

TEST(ElasticBodyElement, EveryShapeStartsAtRestWithZeroElasticForce) {
  for (
      const char* element : {
          R"(<elasticbody shape="sheet" nx="6" ny="3" width="2" height="1" youngsmodulus="1e4" poissonratio="0.45" stretch="50" m="1" rotation="33" x="0.3"/>)",
          R"(<elasticbody shape="rod" segments="7" length="2" stretch="100" bend="3" m="1" rotation="-71"/>)",
          R"(<elasticbody shape="ring" segments="17" radius="1.5" stretch="100" bend="3" m="1" rotation="10"/>)",
          R"(<elasticbody shape="ring" segments="17" radius="1.5" innerradius="1" layers="2" youngsmodulus="1e4" poissonratio="0.3" m="1"/>)",
          R"(<elasticbody shape="polygon" points="0 0 4 0 4 1 2 0.5 1 3 0 1" spacing="0.3" youngsmodulus="1e4" poissonratio="0" totalmass="3" rotation="200"/>)",
          R"(<elasticbody shape="polygon" points="0 0 4 0 4 3 0 3" holes="1 1 2 1 1.5 2; 2.5,0.5, 3.5,0.5, 3.5,2.5" spacing="0.25" youngsmodulus="1e4" poissonratio="0.3" totalmass="3" rotation="30"/>)",
      }) {
    const Scene scene = load_body(element);
    SCOPED_TRACE(element);
    ASSERT_FALSE(scene.model.forces.empty());
    // Forces of E = 1e4 on unit sizes: round-off is about 1e4 · 1e-16.
    EXPECT_LE(rest_gradient(scene), 1e-10);
  }
}

TEST(ElasticBodyElement, RestIsTheInitialShapeSoAStretchedStartPullsBack) {
  // Gravity moves the rest state away: a check that the gradient above could be non-zero.
  const Scene scene = load_body(
      R"(<elasticbody shape="rod" segments="3" length="1" stretch="100" bend="1" m="1"/>)",
      "<simplegravity fx=\"0\" fy=\"-10\"/>\n");
  EXPECT_NEAR(rest_gradient(scene), 10.0, 1e-12);
}

TEST(ElasticBodyElement, ItsForcesSumRightAfterTheScenesOwnOfTheSameKind) {
  const Scene scene =
      load_body(R"(<elasticbody shape="rod" segments="2" stretch="1" bend="1" m="1"/>)",
                "<particle m=\"1\" px=\"5\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n"
                "<particle m=\"1\" px=\"6\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n"
                "<elasticbodyspringforce i1=\"0\" i2=\"1\" alpha=\"1\" l0=\"1\"/>\n"
                "<simplegravity fx=\"0\" fy=\"-1\"/>\n");
  std::vector<std::string> labels;
  for (const auto& force : scene.model.forces) labels.push_back(force->label());
  ASSERT_EQ(labels.size(), 5u);
  EXPECT_EQ(labels[0].rfind("simplegravity", 0), 0u) << labels[0];
  // The body's particles follow the scene's two: 2, 3, 4.
  EXPECT_EQ(labels[1], "elasticbodyspringforce(0, 1)");
  EXPECT_EQ(labels[2], "elasticbodyspringforce(2, 3)");
  EXPECT_EQ(labels[3], "elasticbodyspringforce(3, 4)");
  EXPECT_EQ(labels[4].rfind("elasticbodybendingforce", 0), 0u) << labels[4];
}

TEST(ElasticBodyElement, APolygonWithHolesIsTheMeshGeneratorsBody) {
  // Holes separated by ';', corners by blanks or commas; a hole of either orientation.
  const Scene scene = load_body(
      R"(<elasticbody shape="polygon" points="0 0 4 0 4 3 0 3" holes="1 1 2 1 1.5 2; 2.5,0.5, 3.5,0.5, 3.5,2.5" spacing="0.5" youngsmodulus="1e4" poissonratio="0.3" totalmass="6.2"/>)");
  const ElasticShape shape =
      make_polygon({{0, 0}, {4, 0}, {4, 3}, {0, 3}},
                   {{{1, 1}, {2, 1}, {1.5, 2}}, {{2.5, 0.5}, {3.5, 0.5}, {3.5, 2.5}}}, 0.5);
  ASSERT_EQ(scene.model.num_particles(), shape.num_vertices());
  for (int v = 0; v < shape.num_vertices(); ++v)
    EXPECT_EQ(scene.initial.q.segment<2>(2 * v), shape.vertices[v]) << v;
  EXPECT_EQ(count_forces(scene, "elasticbodycstforce"), static_cast<int>(shape.triangles.size()));
  EXPECT_EQ(scene.model.edges.size(), shape.edges.size());
  EXPECT_NEAR(total_mass(scene), 6.2, 1e-14);
}

TEST(ElasticBodyElement, HolesAreOnlyAPolygonsAndElsewhereAWarning) {
  const Scene scene = load_body(
      R"(<elasticbody shape="sheet" nx="1" ny="1" holes="0.2 0.2 0.4 0.2 0.4 0.4" youngsmodulus="1" poissonratio="0" m="1"/>)");
  EXPECT_EQ(scene.model.num_particles(), 4);
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_NE(scene.warnings[0].find("unknown attribute \"holes\" ignored"), std::string::npos)
      << scene.warnings[0];
}

struct Refusal {
  const char* name;
  const char* element;
  const char* message;
};

class RefusedElasticBody : public ::testing::TestWithParam<Refusal> {};

TEST_P(RefusedElasticBody, NamesFileLineElementAndProblem) {
  EXPECT_EQ(body_error(GetParam().element), GetParam().message);
}

const Refusal kRefusals[] = {
    {"UnknownShape", R"(<elasticbody shape="blob" m="1"/>)",
     "bad.xml:3: error: <elasticbody> 0: attribute \"shape\" names an unknown shape \"blob\" "
     "(expected sheet, rod, ring, polygon or obj)"},
    {"NoMass", R"(<elasticbody shape="rod" segments="2" stretch="1"/>)",
     "bad.xml:3: error: <elasticbody> 0: the mass is missing: give m (every particle's mass) or "
     "totalmass (the body's, shared by area or length)"},
    {"TwoMasses", R"(<elasticbody shape="rod" segments="2" stretch="1" m="1" totalmass="2"/>)",
     "bad.xml:3: error: <elasticbody> 0: give either m (every particle's mass) or totalmass (the "
     "body's), not both"},
    {"RodWithoutStretch", R"(<elasticbody shape="rod" segments="2" m="1"/>)",
     "bad.xml:3: error: <elasticbody> 0: a rod needs stretch (alpha of the springs along it)"},
    {"RodWithCst", R"(<elasticbody shape="rod" segments="2" stretch="1" youngsmodulus="1" m="1"/>)",
     "bad.xml:3: error: <elasticbody> 0: attribute \"youngsmodulus\" applies to bodies of "
     "triangles, not to a rod or a ring rod"},
    {"SheetWithBend",
     R"(<elasticbody shape="sheet" nx="1" ny="1" bend="1" youngsmodulus="1" poissonratio="0" m="1"/>)",
     "bad.xml:3: error: <elasticbody> 0: attribute \"bend\" applies to rods and ring rods (a ring "
     "without innerradius), not to a body of triangles"},
    {"SheetWithoutYoung", R"(<elasticbody shape="sheet" nx="1" ny="1" m="1"/>)",
     "bad.xml:3: error: <elasticbody> 0: attribute \"youngsmodulus\" is missing"},
    {"PoissonOne",
     R"(<elasticbody shape="sheet" nx="1" ny="1" youngsmodulus="1" poissonratio="1" m="1"/>)",
     "bad.xml:3: error: <elasticbody> 0: attribute \"poissonratio\" must lie strictly between -1 "
     "and 1 (the plane-stress energy divides by 1 - ν²), found 1"},
    {"NegativeStretch", R"(<elasticbody shape="rod" segments="2" stretch="-1" m="1"/>)",
     "bad.xml:3: error: <elasticbody> 0: attribute \"stretch\" must be non-negative, found -1"},
    {"ZeroCells",
     R"(<elasticbody shape="sheet" nx="0" ny="1" youngsmodulus="1" poissonratio="0" m="1"/>)",
     "bad.xml:3: error: <elasticbody> 0: attribute \"nx\" must be at least 1, found 0"},
    {"InnerRadiusTooLarge",
     R"(<elasticbody shape="ring" segments="8" radius="1" innerradius="1" youngsmodulus="1" poissonratio="0" m="1"/>)",
     "bad.xml:3: error: <elasticbody> 0: attribute \"innerradius\" must be less than radius (1), "
     "found 1"},
    {"OddPoints",
     R"(<elasticbody shape="polygon" points="0 0 1 0 1" youngsmodulus="1" poissonratio="0" m="1"/>)",
     "bad.xml:3: error: <elasticbody> 0: attribute \"points\" must hold x y pairs, found 5 "
     "numbers"},
    {"CrossingPolygon",
     R"(<elasticbody shape="polygon" points="0 0 1 0 0 1 1 1" youngsmodulus="1" poissonratio="0" m="1"/>)",
     "bad.xml:3: error: <elasticbody> 0: side 1 (corners 1–2) and side 3 (corners 3–0) cross or "
     "touch: the polygon is not simple"},
    {"HoleOutside",
     R"(<elasticbody shape="polygon" points="0 0 4 0 4 4 0 4" holes="1 1 2 1 2 2; 5 5 6 5 6 6" youngsmodulus="1" poissonratio="0" m="1"/>)",
     "bad.xml:3: error: <elasticbody> 0: hole 1 is outside the outline"},
    {"HoleCrossingTheOutline",
     R"(<elasticbody shape="polygon" points="0 0 4 0 4 4 0 4" holes="3 1 5 1 5 2 3 2" youngsmodulus="1" poissonratio="0" m="1"/>)",
     "bad.xml:3: error: <elasticbody> 0: hole 0 crosses or touches the outline: its side 0 "
     "(corners 0–1) and the outline's side 1 (corners 1–2)"},
    {"HolesTouching",
     R"(<elasticbody shape="polygon" points="0 0 4 0 4 4 0 4" holes="1 1 2 1 2 2 1 2; 2 2 3 2 3 3" youngsmodulus="1" poissonratio="0" m="1"/>)",
     "bad.xml:3: error: <elasticbody> 0: holes 0 and 1 cross or touch: side 1 (corners 1–2) of "
     "hole 0 and side 0 (corners 0–1) of hole 1"},
    {"HoleNotSimple",
     R"(<elasticbody shape="polygon" points="0 0 4 0 4 4 0 4" holes="1 1 2 1 1 2 2 2" youngsmodulus="1" poissonratio="0" m="1"/>)",
     "bad.xml:3: error: <elasticbody> 0: hole 0: side 1 (corners 1–2) and side 3 (corners 3–0) "
     "cross or touch: the polygon is not simple"},
    {"OddHole",
     R"(<elasticbody shape="polygon" points="0 0 4 0 4 4 0 4" holes="1 1 2 1 2 2; 3 3 3.5 3 3.5" youngsmodulus="1" poissonratio="0" m="1"/>)",
     "bad.xml:3: error: <elasticbody> 0: attribute \"holes\" (hole 1) must hold x y pairs, found "
     "5 numbers"},
    {"EmptyHole",
     R"(<elasticbody shape="polygon" points="0 0 4 0 4 4 0 4" holes="1 1 2 1 2 2;" youngsmodulus="1" poissonratio="0" m="1"/>)",
     "bad.xml:3: error: <elasticbody> 0: attribute \"holes\" (hole 1) is empty: holes are lists "
     "of x y pairs separated by ';'"},
    {"HoleNotANumber",
     R"(<elasticbody shape="polygon" points="0 0 4 0 4 4 0 4" holes="1 1 2 1 2 x" youngsmodulus="1" poissonratio="0" m="1"/>)",
     "bad.xml:3: error: <elasticbody> 0: attribute \"holes\" (hole 0) must be numbers, found "
     "\"x\""},
    {"FixedOutOfRange", R"(<elasticbody shape="rod" segments="2" stretch="1" m="1" fixed="0 3"/>)",
     "bad.xml:3: error: <elasticbody> 0: attribute \"fixed\" refers to vertex 3, but the body has "
     "3 vertices (0-based)"},
    {"BadSide", R"(<elasticbody shape="rod" segments="2" stretch="1" m="1" fix="middle"/>)",
     "bad.xml:3: error: <elasticbody> 0: attribute \"fix\" must be left, right, bottom, top or "
     "none, found \"middle\""},
    {"Misspelt", R"(<elasticbody shape="rod" segments="2" stretch="1" m="1" lenght="2"/>)",
     "bad.xml:3: error: <elasticbody> 0: unknown attribute \"lenght\" (did you mean "
     "\"length\"?)"},
};

INSTANTIATE_TEST_SUITE_P(Cases, RefusedElasticBody, ::testing::ValuesIn(kRefusals),
                         [](const auto& info) { return std::string(info.param.name); });

std::string load_error(const std::string& text, const std::string& name, InputFiles& files) {
  try {
    load_scene_text(text, name, files);
  } catch (const SceneError& error) {
    return error.what();
  }
  return "(loaded without error)";
}

TEST(ElasticBodyElement, IsRefusedInA3DSceneAndOverTheParticleLimit) {
  EXPECT_EQ(body_error("<particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>"),
            "(loaded without error)");
  const std::string three_d =
      "<scene dim=\"3\">\n<duration time=\"0.01\"/><integrator type=\"implicit-euler\" "
      "dt=\"0.01\"/>\n<elasticbody shape=\"rod\" segments=\"2\" stretch=\"1\" m=\"1\"/>\n"
      "</scene>\n";
  InputFiles files;
  EXPECT_EQ(load_error(three_d, "bad.xml", files),
            "bad.xml:3: error: <elasticbody> 0: an elastic body is planar: it belongs to 2D "
            "scenes");
  const std::string rigid =
      "<scene>\n<simtype type=\"rigid-body\"/>\n"
      "<elasticbody shape=\"rod\" segments=\"2\" stretch=\"1\" m=\"1\"/>\n</scene>\n";
  EXPECT_EQ(load_error(rigid, "bad.xml", files),
            "bad.xml:3: error: <elasticbody>: an elastic body is made of particles: a rigid-body "
            "scene cannot hold one");
  Limits limits;
  limits.max_particles = 10;
  InputFiles small(limits);
  EXPECT_EQ(load_error(std::string(kBodyHeader) +
                           "<particle m=\"1\" px=\"9\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n"
                           "<elasticbody shape=\"rod\" segments=\"9\" stretch=\"1\" m=\"1\"/>\n"
                           "</scene>\n",
                       "bad.xml", small),
            "bad.xml:4: error: <elasticbody> 0: its 10 vertices bring the scene to 11 particles, "
            "more than the limit of 10 particles (raise it with --max-particles N)");
  EXPECT_EQ(load_error(std::string(kBodyHeader) +
                           "<elasticbody shape=\"sheet\" nx=\"9\" ny=\"9\" youngsmodulus=\"1\" "
                           "poissonratio=\"0\" m=\"1\"/>\n</scene>\n",
                       "bad.xml", small),
            "bad.xml:3: error: <elasticbody> 0: a sheet of 9 × 9 cells has 100 vertices, more "
            "than the limit of 10 particles (raise it with --max-particles N)");
}

TEST(ElasticBodyElement, TheCornerLimitCountsTheOutlineAndTheHolesTogether) {
  Limits limits;
  limits.max_polygon_corners = 10;
  InputFiles files(limits);
  const auto scene = [](const std::string& holes) {
    return std::string(kBodyHeader) +
           "<elasticbody shape=\"polygon\" points=\"0 0 4 0 4 4 0 4\" holes=\"" + holes +
           "\" youngsmodulus=\"1\" poissonratio=\"0\" m=\"1\"/>\n</scene>\n";
  };
  EXPECT_EQ(load_error(scene("1 1 2 1 2 2; 3 3 3.5 3 3.5 3.5"), "ok.xml", files),
            "(loaded without error)");  // 4 + 3 + 3 corners
  EXPECT_EQ(load_error(scene("1 1 2 1 2 2; 3 3 3.5 3 3.5 3.5 3.2 3.5"), "bad.xml", files),
            "bad.xml:3: error: <elasticbody> 0: attribute \"holes\" brings the polygon to 11 "
            "corners, more than the limit of 10 corners (raise it with --max-polygon-corners N)");
}

class ElasticBodyObj : public ::testing::Test {
 protected:
  /// The message of loading a scene whose body reads `obj` from mesh.obj.
  std::string error_of(const std::string& obj) {
    folder_.write("mesh.obj", obj);
    const std::string scene = folder_.write(
        "scene.xml", std::string(kBodyHeader) +
                         "<elasticbody shape=\"obj\" file=\"mesh.obj\" youngsmodulus=\"10\" "
                         "poissonratio=\"0.2\" totalmass=\"1\"/>\n</scene>\n");
    try {
      load_scene_file(scene);
    } catch (const SceneError& error) {
      const std::string text = error.what();
      const std::string folder = folder_.path().string() + "/";
      std::string out;
      for (std::size_t at = 0;;) {  // the scratch folder's name varies: leave it out
        const std::size_t found = text.find(folder, at);
        out += text.substr(at, found - at);
        if (found == std::string::npos) break;
        at = found + folder.size();
      }
      return out;
    }
    return "(loaded without error)";
  }
  testing::ScratchFolder folder_;
};

TEST_F(ElasticBodyObj, ReadsPlanarTrianglesWithOrWithoutZ) {
  folder_.write("mesh.obj", "v 0 0\nv 1 0 0\nv 1 1\nv 0 1 0\nf 1 2 3\nf 1 4 3\n");
  const std::string path = folder_.write(
      "scene.xml", std::string(kBodyHeader) +
                       "<elasticbody shape=\"obj\" file=\"mesh.obj\" youngsmodulus=\"10\" "
                       "poissonratio=\"0.2\" totalmass=\"1\"/>\n</scene>\n");
  const Scene scene = load_scene_file(path);
  EXPECT_EQ(scene.model.num_particles(), 4);
  EXPECT_EQ(count_forces(scene, "elasticbodycstforce"), 2);  // the clockwise one turned
  EXPECT_NEAR(total_mass(scene), 1.0, 1e-15);
  EXPECT_LE(rest_gradient(scene), 1e-12);
}

TEST_F(ElasticBodyObj, RefusesBadFilesNamingTheFileAndLine) {
  const std::string context = " (the mesh of scene.xml:3)";
  EXPECT_EQ(error_of("v 0 0\nv 1 0 0.5\nv 1 1\nf 1 2 3\n"),
            "mesh.obj:2: error: vertex 2 has z = 0.5: an elastic body is planar (z must be 0 or "
            "absent)" +
                context);
  EXPECT_EQ(error_of("v 0 0\nv 1 0\nv 1 1\nv 0 1\nf 1 2 3 4\n"),
            "mesh.obj:5: error: a face of 4 corners: an elastic body's mesh holds triangles "
            "only" +
                context);
  EXPECT_EQ(error_of("v 0 0\nv 1 0\nv 1 1\nf 1 2 7\n"),
            "mesh.obj:4: error: vertex index 7 is past the last vertex (the file has 3)" + context);
  EXPECT_EQ(error_of("v 0 0\nv 1 0\nv 1 1\nf 1 2 3\nl 1 3\n"),
            "mesh.obj:5: error: a polyline or a face of 2 corners: an elastic body's mesh holds "
            "triangles only" +
                context);
  EXPECT_EQ(error_of("v 0 0\nv 1 0\nv 2 0\nf 1 2 3\n"),
            "mesh.obj:4: error: the triangle has zero area (its corners are collinear)" + context);
  EXPECT_EQ(error_of("v 0 0\nv 1 0\nv 1 1\nv 5 5\nf 1 2 3\n"),
            "mesh.obj:4: error: vertex 4 is on no triangle: it would have no mass and no force" +
                context);
  EXPECT_EQ(error_of("v 0 0\nv 1 0\nv 1 1\n"),
            "mesh.obj: error: the file has no faces: an elastic body needs triangles" + context);
}

TEST(ElasticBodyText, ReadsOneElementAsTheSceneReaderDoes) {
  InputFiles files;
  const ElasticBodyText read = read_elastic_body_text(
      R"(<elasticbody shape="ring" segments="8" radius="2" stretch="3" bend="1" totalmass="4"/>)",
      "command line", files);
  EXPECT_EQ(read.body.shape.num_vertices(), 8);
  EXPECT_EQ(read.body.shape.hinges.size(), 8u);
  EXPECT_EQ(*read.body.material.stretch, 3.0);
  EXPECT_NEAR(read.body.particles.masses[0], 0.5, 1e-15);
  EXPECT_EQ(thrown_by<SceneError>([&] {
              read_elastic_body_text(R"(<elasticbody shape="ring" segments="2"/>)", "command line",
                                     files);
            }).what(),
            std::string("command line:1: error: <elasticbody>: attribute \"segments\" must be at "
                        "least 3, found 2"));
}

}  // namespace
}  // namespace fosssim
