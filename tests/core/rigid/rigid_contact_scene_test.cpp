// Rigid-body contact run from scene text (<rigidbodycollisionhandling>): the course program's
// worked examples C (lcp), D (velocity-projection), E (gr-lcp) and F (gr-velocity-projection)
// one step at a time, the degenerate five-vertex table, gr-lcp's limit through the step
// pipeline, every malformed <rigidbodycollisionhandling> with its message, and the responses as
// entries of the contact registry.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/rigid/rigid_bodies.h"
#include "core/collisions/contact_registry.h"
#include "core/rigid/rigid_contact_stage.h"
#include "core/step/simulation.h"
#include "core/step_error.h"
#include "io/scene_error.h"
#include "io/scene_loader.h"
#include "support/thrown.h"

namespace fosssim::testing {
namespace {

std::string with_response(std::string text, const std::string& handling) {
  const std::string marker = "<!--contact-->";
  text.replace(text.find(marker), marker.size(), handling);
  return text;
}

/// Worked example C/D: a tilted box landing on a fixed floor, one step of h = 0.01.
constexpr const char* kTiltedBox = R"(<scene>
  <simtype type="rigid-body"/>
  <duration time="0.01"/>
  <rigidbodyintegrator type="symplectic-euler" dt="0.01"/>
  <rigidbodyvertex x="-5" y="0" m="1"/>
  <rigidbodyvertex x="5" y="0" m="1"/>
  <rigidbodyvertex x="5" y="-1" m="1"/>
  <rigidbodyvertex x="-5" y="-1" m="1"/>
  <rigidbodyvertex x="-1" y="1.15" m="1"/>
  <rigidbodyvertex x="1" y="1.1" m="1"/>
  <rigidbodyvertex x="1" y="0.16" m="1"/>
  <rigidbodyvertex x="-1" y="0.18" m="2"/>
  <rigidbody p="0" p="1" p="2" p="3" vx="0" vy="0" omega="0" r="0.1" fixed="1"/>
  <rigidbody p="4" p="5" p="6" p="7" vx="0.5" vy="-1" omega="0.3" r="0.1"/>
  <rigidbodygravityforce fx="0" fy="-9.81"/>
  <!--contact-->
</scene>)";

/// Worked example E/F: a block sliding at 1 into two resting blocks, no gravity.
constexpr const char* kRowOfBlocks = R"(<scene>
  <simtype type="rigid-body"/>
  <duration time="0.01"/>
  <rigidbodyintegrator type="symplectic-euler" dt="0.01"/>
  <rigidbodyvertex x="-0.5" y="0.5" m="1"/>
  <rigidbodyvertex x="0.5" y="0.5" m="1"/>
  <rigidbodyvertex x="0.5" y="-0.5" m="1"/>
  <rigidbodyvertex x="-0.5" y="-0.5" m="1"/>
  <rigidbodyvertex x="0.65" y="0.5" m="1"/>
  <rigidbodyvertex x="1.65" y="0.5" m="1"/>
  <rigidbodyvertex x="1.65" y="-0.5" m="1"/>
  <rigidbodyvertex x="0.65" y="-0.5" m="1"/>
  <rigidbodyvertex x="1.8" y="0.6" m="1"/>
  <rigidbodyvertex x="2.8" y="0.4" m="1"/>
  <rigidbodyvertex x="2.8" y="-0.6" m="1"/>
  <rigidbodyvertex x="1.8" y="-0.4" m="1"/>
  <rigidbody p="0" p="1" p="2" p="3" vx="1" vy="0" omega="0" r="0.1"/>
  <rigidbody p="4" p="5" p="6" p="7" vx="0" vy="0" omega="0" r="0.1"/>
  <rigidbody p="8" p="9" p="10" p="11" vx="0" vy="0" omega="0" r="0.1"/>
  <!--contact-->
</scene>)";

State one_step(const std::string& text) {
  const Scene scene = load_scene_text(text, "contact.xml");
  Simulation simulation(scene.model, scene.initial);
  simulation.step();
  return simulation.state();
}

void expect_body(const State& s, int b, Vec2 X, double theta, Vec2 V, double omega) {
  SCOPED_TRACE("body " + std::to_string(b));
  EXPECT_NEAR(s.q[3 * b], X.x(), 1e-12);
  EXPECT_NEAR(s.q[3 * b + 1], X.y(), 1e-12);
  EXPECT_NEAR(s.q[3 * b + 2], theta, 1e-12);
  EXPECT_NEAR(s.v[3 * b], V.x(), 1e-12);
  EXPECT_NEAR(s.v[3 * b + 1], V.y(), 1e-12);
  EXPECT_NEAR(s.v[3 * b + 2], omega, 1e-12);
}

TEST(RigidContactScene, WorkedExampleCLcp) {
  const State s = one_step(with_response(
      kTiltedBox, R"(<rigidbodycollisionhandling detection="all-pairs" response="lcp"/>)"));
  expect_body(s, 1, {-0.195, 0.543019}, 0.003, {0.5000000000000027, -1.3322676295501878e-15},
              4.996003610813204e-16);
  expect_body(s, 0, {0, -0.5}, 0, {0, 0}, 0);
}

TEST(RigidContactScene, WorkedExampleCRecordsAndLcp) {
  // The records, A, b and λ of the model that reproduces the course's frame.
  const Scene scene = load_scene_text(
      with_response(kTiltedBox,
                    R"(<rigidbodycollisionhandling detection="all-pairs" response="lcp"/>)"),
      "contact.xml");
  State s = scene.initial;
  s.q << 0, -0.5, 0, -0.195, 0.543019, 0.003;
  s.v << 0, 0, 0, 0.5, -1.0981, 0.3;
  const RigidBodies& bodies = *scene.model.rigid_bodies;
  const auto contacts = detect_rigid_contacts(bodies, s.q);
  ASSERT_EQ(contacts.size(), 2u);
  EXPECT_NEAR(contacts[0].arm0.x(), -0.9938744016856995, 1e-12);
  EXPECT_NEAR(contacts[0].arm0.y(), 0.6, 1e-12);
  EXPECT_NEAR(contacts[1].arm0.x(), 1.0061765982310507, 1e-12);
  EXPECT_NEAR(contacts[0].arm1.x(), -0.8002999995500004, 1e-12);
  EXPECT_NEAR(contacts[0].arm1.y(), -0.47399955000033756, 1e-12);
  EXPECT_NEAR(contacts[1].arm1.x(), 1.1997000004499996, 1e-12);
  EXPECT_NEAR(contacts[1].arm1.y(), -0.49399955000033746, 1e-12);
  const ContactProblem problem =
      assemble_contact_problem(ContactSolver::kLcp, bodies, s.q, s.v, contacts);
  EXPECT_NEAR(problem.A(0, 0), 0.3083841078047188, 1e-12);
  EXPECT_NEAR(problem.A(0, 1), 0.0370351413933527, 1e-12);
  EXPECT_NEAR(problem.A(1, 0), 0.0370351413933527, 1e-12);
  EXPECT_NEAR(problem.A(1, 1), 0.44503172723933493, 1e-12);
  EXPECT_NEAR(problem.b[0], -1.3377623205057079, 1e-12);
  EXPECT_NEAR(problem.b[1], -0.737747020530684, 1e-12);
  const ContactSolveResult result = solve_contact_lcp_dantzig(problem);
  ASSERT_TRUE(result.valid) << result.problem;
  EXPECT_NEAR(result.lambda[0], 4.180671449345852, 1e-12);
  EXPECT_NEAR(result.lambda[1], 1.309828550654142, 1e-12);
}

TEST(RigidContactScene, WorkedExampleDVelocityProjection) {
  const State s = one_step(with_response(
      kTiltedBox,
      R"(<rigidbodycollisionhandling detection="all-pairs" response="velocity-projection"/>)"));
  expect_body(s, 1, {-0.195, 0.543019}, 0.003, {0.5000000000000027, -1.3600232051658168e-15},
              4.440892098500626e-16);
}

TEST(RigidContactScene, WorkedExampleEGeneralizedReflectionsLcp) {
  const Scene scene = load_scene_text(
      with_response(kRowOfBlocks,
                    R"(<rigidbodycollisionhandling detection="all-pairs" response="gr-lcp"/>)"),
      "contact.xml");
  EXPECT_NEAR(scene.model.rigid_bodies->bodies[2].inertia, 2.0399999999999996, 1e-15);
  Simulation simulation(scene.model, scene.initial);
  simulation.step();
  const State& s = simulation.state();
  expect_body(s, 0, {0.01, 0}, 0, {0, 0}, 1.6653345369377348e-16);
  expect_body(s, 1, {1.15, 0}, 0, {1.1102230246251565e-16, -1.659915697598649e-16},
              -1.6653345369377348e-16);
  expect_body(s, 2, {2.3, 0}, 0, {0.9999999999999999, 1.659915697598649e-16},
              -3.3306690738754696e-16);
}

TEST(RigidContactScene, WorkedExampleEReflectsTwice) {
  const Scene scene = load_scene_text(
      with_response(kRowOfBlocks,
                    R"(<rigidbodycollisionhandling detection="all-pairs" response="gr-lcp"/>)"),
      "contact.xml");
  State s = scene.initial;
  s.q[0] += 0.01;  // after the integration of the first step
  const auto contacts = detect_rigid_contacts(*scene.model.rigid_bodies, s.q);
  ContactReport report;
  apply_generalized_reflections(ContactSolver::kLcp, *scene.model.rigid_bodies, s.q, contacts, 100,
                                s.v, report);
  EXPECT_EQ(report.reflections, 2);
}

TEST(RigidContactScene, WorkedExampleFGeneralizedReflectionsVelocityProjection) {
  const State s = one_step(with_response(
      kRowOfBlocks,
      R"(<rigidbodycollisionhandling detection="all-pairs" response="gr-velocity-projection"/>)"));
  EXPECT_NEAR(s.v[6], 0.9999999999999999, 1e-12);
  EXPECT_NEAR(s.v[7], 0.0, 1e-12);
  EXPECT_NEAR(s.v[3], 1.1102230246251565e-16, 1e-12);
  EXPECT_NEAR(s.v[4], 0.0, 1e-12);
  EXPECT_NEAR(s.v[5], 2.220446049250313e-16, 1e-12);
  EXPECT_NEAR(s.v[0], 0.0, 1e-12);
}

/// A five-vertex table whose three bottom vertices land flat on a fixed floor: three collinear
/// contacts, a singular LCP (the course's held-out "degenerate" scene has this shape).
constexpr const char* kTable = R"(<scene>
  <simtype type="rigid-body"/>
  <duration time="0.5"/>
  <rigidbodyintegrator type="symplectic-euler" dt="0.01"/>
  <rigidbodyvertex x="-5" y="0" m="1"/>
  <rigidbodyvertex x="5" y="0" m="1"/>
  <rigidbodyvertex x="5" y="-1" m="1"/>
  <rigidbodyvertex x="-5" y="-1" m="1"/>
  <rigidbodyvertex x="-1" y="1.25" m="1"/>
  <rigidbodyvertex x="1" y="1.25" m="1"/>
  <rigidbodyvertex x="1" y="0.25" m="1"/>
  <rigidbodyvertex x="0" y="0.25" m="1"/>
  <rigidbodyvertex x="-1" y="0.25" m="1"/>
  <rigidbody p="0" p="1" p="2" p="3" vx="0" vy="0" omega="0" r="0.1" fixed="1"/>
  <rigidbody p="4" p="5" p="6" p="7" p="8" vx="0" vy="0" omega="0" r="0.1"/>
  <rigidbodygravityforce fx="0" fy="-9.81"/>
  <rigidbodycollisionhandling detection="all-pairs" response="lcp"/>
</scene>)";

TEST(RigidContactScene, DegenerateTableLandsWithoutNanOrHangAndWarnsOnce) {
  const Scene scene = load_scene_text(kTable, "table.xml");
  ::testing::internal::CaptureStderr();
  Simulation simulation(scene.model, scene.initial);
  int resting_steps = 0;
  while (!simulation.finished()) {
    simulation.step();
    const State& s = simulation.state();
    ASSERT_TRUE(s.v.allFinite());
    // Once the table rests, contact stops it every step (velocity projection's answer; the
    // course's solver stops early every second step and lets it gain −g h).
    if (s.q[4] < 0.6) {  // the bottom (X_y − 0.4) within the radii (0.2) of the floor
      EXPECT_NEAR(s.v[4], 0.0, 1e-12) << "step " << s.step;
      EXPECT_NEAR(s.v[5], 0.0, 1e-12) << "step " << s.step;
      ++resting_steps;
    }
  }
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_GT(resting_steps, 10);
  const auto first = err.find("FOSSSim: warning: step ");
  ASSERT_NE(first, std::string::npos) << err;
  EXPECT_EQ(err.find("FOSSSim: warning: step ", first + 1), std::string::npos) << err;
  EXPECT_NE(err.find("redundant contacts"), std::string::npos) << err;
}

TEST(RigidContactScene, GeneralizedReflectionsOnAMovingFixedFloorStopAtTheLimit) {
  // A box resting on a fixed floor that declares vy = −0.5: the course's gr-lcp loops forever.
  const std::string text = R"(<scene>
  <simtype type="rigid-body"/>
  <duration time="0.05"/>
  <rigidbodyintegrator type="symplectic-euler" dt="0.01"/>
  <rigidbodyvertex x="-5" y="0" m="1"/>
  <rigidbodyvertex x="5" y="0" m="1"/>
  <rigidbodyvertex x="5" y="-1" m="1"/>
  <rigidbodyvertex x="-5" y="-1" m="1"/>
  <rigidbodyvertex x="-1" y="1.15" m="1"/>
  <rigidbodyvertex x="1" y="1.15" m="1"/>
  <rigidbodyvertex x="1" y="0.15" m="1"/>
  <rigidbodyvertex x="-1" y="0.15" m="1"/>
  <rigidbody p="0" p="1" p="2" p="3" vx="0" vy="-0.5" omega="0" r="0.1" fixed="1"/>
  <rigidbody p="4" p="5" p="6" p="7" vx="0" vy="0" omega="0" r="0.1"/>
  <rigidbodygravityforce fx="0" fy="-9.81"/>
  <rigidbodycollisionhandling detection="all-pairs" response="gr-lcp" maxreflections="200"/>
</scene>)";
  const Scene scene = load_scene_text(text, "moving_floor.xml");
  bool warned = false;
  for (const std::string& w : scene.warnings)
    warned |= w.find("never stops reflecting") != std::string::npos;
  EXPECT_TRUE(warned);
  Simulation simulation(scene.model, scene.initial);
  const StepError error = thrown_by<StepError>([&] { simulation.step(); });
  const std::string message = error.what();
  EXPECT_NE(message.find("did not end after 200 reflections"), std::string::npos) << message;
  EXPECT_NE(message.find("step 1"), std::string::npos) << message;
}

TEST(RigidContactScene, AGroupOfMoreContactsThanTheLimitFailsClearly) {
  // Example C's box lands with two contacts: a limit of one refuses the step.
  const Scene scene = load_scene_text(
      with_response(kTiltedBox, R"(<rigidbodycollisionhandling detection="all-pairs" )"
                                R"(response="lcp" maxgroupcontacts="1"/>)"),
      "contact.xml");
  EXPECT_EQ(scene.model.rigid_bodies->contact.max_group_contacts, 1);
  Simulation simulation(scene.model, scene.initial);
  const StepError error = thrown_by<StepError>([&] { simulation.step(); });
  EXPECT_NE(std::string(error.what()).find("2 contacts form one group"), std::string::npos)
      << error.what();
  EXPECT_NE(std::string(error.what()).find("maxgroupcontacts"), std::string::npos);
}

std::string error_of(const std::string& handling) {
  const std::string text = with_response(kTiltedBox, handling);
  return thrown_by<SceneError>([&] { load_scene_text(text, "contact.xml"); }).what();
}

TEST(RigidContactScene, MalformedCollisionHandlingIsRefusedWithTheCoursesMessages) {
  const std::string where = "contact.xml:16: error: <rigidbodycollisionhandling>";
  struct Case {
    const char* element;
    const char* message;
  };
  const Case cases[] = {
      {R"(<rigidbodycollisionhandling response="lcp"/>)",
       "No rigidbodycollisionhandling 'detection' attribute specified. Exiting."},
      {R"(<rigidbodycollisionhandling detection="grid" response="lcp"/>)",
       "Invalid rigidbodycollisionhandling 'detection' attribute specified. Valid option is "
       "all-pairs. Exiting. (found \"grid\")"},
      {R"(<rigidbodycollisionhandling detection="all-pairs"/>)",
       "No rigidbodycollisionhandling 'response' attribute specified. Exiting."},
      {R"(<rigidbodycollisionhandling detection="all-pairs" response="LCP"/>)",
       "Invalid rigidbodycollisionhandling 'response' attribute specified. Valid options are lcp "
       "and velocity-projection. Exiting. (found \"LCP\"; gr-lcp and gr-velocity-projection are "
       "valid too)"},
      {R"(<rigidbodycollisionhandling detection="all-pairs" response="gr-lcp" maxreflections="0"/>)",
       "attribute \"maxreflections\" must be a whole number from 1 to 2147483647, found 0"},
      {R"(<rigidbodycollisionhandling detection="all-pairs" response="gr-lcp" maxreflections="x"/>)",
       "maxreflections"},
      {R"(<rigidbodycollisionhandling detection="all-pairs" response="lcp" maxgroupcontacts="0"/>)",
       "attribute \"maxgroupcontacts\" must be a whole number from 1 to 2147483647, found 0"},
  };
  for (const Case& c : cases) {
    const std::string message = error_of(c.element);
    EXPECT_NE(message.find(where), std::string::npos) << message;
    EXPECT_NE(message.find(c.message), std::string::npos) << message;
  }
}

std::string handling(std::string_view response) {
  return R"(<rigidbodycollisionhandling detection="all-pairs" response=")" +
         std::string(response) + R"("/>)";
}

TEST(RigidContactScene, TheFourResponsesAreRegistryEntriesOfPlanarRigidBodies) {
  std::vector<std::string> names;
  for (const ContactMethod* method : contact_methods()) {
    if (!method->scope.planar_rigid_bodies) continue;
    names.emplace_back(method->name);
    // A rigid-body response handles nothing else and records nothing in particle files.
    EXPECT_FALSE(method->scope.particles) << method->name;
    EXPECT_EQ(method->records, StepRecordLayout::kFrames) << method->name;
    ASSERT_NE(method->rigid_response, nullptr) << method->name;
    EXPECT_EQ(method->make_force, nullptr) << method->name;
  }
  EXPECT_EQ(names, (std::vector<std::string>{"lcp", "velocity-projection", "gr-lcp",
                                              "gr-velocity-projection"}));
  EXPECT_EQ(describe_contact_method_names(BodyKind::kPlanarRigidBodies),
            "lcp, velocity-projection, gr-lcp, gr-velocity-projection");
  // Their responses: the two inelastic problems, once or as generalized reflections.
  const auto response = [](std::string_view name) { return *contact_method(name).rigid_response; };
  EXPECT_EQ(response("lcp").solver, ContactSolver::kLcp);
  EXPECT_FALSE(response("lcp").generalized_reflections);
  EXPECT_EQ(response("velocity-projection").solver, ContactSolver::kVelocityProjection);
  EXPECT_FALSE(response("velocity-projection").generalized_reflections);
  EXPECT_EQ(response("gr-lcp").solver, ContactSolver::kLcp);
  EXPECT_TRUE(response("gr-lcp").generalized_reflections);
  EXPECT_EQ(response("gr-velocity-projection").solver, ContactSolver::kVelocityProjection);
  EXPECT_TRUE(response("gr-velocity-projection").generalized_reflections);
}

TEST(RigidContactScene, EveryMethodIsNamedAndMadeFromTheScene) {
  int rigid_methods = 0;
  for (const ContactMethod* method : contact_methods()) {
    if (!method->scope.planar_rigid_bodies) continue;
    ++rigid_methods;
    const Scene scene =
        load_scene_text(with_response(kTiltedBox, handling(method->name)), "contact.xml");
    EXPECT_EQ(scene.model.collisions.method, method);
    EXPECT_TRUE(contact_method_refusal(*method, scene.model).empty());
    const std::unique_ptr<StepStage> stage = make_contact_stage(scene.model);
    ASSERT_NE(stage, nullptr);
    EXPECT_NE(dynamic_cast<const RigidContactStage*>(stage.get()), nullptr);
  }
  EXPECT_EQ(rigid_methods, 4);
  const Scene none = load_scene_text(with_response(kTiltedBox, ""), "contact.xml");
  EXPECT_EQ(none.model.collisions.method, &no_contact_method());
  EXPECT_EQ(make_contact_stage(none.model), nullptr);
}

TEST(RigidContactScene, AParticleMethodIsRefusedAsAResponseWithTheCoursesMessage) {
  const std::string where = "contact.xml:16: error: <rigidbodycollisionhandling>";
  for (const ContactMethod* method : contact_methods()) {
    if (method->scope.planar_rigid_bodies) continue;
    SCOPED_TRACE(std::string(method->name));
    const std::string message = error_of(handling(method->name));
    EXPECT_NE(message.find(where), std::string::npos) << message;
    EXPECT_NE(message.find("Invalid rigidbodycollisionhandling 'response' attribute specified. "
                           "Valid options are lcp and velocity-projection. Exiting. (found \"" +
                           std::string(method->name) + "\": \"" + std::string(method->name) +
                           "\" does not handle rigid bodies (it is a method of particles, named "
                           "by <collision type=\"...\">); gr-lcp and gr-velocity-projection are "
                           "valid too)"),
              std::string::npos)
        << message;
  }
}

}  // namespace
}  // namespace fosssim::testing
