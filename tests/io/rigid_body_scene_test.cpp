// Rigid-body scenes (docs/scene-format.md, 'Rigid bodies'; docs/rigid-bodies.md): every element
// and the course's parsing quirks, the errors FOSSSim adds, the worked examples of the course's
// program run end to end (bit for bit where the course's arithmetic is followed), and the Theme 3
// trajectory layout.

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

#include "core/force_set.h"
#include "core/rigid/rigid_bodies.h"
#include "core/step/simulation.h"
#include "io/rigid_body_elements.h"
#include "io/rigid_trajectory.h"
#include "io/scene_loader.h"
#include "support/scratch_folder.h"
#include "support/thrown.h"

namespace fosssim::testing {
namespace {

Scene load_rigid(const std::string& xml) { return load_scene_text(xml, "rigid.xml"); }

/// Worked example A of the course's program: explicit Euler, gravity and a spring to a world
/// point, one step of h = 0.1.
constexpr const char* kExampleA = R"(<scene>
  <simtype type="rigid-body"/>
  <duration time="0.1"/>
  <rigidbodyintegrator type="explicit-euler" dt="0.1"/>
  <rigidbodyvertex x="0" y="1" m="1"/>
  <rigidbodyvertex x="1" y="0" m="2"/>
  <rigidbodyvertex x="-1" y="0" m="1"/>
  <rigidbody p="0" p="1" p="2" vx="0.5" vy="0" omega="1" r="0.1"/>
  <rigidbodygravityforce fx="0" fy="-9.81"/>
  <rigidbodyspringforce i="0" pix="0.5" piy="0.5" j="-1" pjx="2" pjy="3" k="10" l0="1"/>
</scene>)";

/// Worked example B: symplectic Euler, a body–body spring with l0 = 0, wind on a square and on
/// a two-vertex stick.
constexpr const char* kExampleB = R"(<scene>
  <simtype type="rigid-body"/>
  <duration time="0.1"/>
  <rigidbodyintegrator type="symplectic-euler" dt="0.1"/>
  <rigidbodyvertex x="-1" y="1" m="1"/>
  <rigidbodyvertex x="1" y="1" m="1"/>
  <rigidbodyvertex x="1" y="-1" m="1"/>
  <rigidbodyvertex x="-1" y="-1" m="1"/>
  <rigidbodyvertex x="3" y="0" m="1"/>
  <rigidbodyvertex x="4" y="0" m="3"/>
  <rigidbody p="0" p="1" p="2" p="3" vx="0" vy="0" omega="0.5" r="0.1"/>
  <rigidbody p="4" p="5" vx="0" vy="1" omega="0" r="0.1"/>
  <rigidbodyspringforce i="0" pix="1" piy="0" j="1" pjx="0" pjy="0" k="5" l0="0"/>
  <rigidbodywindforce beta="2" fx="1" fy="0.5" pointsperedge="2"/>
</scene>)";

TEST(RigidBodyScene, ReadsBodiesAndMassProperties) {
  const Scene scene = load_rigid(kExampleA);
  const SceneModel& model = scene.model;
  ASSERT_TRUE(model.rigid_bodies);
  EXPECT_EQ(model.dim, 3);
  EXPECT_EQ(model.num_particles(), 1);
  const RigidBody& body = model.rigid_bodies->bodies[0];
  EXPECT_EQ(body.hull, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(body.mass, 4.0);
  EXPECT_EQ(body.initial_center, Vec2(0.25, 0.25));
  EXPECT_EQ(body.inertia, 3.5);
  EXPECT_EQ(body.radius, 0.1);
  EXPECT_EQ(scene.initial.q, (Vector(3) << 0.25, 0.25, 0.0).finished());
  EXPECT_EQ(scene.initial.v, (Vector(3) << 0.5, 0.0, 1.0).finished());
  EXPECT_EQ(model.forces.size(), 2u);
  EXPECT_EQ(model.num_steps(), 1);
  EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
}

TEST(RigidBodyScene, WorkedExampleAExplicitEulerBitForBit) {
  const Scene scene = load_rigid(kExampleA);
  const ForceSet forces(scene.model);
  const Vector q0 = rigid_quantities_block(forces, scene.initial.q, scene.initial.v);
  // P (2, 0), L_cm −0.5, L_spin 3.5, T_cm 0.5, T_spin 1.75, U.
  EXPECT_EQ(q0, (Vector(7) << 2, 0, -0.5, 3.5, 0.5, 1.75, 22.1959246475325).finished());
  Simulation simulation(scene.model, scene.initial);
  simulation.step();
  const State& s = simulation.state();
  EXPECT_EQ(s.q, (Vector(3) << 0.3, 0.25, 0.1).finished());
  EXPECT_EQ(s.v,
            (Vector(3) << 0.691089267205342, -0.6370393190303845, 1.0873550935795848).finished());
  const Vector q1 = rigid_quantities_block(forces, s.q, s.v);
  EXPECT_EQ(q1, (Vector(7) << 2.764357068821368, -2.548157276121538, -1.4555364500418033,
                 3.805742827528547, 1.7668469384742251, 2.0690969241835684, 21.57199771738921)
                    .finished());
}

TEST(RigidBodyScene, WorkedExampleBSymplecticEulerSpringAndWindBitForBit) {
  const Scene scene = load_rigid(kExampleB);
  const auto& bodies = scene.model.rigid_bodies->bodies;
  EXPECT_EQ(bodies[0].mass, 4.0);
  EXPECT_EQ(bodies[1].mass, 4.0);
  EXPECT_EQ(bodies[0].initial_center, Vec2(0, 0));
  EXPECT_EQ(bodies[1].initial_center, Vec2(3.75, 0));
  EXPECT_EQ(bodies[0].inertia, 8.0);
  EXPECT_EQ(bodies[1].inertia, 0.75);
  const ForceSet forces(scene.model);
  EXPECT_EQ(rigid_quantities_block(forces, scene.initial.q, scene.initial.v)[12], 18.90625);
  Simulation simulation(scene.model, scene.initial);
  simulation.step();
  const State& s = simulation.state();
  const Vector expected_q = (Vector(6) << 0.05437500000000001, 0.010000000000000002, 0.0475,
                             3.715625, 0.095, 0.006666666666666667)
                                .finished();
  const Vector expected_v =
      (Vector(6) << 0.5437500000000001, 0.1, 0.475, -0.34375, 0.95, 0.06666666666666667).finished();
  // The spec asks for 1e-12 here; FOSSSim follows the course's order of operations and
  // matches its digits bit for bit (as printed, shortest round trip).
  EXPECT_EQ(s.q, expected_q);
  EXPECT_EQ(s.v, expected_v);
  EXPECT_EQ(rigid_quantities_block(forces, s.q, s.v)[12], 17.72415935235102);
}

TEST(RigidBodyScene, RepeatedHullAttributesAreNumberedKeepingLines) {
  const std::string text =
      "<scene>\n<rigidbody p=\"0\" p = '1'\n p=\"2\" vx=\"1\"/>\n"
      "<rigidbodyvertex x=\"1\" y=\"2\" m=\"1\"/></scene>";
  const std::string out = number_repeated_hull_attributes(text);
  EXPECT_EQ(out,
            "<scene>\n<rigidbody p=\"0\" p.2 = '1'\n p.3=\"2\" vx=\"1\"/>\n"
            "<rigidbodyvertex x=\"1\" y=\"2\" m=\"1\"/></scene>");
  // Values holding "p=" are values, not attributes.
  EXPECT_EQ(number_repeated_hull_attributes("<rigidbody p=\"0\" q=\"p=1\" p=\"1\"/>"),
            "<rigidbody p=\"0\" q=\"p=1\" p.2=\"1\"/>");
}

/// A one-body scene with `body` as its <rigidbody> element and `extra` elements.
std::string scene_with_bodies(const std::string& body, const std::string& extra = "") {
  return R"(<scene>
  <simtype type="rigid-body"/>
  <duration time="1"/>
  <rigidbodyintegrator type="symplectic-euler" dt="0.01"/>
  <rigidbodyvertex x="-1" y="1" m="1"/>
  <rigidbodyvertex x="1" y="1" m="1"/>
  <rigidbodyvertex x="1" y="-1" m="1"/>
  )" + body +
         "\n" + extra + "\n</scene>";
}

TEST(RigidBodyScene, AcceptsTheCoursesNumberQuirksWithWarnings) {
  const Scene scene = load_rigid(scene_with_bodies(
      R"(<rigidbody p="0" p="1.7" p="2" vx="-1abc" vy="1.5e0xyz" omega="0"r="0.2" fixed="0.5"/>)",
      R"(<rigidbodywindforce beta="1" fx="0" fy="0" pointsperedge="2.5"/>)"));
  const RigidBody& body = scene.model.rigid_bodies->bodies[0];
  EXPECT_EQ(body.hull, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(scene.initial.v[0], -1.0);
  EXPECT_EQ(scene.initial.v[1], 1.5);
  EXPECT_EQ(body.radius, 0.2);
  EXPECT_FALSE(body.fixed);
  std::string all;
  for (const auto& w : scene.warnings) all += w + "\n";
  EXPECT_NE(all.find("\"-1abc\""), std::string::npos) << all;
  EXPECT_NE(all.find("\"1.5e0xyz\""), std::string::npos) << all;
  EXPECT_NE(all.find("\"1.7\""), std::string::npos) << all;
  EXPECT_NE(all.find("\"0.5\""), std::string::npos) << all;
  EXPECT_NE(all.find("pointsperedge"), std::string::npos) << all;
  EXPECT_NE(all.find("rigid.xml:"), std::string::npos) << all;
}

TEST(RigidBodyScene, WarnsAboutCounterClockwiseHullsAndNonPositiveMasses) {
  const Scene scene = load_rigid(R"(<scene>
  <simtype type="rigid-body"/>
  <duration time="1"/>
  <rigidbodyintegrator type="explicit-euler" dt="0.01"/>
  <rigidbodyvertex x="0" y="0" m="1"/>
  <rigidbodyvertex x="1" y="0" m="0"/>
  <rigidbodyvertex x="0" y="1" m="1"/>
  <rigidbody p="0" p="1" p="2" vx="0" vy="0" omega="0" r="0.1"/>
</scene>)");
  std::string all;
  for (const auto& w : scene.warnings) all += w + "\n";
  EXPECT_NE(all.find("counter-clockwise"), std::string::npos) << all;
  EXPECT_NE(all.find("rigid.xml:6: warning: <rigidbodyvertex> 1: mass 0"), std::string::npos)
      << all;
}

struct BadScene {
  std::string xml;
  int line;
  std::string element;
  std::string problem;
};

TEST(RigidBodyScene, RefusesBadInputNamingFileLineAndElement) {
  const std::vector<BadScene> cases = {
      {scene_with_bodies(R"(<rigidbody p="0" vx="0" vy="0" omega="0" r="0.1"/>)"), 8,
       "<rigidbody> 0", "at least 2 hull vertices"},
      {scene_with_bodies(R"(<rigidbody p="0" p="3" vx="0" vy="0" omega="0" r="0.1"/>)"), 8,
       "<rigidbody> 0", "refers to vertex 3"},
      {scene_with_bodies(R"(<rigidbody p="0" p="-1" vx="0" vy="0" omega="0" r="0.1"/>)"), 8,
       "<rigidbody> 0", "refers to vertex -1"},
      {scene_with_bodies(R"(<rigidbody p="0" p="1" vx="0" vy="0" omega="0" r="0"/>)"), 8,
       "<rigidbody> 0", "\"r\" must be positive"},
      {scene_with_bodies(R"(<rigidbody p="0" p="1" vx="0" vy="0" omega="0" r="0.1" fixed="2"/>)"),
       8, "<rigidbody> 0", "\"fixed\" must be 0 or 1"},
      {scene_with_bodies(R"(<rigidbody p="0" p="1" vx="abc" vy="0" omega="0" r="0.1"/>)"), 8,
       "<rigidbody> 0", "\"vx\" must be a number"},
      {scene_with_bodies(
           R"(<rigidbody p="0" p="1" vx="0" vy="0" omega="0" r="0.1"/>)",
           R"(<rigidbodyspringforce i="0" pix="0" piy="0" j="1" pjx="0" pjy="0" k="1" l0="0"/>)"),
       9, "<rigidbodyspringforce> 0", "refers to body 1"},
      {scene_with_bodies(
           R"(<rigidbody p="0" p="1" vx="0" vy="0" omega="0" r="0.1"/>)",
           R"(<rigidbodyspringforce i="-2" pix="0" piy="0" j="0" pjx="0" pjy="0" k="1" l0="0"/>)"),
       9, "<rigidbodyspringforce> 0", "refers to body -2"},
      {scene_with_bodies(R"(<rigidbody p="0" p="1" vx="0" vy="0" omega="0" r="0.1"/>)",
                         R"(<rigidbodywindforce beta="-1" fx="0" fy="0" pointsperedge="2"/>)"),
       9, "<rigidbodywindforce> 0", "\"beta\" must be non-negative"},
      {scene_with_bodies(R"(<rigidbody p="0" p="1" vx="0" vy="0" omega="0" r="0.1"/>)",
                         R"(<rigidbodywindforce beta="1" fx="0" fy="0" pointsperedge="1"/>)"),
       9, "<rigidbodywindforce> 0", "at least 2"},
      {scene_with_bodies(R"(<rigidbody p="0" p="1" vx="0" vy="0" omega="0" r="0.1"/>)",
                         R"(<rigidbodycolor body="1" r="0" g="0" b="0"/>)"),
       9, "<rigidbodycolor> 0", "refers to body 1"},
  };
  for (const BadScene& c : cases) {
    const SceneError error = thrown_by<SceneError>([&] { load_rigid(c.xml); });
    EXPECT_EQ(error.line(), c.line) << error.what();
    EXPECT_NE(std::string(error.what()).find(c.element), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find(c.problem), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("rigid.xml"), std::string::npos) << error.what();
  }
}

TEST(RigidBodyScene, RefusesOtherIntegratorsAndSimtypes) {
  std::string xml =
      scene_with_bodies(R"(<rigidbody p="0" p="1" vx="0" vy="0" omega="0" r="0.1"/>)");
  const std::string forward = xml;
  std::string aliased = xml;
  aliased.replace(aliased.find("symplectic-euler"), 16, "forward-backward-euler");
  EXPECT_NE(std::string(thrown_by<SceneError>([&] { load_rigid(aliased); }).what())
                .find("explicit-euler or symplectic-euler"),
            std::string::npos);
  std::string other = xml;
  other.replace(other.find("rigid-body"), 10, "soft-body");
  EXPECT_NE(
      std::string(thrown_by<SceneError>([&] { load_rigid(other); }).what()).find("\"soft-body\""),
      std::string::npos);
  std::string without = xml;
  without.erase(without.find("<simtype"), std::strlen("<simtype type=\"rigid-body\"/>"));
  EXPECT_NE(std::string(thrown_by<SceneError>([&] { load_rigid(without); }).what())
                .find("<simtype type=\"rigid-body\"/>"),
            std::string::npos);
}

TEST(RigidTrajectory, LayoutSizeAndRoundTrip) {
  const Scene scene = load_rigid(kExampleB);
  ScratchFolder folder;
  const std::string path = folder / "b.bin";
  {
    RigidTrajectoryWriter writer(TrajectoryWriter::open(path), scene.model);
    Simulation simulation(scene.model, scene.initial);
    writer.write(simulation.state());
    while (!simulation.finished()) {
      simulation.step();
      writer.write(simulation.state());
    }
    writer.commit();
  }
  // B = 2, K = 1: 8 (4·2 + 2 (12·2 + 1)) = 464 bytes.
  EXPECT_EQ(rigid_trajectory_bytes(2, 1), 464);
  EXPECT_EQ(std::filesystem::file_size(path), 464u);
  RigidTrajectoryReader reader = RigidTrajectoryReader::open(path, 2, 1);
  const RigidFrame first = reader.read_frame(0);
  EXPECT_EQ(first.start, (Vector(8) << 4, 4, 0, 0, 3.75, 0, 8, 0.75).finished());
  EXPECT_EQ(first.state.segment<6>(0), (Vector(6) << 0, 0, 0, 0, 0, 0.5).finished());
  const RigidFrame second = reader.read_frame(1);
  EXPECT_NEAR(second.state[6], 3.715625, 1e-12);
  EXPECT_NEAR(second.quantities[12], 17.72415935235102, 1e-12);
  // A file a few bytes short is refused with its size and the expected one.
  std::filesystem::resize_file(path, 456);
  const Error error = thrown_by<Error>([&] { RigidTrajectoryReader::open(path, 2, 1); });
  EXPECT_NE(std::string(error.what()).find("456 bytes"), std::string::npos) << error.what();
  EXPECT_NE(std::string(error.what()).find("exactly 464"), std::string::npos) << error.what();
}

}  // namespace
}  // namespace fosssim::testing
