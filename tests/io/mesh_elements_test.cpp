// The XML elements that bring meshes into scenes, and the new integrators' attributes.

#include "io/mesh_elements.h"

#include <gtest/gtest.h>

#include "core/force_evaluation.h"
#include "io/scene_loader.h"
#include "mesh/generators.h"
#include "support/scratch_folder.h"
#include "support/thrown.h"

namespace fosssim {
namespace {

constexpr const char* kTet =
    "MeshVersionFormatted 1\nDimension 3\nVertices 4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
    "Tetrahedra 1\n1 2 3 4 0\nEnd\n";

TEST(MeshElements, ReadMeshesInDocumentOrderAfterXmlParticlesWithSpringsAfterSpringforces) {
  testing::ScratchFolder dir;
  dir.write("meshes/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  dir.write("tet.mesh", kTet);
  const auto scene = load_scene_file(dir.write("scene.xml", R"(<scene dim="3">
  <duration time="1"/>
  <integrator type="local-global" dt="0.01" iterations="12" tolerance="1e-9" start="current" pins="penalty" penalty="1e8" solver="sparse"/>
  <simplegravity fx="0" fy="-9.8" fz="0"/>
  <tetmesh file="tet.mesh" k="100" mass="volume" density="600" tx="5"/>
  <particle m="1" px="0" py="0" pz="0" vx="0" vy="0" vz="0" fixed="1"/>
  <particle m="1" px="1" py="0" pz="0" vx="0" vy="0" vz="0" fixed="0"/>
  <edge i="0" j="1"/>
  <springforce edge="0" k="3" l0="1"/>
  <clothmesh file="meshes/tri.obj" k="7" b="0.1" m="0.5" scale="2">
    <pin vertices="0, 2"/>
  </clothmesh>
  <generate type="chain" links="3" length="1.5" k="9" mass="total" total="0.4" pin="ends">
    <pin axis="x" side="lowest" within="0.6"/>
  </generate>
</scene>)"));
  const SceneModel& model = scene.model;
  EXPECT_EQ(model.num_particles(), 2 + 4 + 3 + 4);
  // The tet mesh first (document order), shifted by tx.
  EXPECT_EQ(scene.initial.q.segment<3>(3 * 3), Eigen::Vector3d(6.0, 0.0, 0.0));
  EXPECT_DOUBLE_EQ(model.mass[3 * 2], 600.0 / 6.0 / 4.0);
  // The cloth mesh, scaled, with vertices 0 and 2 pinned.
  EXPECT_EQ(scene.initial.q.segment<3>(3 * 8), Eigen::Vector3d(0.0, 2.0, 0.0));
  EXPECT_TRUE(model.fixed[6] && !model.fixed[7] && model.fixed[8]);
  // The chain: the "ends" set plus the rule (x within 0.6 of the lowest: vertices 0 and 1).
  EXPECT_EQ(std::vector<bool>(model.fixed.begin() + 9, model.fixed.end()),
            (std::vector<bool>{true, true, false, true}));
  EXPECT_DOUBLE_EQ(model.mass[3 * 12], 0.1);
  // Edges: the <edge> first, then the meshes' springs.
  EXPECT_EQ(model.edges.size(), 1u + 6u + 3u + 3u);
  EXPECT_EQ(model.edges[0].j, 1);
  // Forces: springforce, then the three mesh spring sets in document order, then gravity.
  ASSERT_EQ(model.forces.size(), 5u);
  EXPECT_EQ(model.forces[0]->label(), "springforce(0, 1)");
  EXPECT_EQ(model.forces[1]->label(), "tetmesh 0 (6 springs)");
  EXPECT_EQ(model.forces[2]->label(), "clothmesh 0 (3 springs)");
  EXPECT_EQ(model.forces[3]->label(), "generate 0 (chain) (3 springs)");
  EXPECT_EQ(model.forces[4]->label(), "simplegravity");
  const OptionValues& lg = model.integrator.options;
  EXPECT_EQ(lg.integer("iterations"), 12);
  EXPECT_EQ(lg.number("tolerance"), 1e-9);
  EXPECT_EQ(lg.choice("start"), "current");
  EXPECT_EQ(lg.choice("pins"), "penalty");
  EXPECT_EQ(lg.number("penalty"), 1e8);
  EXPECT_EQ(lg.choice("solver"), "sparse");
  EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
  EXPECT_EQ(scene.appearance.triangles.size(), 4u + 1u);
}

TEST(MeshElements, GenerateEveryKindAndDefaultIntegratorOptions) {
  const auto scene = load_scene_text(R"(<scene dim="3">
  <duration time="1"/>
  <integrator type="fast-mass-springs" dt="0.01"/>
  <generate type="cloth" nx="4" ny="3" plane="xz" bend="0" k="1" m="0.1"/>
  <generate type="net" nx="3" ny="3" k="1" m="0.1" pin="border"/>
  <generate type="skirt" segments="6" rings="3" k="1" m="0.1"/>
  <generate type="tetbox" nx="2" ny="1" nz="1" k="1" mass="volume" density="1" pin="left"/>
  <generate type="tetball" cells="4" radius="0.5" k="1" m="0.1"/>
  <generate type="chain" links="2" k="1" m="0.1" vx="1" vy="2" vz="3"/>
</scene>)",
                                     "all.xml");
  const SceneModel& model = scene.model;
  EXPECT_EQ(model.integrator.method->name, "local-global");
  EXPECT_EQ(model.integrator.options.integer("iterations"), 10);
  EXPECT_EQ(model.integrator.options.choice("pins"), "elimination");
  EXPECT_EQ(model.integrator.options.choice("start"), "inertial");
  EXPECT_EQ(model.forces.size(), 6u);
  int pinned = 0;
  for (bool f : model.fixed) pinned += f;
  EXPECT_EQ(pinned, 2 + 8 + 6 + 4 + 0 + 1);
  EXPECT_EQ(scene.initial.v.tail<3>(), Eigen::Vector3d(1.0, 2.0, 3.0));
}

TEST(MeshElements, TheMassAttributeChoosesHowAreasBecomeMasses) {
  // A 3 × 3 cloth of 2 m × 1 m: rectangular cells, so its triangles are right but not
  // isosceles, and the corners and edges of the cloth lump differently under each rule.
  const Mesh cloth = generate_cloth(3, 3, 2.0, 1.0, false, false).mesh;
  const auto masses_of = [](const std::string& attributes) {
    const auto scene = load_scene_text(
        "<scene dim=\"3\">\n<duration time=\"1\"/>\n<integrator type=\"local-global\" "
        "dt=\"0.01\"/>\n<generate type=\"cloth\" nx=\"3\" ny=\"3\" width=\"2\" bend=\"0\" "
        "k=\"1\" " +
            attributes + "/>\n</scene>",
        "masses.xml");
    std::vector<double> masses;
    for (int p = 0; p < scene.model.num_particles(); ++p) masses.push_back(scene.model.mass[3 * p]);
    return masses;
  };
  const auto voronoi = masses_of(R"(mass="voronoi" density="2")");
  const auto barycentric = masses_of(R"(mass="barycentric" density="2")");
  EXPECT_EQ(voronoi, compute_vertex_masses(cloth, {MassRule::kVoronoi, 2.0}));
  EXPECT_EQ(barycentric, compute_vertex_masses(cloth, {MassRule::kArea, 2.0}));
  EXPECT_EQ(masses_of(R"(mass="area" density="2")"), barycentric) << "area is barycentric";
  EXPECT_NE(voronoi[0], barycentric[0]);
  EXPECT_EQ(masses_of(R"(m="0.5")"), std::vector<double>(9, 0.5)) << "uniform by default";
  EXPECT_EQ(masses_of(R"(mass="total" total="0.9")"), std::vector<double>(9, 0.1));
}

TEST(MeshElements, MeshesInA2DSceneMustLieInThePlane) {
  const char* text = R"(<scene>
  <duration time="1"/>
  <integrator type="local-global" dt="0.01"/>
  <generate type="chain" links="4" k="10" m="1"/>
  <generate type="cloth" nx="3" ny="3" k="10" m="1" PLANE/>
</scene>)";
  std::string flat = text;
  flat.replace(flat.find("PLANE"), 5, "plane=\"xy\"");
  const auto ok = load_scene_text(flat, "flat.xml");
  EXPECT_EQ(ok.model.dim, 2);
  EXPECT_EQ(ok.model.num_particles(), 5 + 9);
  std::string raised = text;
  raised.replace(raised.find("PLANE"), 5, "plane=\"xz\"");
  const SceneError bad_error =
      thrown_by<SceneError>([&] { load_scene_text(raised, "raised.xml"); });
  EXPECT_EQ(bad_error.line(), 5);
  EXPECT_NE(bad_error.problem().find("the scene is 2D"), std::string::npos) << bad_error.what();
}

struct BadMeshElement {
  const char* element;
  const char* problem;
};

TEST(MeshElements, RejectBadDeclarationsWithTheirLine) {
  const BadMeshElement cases[] = {
      {R"(<generate type="donut" k="1" m="1"/>)", "unknown generator \"donut\""},
      {R"(<generate type="cloth" nx="1" ny="4" k="1" m="1"/>)",
       "attribute \"nx\" must be at least 2, found 1"},
      {R"(<generate type="cloth" nx="3" ny="3" k="1" m="1" pin="middle"/>)",
       "(expected corners, top-row, left-column or none)"},
      {R"(<generate type="cloth" nx="3" ny="3" k="1" m="1" plane="yz"/>)", "attribute \"plane\""},
      {R"(<generate type="chain" links="3" m="1"/>)", "attribute \"k\" is missing"},
      {R"(<generate type="chain" links="3" k="1"/>)", "attribute \"m\" is missing"},
      {R"(<generate type="chain" links="3" k="1" mass="heavy"/>)", "attribute \"mass\" must be"},
      {R"(<generate type="chain" links="3" k="1" mass="area" density="1"/>)",
       "masses from areas need faces"},
      {R"(<generate type="chain" links="3" k="1" mass="voronoi" density="1"/>)",
       "masses from areas need faces"},
      {R"(<generate type="cloth" nx="3" ny="3" k="1" mass="voronoi"/>)",
       "attribute \"density\" is missing"},
      {R"(<generate type="chain" links="3" k="1" mass="lumped"/>)",
       "\"barycentric\" (or \"area\"), \"voronoi\" or \"volume\" (with density), found "
       "\"lumped\""},
      {R"(<generate type="chain" links="3" k="1" m="1"><pin vertices="0 9"/></generate>)",
       "refers to vertex 9, but the mesh has 4"},
      {R"(<generate type="chain" links="3" k="1" m="1"><pin axis="w" side="lowest" within="1"/></generate>)",
       "attribute \"axis\" must be x, y or z"},
      {R"(<generate type="chain" links="3" k="1" m="1"><fix i="0"/></generate>)",
       "only <pin> may appear"},
      {R"(<clothmesh file="absent.obj" k="1" m="1"/>)", "cannot open the file"},
  };
  for (const BadMeshElement& c : cases) {
    const std::string text = std::string(
                                 "<scene dim=\"3\">\n<duration time=\"1\"/>\n<integrator "
                                 "type=\"local-global\" dt=\"0.01\"/>\n") +
                             c.element + "\n</scene>";
    const SceneError scene_error = thrown_by<SceneError>([&] { load_scene_text(text, "bad.xml"); });
    EXPECT_NE(scene_error.problem().find(c.problem), std::string::npos) << scene_error.what();
    if (std::string(c.problem) != "cannot open the file") {
      EXPECT_EQ(scene_error.line(), 4) << scene_error.what();
    }
  }
}

TEST(MeshElements, AMalformedMeshFileIsReportedAtItsOwnLine) {
  testing::ScratchFolder dir;
  dir.write("broken.mesh", "MeshVersionFormatted 1\nDimension 3\nVertices 2\n0 0 0 0\n1 0 0\n");
  const SceneError scene_error = thrown_by<SceneError>([&] {
    load_scene_file(dir.write("s.xml", R"(<scene dim="3">
  <duration time="1"/>
  <integrator type="linearly-implicit-euler" dt="0.01"/>
  <tetmesh file="broken.mesh" k="1" m="1"/>
</scene>)"));
  });
  EXPECT_EQ(scene_error.file(), (dir / "broken.mesh"));
  EXPECT_EQ(scene_error.line(), 5);
  EXPECT_NE(scene_error.problem().find("(the mesh of " + (dir / "s.xml") + ":4)"),
            std::string::npos)
      << scene_error.what();
}

TEST(IntegratorOptions, AreValidatedAndWarnedAboutForOtherMethods) {
  const auto base = [](const std::string& integrator) {
    return "<scene dim=\"3\">\n<duration time=\"1\"/>\n" + integrator +
           "\n<generate type=\"chain\" links=\"2\" k=\"1\" m=\"1\"/>\n</scene>";
  };
  const std::pair<const char*, const char*> bad[] = {
      {R"(<integrator type="local-global" dt="0.01" iterations="0"/>)",
       "attribute \"iterations\" must be a whole number from 1 to 1000000, found 0"},
      {R"(<integrator type="local-global" dt="0.01" pins="glue"/>)",
       "must be \"elimination\" or \"penalty\""},
      {R"(<integrator type="local-global" dt="0.01" start="previous"/>)",
       "attribute \"start\" must be \"inertial\" or \"current\", found \"previous\""},
      {R"(<integrator type="local-global" dt="0.01" penalty="-1"/>)",
       "attribute \"penalty\" must be a positive number, found -1"},
      {R"(<integrator type="local-global" dt="0.01" solver="cg"/>)",
       "\"auto\", \"dense\" or \"sparse\", found \"cg\""},
      {R"(<integrator type="local-global" dt="0.01" tolerance="-1"/>)",
       "must be a non-negative number"},
      {R"(<integrator type="linearly-implicit-euler" dt="0.01" hessian="clamped"/>)",
       "\"exact\" or \"projected\""},
  };
  for (const auto& [element, problem] : bad) {
    const SceneError scene_error = thrown_by<SceneError>(
        [&, &element = element] { load_scene_text(base(element), "opts.xml"); });
    EXPECT_EQ(scene_error.line(), 3);
    EXPECT_NE(scene_error.problem().find(problem), std::string::npos) << scene_error.what();
  }
  const auto projected = load_scene_text(
      base(R"(<integrator type="linearly-implicit-euler" dt="0.01" hessian="projected"/>)"),
      "p.xml");
  EXPECT_EQ(projected.model.integrator.options.choice("hessian"), "projected");
  const auto other = load_scene_text(
      base(R"(<integrator type="implicit-euler" dt="0.01" iterations="5"/>)"), "o.xml");
  ASSERT_EQ(other.warnings.size(), 1u);
  EXPECT_NE(other.warnings[0].find("unknown attribute \"iterations\""), std::string::npos);
}

}  // namespace
}  // namespace fosssim
