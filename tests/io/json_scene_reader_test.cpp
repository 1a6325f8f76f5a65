// The fast mass-springs JSON scenes, read from small files written here.

#include "io/json_scene_reader.h"

#include <gtest/gtest.h>

#include "core/force_evaluation.h"
#include "core/forces/spring_set_force.h"
#include "io/scene_loader.h"
#include "support/scratch_folder.h"
#include "support/thrown.h"

namespace fosssim {
namespace {

/// Two triangles making the unit square in the xy plane (area 1), plus a loose spring.
constexpr const char* kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n";

TEST(JsonScene, AppliesTheAssignmentsDefaults) {
  testing::ScratchFolder dir;
  dir.write("meshes/square.obj", kSquare);
  const auto scene = load_json_scene_file(
      dir.write("scene.json", R"({"obj": "meshes/square.obj", "k": 250, "b": [1, 4]})"));
  const SceneModel& model = scene.model;
  EXPECT_EQ(model.dim, 3);
  EXPECT_EQ(model.integrator.method->name, "local-global");
  EXPECT_EQ(model.integrator.dt, 1.0 / 30.0);
  EXPECT_EQ(model.integrator.options.integer("iterations"), 50);
  EXPECT_EQ(model.integrator.options.choice("start"), "current");
  EXPECT_EQ(model.integrator.options.choice("pins"), "penalty");
  EXPECT_EQ(model.integrator.options.number("penalty"), 1e10);
  EXPECT_EQ(model.duration, 10.0);
  EXPECT_EQ(model.fixed, (std::vector<bool>{true, false, false, true}));
  // Masses from mixed Voronoi areas: both triangles are right-angled and isosceles, at
  // corners 1 and 3 (1/2 of their area there, 1/4 at the others), so corners 0 and 2 get
  // 1/4 + 1/4 of 1/2 each and corners 1 and 3 get 1/2 of 1/2 (a third each would be 1/3, 1/6).
  EXPECT_DOUBLE_EQ(model.mass[0], 0.25);
  EXPECT_DOUBLE_EQ(model.mass[3], 0.25);
  EXPECT_DOUBLE_EQ(model.mass[6], 0.25);
  EXPECT_DOUBLE_EQ(model.mass[9], 0.25);
  // Springs: the 5 distinct edges of the two triangles, at rest; gravity -9.8 N on every vertex.
  EXPECT_EQ(model.edges.size(), 5u);
  ASSERT_EQ(model.forces.size(), 2u);
  const Vector force = compute_force(ForceSet(model), scene.initial.q, scene.initial.v);
  for (int p = 0; p < 4; ++p) EXPECT_EQ(force.segment<3>(3 * p), Eigen::Vector3d(0.0, -9.8, 0.0));
  const auto* springs = dynamic_cast<const SpringSetForce<3>*>(model.forces[0].get());
  ASSERT_NE(springs, nullptr);
  EXPECT_EQ(springs->springs()[0].k, 250.0);
  EXPECT_TRUE(scene.warnings.empty());
}

TEST(JsonScene, TakesUniformMassesAndOurOptionalKeys) {
  testing::ScratchFolder dir;
  dir.write("square.obj", kSquare);
  const auto scene = load_json_scene_file(dir.write("scene.json", R"({
    "obj": "square.obj", "k": 10, "m": 0.25, "h": 0.01, "iterations": 7, "duration": 2,
    "start": "inertial", "colour": "red"
  })"));
  EXPECT_EQ(scene.model.mass, Vector::Constant(12, 0.25));
  EXPECT_EQ(scene.model.integrator.dt, 0.01);
  EXPECT_EQ(scene.model.integrator.options.integer("iterations"), 7);
  EXPECT_EQ(scene.model.integrator.options.choice("start"), "inertial");
  EXPECT_EQ(scene.model.num_steps(), 200);
  EXPECT_EQ(scene.model.fixed, std::vector<bool>(4, false));
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_NE(scene.warnings[0].find("unknown key \"colour\""), std::string::npos);
}

TEST(JsonScene, IsChosenByTheSceneLoaderForJsonFiles) {
  testing::ScratchFolder dir;
  dir.write("square.obj", kSquare);
  const auto scene = load_scene_file(dir.write("s.json", R"({"obj": "square.obj", "k": 1})"));
  EXPECT_EQ(scene.model.integrator.method->name, "local-global");
}

struct BadJsonScene {
  const char* json;
  int line;
  const char* problem;
};

TEST(JsonScene, RejectsBadScenesNamingTheProblem) {
  testing::ScratchFolder dir;
  dir.write("square.obj", kSquare);
  dir.write("lines.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n");
  const BadJsonScene cases[] = {
      {R"({"k": 1})", 1, "the required key \"obj\""},
      {R"({"obj": "square.obj"})", 1, "the required key \"k\" is missing"},
      {R"({"obj": "square.obj", "k": "stiff"})", 1, "\"k\" must be a number, found \"stiff\""},
      {R"({"obj": "square.obj", "k": -1})", 1, "\"k\" must not be negative"},
      {R"({"obj": "square.obj", "k": 1, "b": [0]})", 1,
       "\"b\"[0] must be a vertex number from 1 to 4 (1-based), found 0"},
      {R"({"obj": "square.obj", "k": 1, "b": [1, 5]})", 1,
       "\"b\"[1] must be a vertex number from 1 to 4"},
      {R"({"obj": "square.obj", "k": 1, "b": 3})", 1, "\"b\" must be a list"},
      {R"({"obj": "square.obj", "k": 1, "m": 0})", 1, "\"m\" must be positive"},
      {R"({"obj": "square.obj", "k": 1, "iterations": 2.5})", 1,
       "\"iterations\" must be a whole number"},
      {R"({"obj": "square.obj", "k": 1, "start": "previous"})", 1,
       "\"start\" must be \"inertial\" or \"current\", found \"previous\""},
      {R"({"obj": "square.obj", "k": 1, "start": 1})", 1,
       "\"start\" must be \"inertial\" or \"current\", found \"1\""},
      {R"({"obj": "lines.obj", "k": 1})", 1, "masses from areas need faces"},
      {"{\n  \"obj\": \"square.obj\",\n  \"k\": 1,,\n}", 3, "not valid JSON"},
      {"[1, 2]", 1, "must hold a JSON object"},
      {R"({"obj": "square.obj\u0000.txt", "k": 1})", 1,
       "\"obj\" must be a file name, found one holding a NUL character"},
      {"  \n", 0, "the file is empty"},
      {"{\n  \"obj\": \"square.obj\",\n  \"k\": 1,\n  \"m\": -2\n}", 4, "\"m\" must be positive"},
      {"{\n  \"obj\": \"square.obj\",\n  \"k\": 1,\n  \"b\": [\n    1,\n    7]\n}", 6,
       "\"b\"[1] must be a vertex number"},
      {"\n\n{\"obj\": \"square.obj\"}", 3, "the required key \"k\" is missing"},
      {R"({"obj": "square.obj", "k": 1, "duraton": 2})", 1,
       "unknown key \"duraton\" (did you mean \"duration\"?)"},
  };
  for (const BadJsonScene& c : cases) {
    const std::string path = dir.write("bad.json", c.json);
    const SceneError scene_error = thrown_by<SceneError>([&] { load_json_scene_file(path); });
    EXPECT_EQ(scene_error.file(), path);
    EXPECT_EQ(scene_error.line(), c.line) << scene_error.what();
    EXPECT_NE(scene_error.problem().find(c.problem), std::string::npos) << scene_error.what();
  }
}

TEST(JsonScene, ReportsEveryProblemOfAFileWithItsLine) {
  testing::ScratchFolder dir;
  dir.write("square.obj", kSquare);
  const std::string path = dir.write("scene.json",
                                     "{\n"                          // 1
                                     "  \"obj\": \"square.obj\",\n"  // 2
                                     "  \"k\": -1,\n"                // 3
                                     "  \"itreations\": 5,\n"        // 4
                                     "  \"b\": [1,\n"                // 5
                                     "        9,\n"                 // 6
                                     "        0],\n"                // 7
                                     "  \"h\": \"fast\",\n"          // 8
                                     "  \"colour\": \"red\"\n"       // 9: only a warning
                                     "}\n");
  const SceneErrors errors = thrown_by<SceneErrors>([&] { load_json_scene_file(path); });
  EXPECT_EQ(errors.kind(), ErrorKind::kBadInput);  // the programs exit 2
  ASSERT_EQ(errors.total(), 5u) << errors.what();
  const std::pair<int, const char*> expected[] = {
      {3, "\"k\" must not be negative, found -1"},
      {4, "unknown key \"itreations\" (did you mean \"iterations\"?)"},
      {6, "\"b\"[1] must be a vertex number from 1 to 4 (1-based), found 9"},
      {7, "\"b\"[2] must be a vertex number from 1 to 4 (1-based), found 0"},
      {8, "\"h\" must be a number, found \"fast\""},
  };
  ASSERT_EQ(errors.errors().size(), 5u);
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_EQ(errors.errors()[k].file(), path);
    EXPECT_EQ(errors.errors()[k].line(), expected[k].first) << errors.what();
    EXPECT_EQ(errors.errors()[k].problem(), expected[k].second) << errors.what();
  }
  // One line per problem in the message, each "file:line: error: ...".
  const std::string what = errors.what();
  EXPECT_NE(what.find(path + ":4: error: unknown key \"itreations\""), std::string::npos) << what;
  EXPECT_NE(what.find(path + ":8: error: \"h\" must be a number"), std::string::npos) << what;
  EXPECT_EQ(what.find("colour"), std::string::npos) << what;
}

TEST(JsonScene, KeepsAtMostTheDocumentedNumberOfProblemsAndCountsTheRest) {
  testing::ScratchFolder dir;
  dir.write("square.obj", kSquare);
  std::string list = "[";
  for (int k = 0; k < 25; ++k) list += std::string(k == 0 ? "" : ",\n") + "0";
  const std::string path =
      dir.write("scene.json", R"({"obj": "square.obj", "k": 1, "b": )" + list + "]}");
  const SceneErrors errors = thrown_by<SceneErrors>([&] { load_json_scene_file(path); });
  EXPECT_EQ(errors.total(), 25u);
  ASSERT_EQ(errors.errors().size(), SceneErrorList::kMaxReported);
  EXPECT_EQ(errors.errors().back().line(), static_cast<int>(SceneErrorList::kMaxReported));
  EXPECT_NE(std::string(errors.what()).find("and 5 more errors"), std::string::npos)
      << errors.what();
}

TEST(JsonScene, ReportsTheSceneProblemsBesideABrokenMesh) {
  testing::ScratchFolder dir;
  dir.write("broken.obj", "v 0 0 0\nv 1 0 0\nf 1 7\n");
  const std::string path =
      dir.write("scene.json", "{\"obj\": \"broken.obj\",\n \"k\": 1,\n \"m\": 0}");
  const SceneErrors errors = thrown_by<SceneErrors>([&] { load_json_scene_file(path); });
  ASSERT_EQ(errors.total(), 2u) << errors.what();
  const std::string what = errors.what();
  EXPECT_NE(what.find((dir / "broken.obj") + ":3: error:"), std::string::npos) << what;
  EXPECT_NE(what.find(path + ":3: error: \"m\" must be positive"), std::string::npos) << what;
}

TEST(JsonScene, PassesOnTheMeshFilesErrorsWithTheirLines) {
  testing::ScratchFolder dir;
  dir.write("broken.obj", "v 0 0 0\nv 1 0 0\nf 1 7\n");
  const SceneError scene_error = thrown_by<SceneError>([&] {
    load_json_scene_file(dir.write("scene.json", R"({"obj": "broken.obj", "k": 1, "m": 1})"));
  });
  EXPECT_EQ(scene_error.file(), (dir / "broken.obj"));
  EXPECT_EQ(scene_error.line(), 3);
  EXPECT_NE(scene_error.problem().find("the \"obj\" of"), std::string::npos);
}

}  // namespace
}  // namespace fosssim
