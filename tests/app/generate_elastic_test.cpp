// FOSSSim-generate's elastic bodies (sheet, rod, ring, polygon with or without holes, obj), run as
// a user would: the XML scene it writes gives the same trajectory bytes as the <elasticbody>
// element with the same attributes, grades against itself with -i, and bad requests end with a
// message and status 2 without a file.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/run_program.h"
#include "support/scratch_folder.h"

namespace {

using fosssim::testing::ProgramResult;

const std::string kFosssimProgram = fosssim::testing::fosssim_program();
const std::string kGenerateProgram = fosssim::testing::fosssim_generate_program();

class GenerateElastic : public ::testing::Test {
 protected:
  ProgramResult run(const std::string& command) const {
    return fosssim::testing::run_command(folder_, command);
  }
  std::string path(const std::string& name) const { return folder_ / name; }

  /// The trajectory bytes of a run of `scene` (a file in the folder).
  std::string trajectory(const std::string& scene) {
    const std::string out = scene + ".bin";
    const ProgramResult r =
        run(kFosssimProgram + " -s " + path(scene) + " -d 0 -q -o " + path(out));
    EXPECT_EQ(r.status, 0) << scene << "\n" << r.output();
    return folder_.read(out);
  }

  fosssim::testing::ScratchFolder folder_;
};

struct Body {
  const char* name;
  const char* command;  ///< FOSSSim-generate's subcommand and options
  const char* element;  ///< the same body as an element
};

// Gravity and a fixed side make every body move; 0.3 s of implicit Euler steps.
const Body kBodies[] = {
    {"sheet",
     "sheet --nx 5 --ny 2 --width 2 --height 0.8 --youngsmodulus 2000 --poissonratio 0.3 "
     "--totalmass 2 --fix left --rotation 15 --x 0.5",
     R"(shape="sheet" nx="5" ny="2" width="2" height="0.8" youngsmodulus="2000" poissonratio="0.3" totalmass="2" fix="left" rotation="15" x="0.5")"},
    {"rod", "rod --segments 6 --length 1.5 --stretch 300 --bend 2 --m 0.1 --fixed 0,1",
     R"(shape="rod" segments="6" length="1.5" stretch="300" bend="2" m="0.1" fixed="0,1")"},
    {"ring", "ring --segments 14 --radius 0.7 --stretch 200 --bend 1 --totalmass 1 --vx 1 --y 2",
     R"(shape="ring" segments="14" radius="0.7" stretch="200" bend="1" totalmass="1" vx="1" y="2")"},
    {"annulus",
     "ring --segments 12 --radius 1 --innerradius 0.6 --layers 2 --youngsmodulus 500 "
     "--poissonratio 0.2 --m 0.05 --fix top --particleradius 0.03 --edgeradius 0.01",
     R"(shape="ring" segments="12" radius="1" innerradius="0.6" layers="2" youngsmodulus="500" poissonratio="0.2" m="0.05" fix="top" particleradius="0.03" edgeradius="0.01")"},
    {"polygon",
     "polygon --points '0 0 3 0 3 1 1.5 0.4 0.8 2 0 1' --spacing 0.35 --youngsmodulus 800 "
     "--poissonratio 0.4 --stretch 20 --totalmass 1.5 --fix bottom",
     R"(shape="polygon" points="0 0 3 0 3 1 1.5 0.4 0.8 2 0 1" spacing="0.35" youngsmodulus="800" poissonratio="0.4" stretch="20" totalmass="1.5" fix="bottom")"},
    {"polygon_with_holes",
     "polygon --points '0 0 3 0 3 2 0 2' --holes '0.5 0.5 1.2 0.5 1.2 1.5 0.5 1.5; 2 0.6 2.5 1 "
     "2 1.4 1.6 1' --spacing 0.3 --youngsmodulus 800 --poissonratio 0.3 --totalmass 1.5 --fix "
     "left",
     R"(shape="polygon" points="0 0 3 0 3 2 0 2" holes="0.5 0.5 1.2 0.5 1.2 1.5 0.5 1.5; 2 0.6 2.5 1 2 1.4 1.6 1" spacing="0.3" youngsmodulus="800" poissonratio="0.3" totalmass="1.5" fix="left")"},
    {"obj", "obj --file square.obj --youngsmodulus 100 --poissonratio 0 --totalmass 1 --fixed 0",
     R"(shape="obj" file="square.obj" youngsmodulus="100" poissonratio="0" totalmass="1" fixed="0")"},
};

constexpr const char* kSquare =
    "v 0 0\nv 1 0\nv 1 1\nv 0 1 0\nv 0.5 0.5\n"
    "f 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n";

class GenerateElasticBody : public GenerateElastic, public ::testing::WithParamInterface<Body> {};

TEST_P(GenerateElasticBody, WritesASceneWithTheElementsTrajectoryBytesThatGradesItself) {
  folder_.write("square.obj", kSquare);
  const ProgramResult made = run(kGenerateProgram + " -o " + path("generated.xml") + " " +
                                 GetParam().command + " --gravity -9.81 --duration 0.3 --dt 0.01");
  ASSERT_EQ(made.status, 0) << made.output();
  EXPECT_NE(made.out.find("wrote " + path("generated.xml") + ": "), std::string::npos);
  folder_.write("element.xml",
                std::string("<scene>\n<duration time=\"0.3\"/>\n"
                            "<integrator type=\"implicit-euler\" dt=\"0.01\"/>\n"
                            "<simplegravity fx=\"0\" fy=\"-9.81\"/>\n<elasticbody ") +
                    GetParam().element + "/>\n</scene>\n");
  const std::string generated = trajectory("generated.xml");
  const std::string element = trajectory("element.xml");
  ASSERT_FALSE(generated.empty());
  EXPECT_TRUE(generated == element) << "the two scenes' trajectories differ";
  // The generated scene is plain course format, and its trajectory grades against it.
  const std::string text = folder_.read("generated.xml");
  const std::string after_comment = text.substr(text.find("-->"));
  EXPECT_EQ(after_comment.find("<elasticbody "), std::string::npos);  // no element to expand
  EXPECT_NE(text.find("<particle m="), std::string::npos);
  const ProgramResult grade = run(kFosssimProgram + " -s " + path("generated.xml") +
                                  " -d 0 -q -i " + path("element.xml.bin"));
  EXPECT_EQ(grade.status, 0) << grade.output();
  EXPECT_NE(grade.output().find("Overall success: Passed."), std::string::npos) << grade.output();
}

INSTANTIATE_TEST_SUITE_P(Shapes, GenerateElasticBody, ::testing::ValuesIn(kBodies),
                         [](const auto& info) { return std::string(info.param.name); });

TEST_F(GenerateElastic, TheSceneIsOneElementPerForceWithRestValuesFromThePositions) {
  const ProgramResult made = run(kGenerateProgram + " -o " + path("rod.xml") +
                                 " rod --segments 2 --length 2 --stretch 5 "
                                 "--bend 0.5 --m 1 --duration 1");
  ASSERT_EQ(made.status, 0) << made.output();
  EXPECT_EQ(folder_.read("rod.xml"),
            "<!-- Written by FOSSSim-generate rod from <elasticbody shape=\"rod\" segments=\"2\" "
            "length=\"2\" m=\"1\" stretch=\"5\" bend=\"0.5\"/> -->\n"
            "<scene>\n"
            "  <duration time=\"1\"/>\n"
            "  <integrator type=\"implicit-euler\" dt=\"0.01\"/>\n"
            "  <particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n"
            "  <particle m=\"1\" px=\"1\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n"
            "  <particle m=\"1\" px=\"2\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n"
            "  <edge i=\"0\" j=\"1\"/>\n"
            "  <edge i=\"1\" j=\"2\"/>\n"
            "  <elasticbodyspringforce i1=\"0\" i2=\"1\" alpha=\"5\" l0=\"1\"/>\n"
            "  <elasticbodyspringforce i1=\"1\" i2=\"2\" alpha=\"5\" l0=\"1\"/>\n"
            "  <elasticbodybendingforce i1=\"0\" i2=\"1\" i3=\"2\" alpha=\"0.5\" theta0=\"0\"/>\n"
            "</scene>\n");
}

TEST_F(GenerateElastic, HelpSaysAnElasticBodyIsWrittenAsXml) {
  const ProgramResult r = run(kGenerateProgram + " --help");
  EXPECT_EQ(r.status, 0) << r.output();
  EXPECT_NE(r.out.find("-o,--output TEXT REQUIRED   File to write: .obj or .mesh for a mesh, "
                       ".xml for an elastic body"),
            std::string::npos)
      << r.out;
}

TEST_F(GenerateElastic, RefusesBadRequestsWithAMessageAndNoFile) {
  const auto refused = [this](const std::string& arguments, const std::string& message) {
    const ProgramResult r = run(kGenerateProgram + " " + arguments);
    EXPECT_EQ(r.status, 2) << arguments << "\n" << r.output();
    EXPECT_NE(r.err.find(message), std::string::npos) << arguments << "\n" << r.err;
    EXPECT_FALSE(folder_.exists("x.xml")) << arguments;
  };
  refused("-o " + path("x.xml") + " rod --segments 0 --stretch 1 --m 1",
          "FOSSSim-generate: command line:1: error: <elasticbody>: attribute \"segments\" must "
          "be at least 1, found 0");
  refused("-o " + path("x.xml") +
              " polygon --points '0 0 4 0 4 4 0 4' --holes '1 1 2 1 2 2; 2 2 3 2 3 3' "
              "--youngsmodulus 1 --poissonratio 0 --m 1",
          "FOSSSim-generate: command line:1: error: <elasticbody>: holes 0 and 1 cross or touch: "
          "side 1 (corners 1–2) of hole 0 and side 0 (corners 0–1) of hole 1");
  refused("-o " + path("x.obj") + " rod --segments 3 --stretch 1 --m 1",
          "FOSSSim-generate: error: an elastic body is written as an XML scene, but the output "
          "is " +
              path("x.obj"));
  refused("-o " + path("x.xml") +
              " --max-particles 1000 sheet --nx 2000 --ny 2000 "
              "--youngsmodulus 1 --poissonratio 0 --m 1",
          "a sheet of 2000 × 2000 cells has 4004001 vertices, more than the limit of 1000 "
          "particles (raise it with --max-particles N)");
  refused("-o " + path("x.xml") +
              " obj --file missing.obj --youngsmodulus 1 --poissonratio 0 "
              "--m 1",
          "missing.obj");
  refused("-o " + path("x.xml") + " --json " + path("x.json") +
              " rod --segments 3 --stretch 1 "
              "--m 1",
          "FOSSSim-generate: error: --json and --pins apply to meshes, not to elastic bodies");
}

TEST_F(GenerateElastic, FOSSSimRefusesAPolygonOverTheCornerLimitUntilItIsRaised) {
  std::string points;
  for (int k = 0; k < 12; ++k) {
    const double a = 6.283185307179586 * k / 12;
    points += (k ? " " : "") + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a));
  }
  folder_.write("polygon.xml",
                "<scene>\n<duration time=\"0.05\"/>\n"
                "<integrator type=\"implicit-euler\" dt=\"0.01\"/>\n"
                "<elasticbody shape=\"polygon\" points=\"" +
                    points +
                    "\" youngsmodulus=\"10\" poissonratio=\"0.3\" m=\"1\"/>\n"
                    "</scene>\n");
  const std::string run_it = kFosssimProgram + " -s " + path("polygon.xml") + " -d 0 -q -o " +
                             path("p.bin") + " --max-polygon-corners ";
  const ProgramResult refused = run(run_it + "11");
  EXPECT_EQ(refused.status, 2) << refused.output();
  EXPECT_NE(refused.err.find("polygon.xml:4: error: <elasticbody> 0: attribute \"points\" holds "
                             "12 corners, more than the limit of 11 corners (raise it with "
                             "--max-polygon-corners N)"),
            std::string::npos)
      << refused.err;
  EXPECT_FALSE(folder_.exists("p.bin"));
  const ProgramResult accepted = run(run_it + "12");
  EXPECT_EQ(accepted.status, 0) << accepted.output();
}

}  // namespace
