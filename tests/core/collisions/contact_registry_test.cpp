// The contact registry: the invariants every entry must keep, and that the step pipeline, the
// force set and the records follow the entries (a new method is covered without changes here).

#include "core/collisions/contact_registry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/force_set.h"
#include "core/rigid/rigid_contact_stage.h"
#include "core/step/step_pipeline.h"
#include "core/rigid_test_models.h"
#include "support/scene_builder.h"

namespace fosssim {
namespace {

using testing::TestScene;
using testing::vec;

TEST(ContactRegistry, NamesAreUniqueAndFoundByName) {
  std::set<std::string> names;
  for (const ContactMethod* method : contact_methods()) {
    EXPECT_FALSE(method->name.empty());
    EXPECT_TRUE(names.insert(std::string(method->name)).second) << method->name;
    EXPECT_EQ(find_contact_method(method->name), method);
    EXPECT_EQ(&contact_method(method->name), method);
  }
  EXPECT_EQ(find_contact_method("SIMPLE"), nullptr);  // exact spelling
  EXPECT_THROW(contact_method("bounce"), std::logic_error);
}

TEST(ContactRegistry, TheCourseMethodsAreRegisteredInTheCourseOrder) {
  EXPECT_EQ(describe_contact_method_names(BodyKind::kParticles),
            "none, simple, penalty, continuous-time, hybrid");
  EXPECT_EQ(describe_contact_method_names(BodyKind::kPlanarRigidBodies),
            "lcp, velocity-projection, gr-lcp, gr-velocity-projection");
  EXPECT_EQ(no_contact_method().name, "none");
  EXPECT_EQ(CollisionSettings{}.method, &no_contact_method());
}

TEST(ContactRegistry, EveryEntryHasASummaryAFactoryAndDocumentedOptions) {
  for (const ContactMethod* method : contact_methods()) {
    SCOPED_TRACE(std::string(method->name));
    EXPECT_FALSE(method->summary.empty());
    // Only "none" does nothing; every other method has a stage or a force.
    const bool acts = method->make_stage != nullptr || method->make_force != nullptr;
    EXPECT_EQ(acts, method != &no_contact_method());
    // A method that records collisions or polynomials needs a stage to record them.
    if (method->records != StepRecordLayout::kFrames) {
      EXPECT_NE(method->make_stage, nullptr);
    }
    // It handles one body kind in some dimension, and says why it refuses the others.
    const ContactScope& scope = method->scope;
    EXPECT_NE(scope.particles, scope.planar_rigid_bodies);
    EXPECT_TRUE(scope.runs_2d || scope.runs_3d);
    if (!(scope.particles && scope.runs_2d && scope.runs_3d)) {
      EXPECT_FALSE(scope.restriction.empty());
    }
    // Rigid bodies are planar; a rigid-body method has its response, which only its stage runs
    // (it records nothing in a particle file and adds no force), and a particle method has none.
    if (scope.planar_rigid_bodies) {
      EXPECT_TRUE(scope.runs_2d);
      EXPECT_FALSE(scope.runs_3d);
      EXPECT_NE(method->rigid_response, nullptr);
      EXPECT_NE(method->make_stage, nullptr);
      EXPECT_EQ(method->make_force, nullptr);
      EXPECT_EQ(method->records, StepRecordLayout::kFrames);
    } else {
      EXPECT_EQ(method->rigid_response, nullptr);
    }
    std::set<std::string> options;
    for (const OptionSpec& option : method->options) {
      SCOPED_TRACE(std::string(option.name));
      EXPECT_TRUE(options.insert(std::string(option.name)).second);
      EXPECT_FALSE(option.help.empty());
      EXPECT_FALSE(option.describe_values().empty());
      EXPECT_FALSE(option.default_text().empty());
      if (option.type == OptionSpec::Type::kChoice) {
        EXPECT_FALSE(option.choices.empty());
      } else {
        // The default is a value the option accepts.
        EXPECT_TRUE(std::isfinite(option.default_value));
        EXPECT_TRUE(option.lowest_excluded ? option.default_value > option.lowest
                                           : option.default_value >= option.lowest);
        EXPECT_LE(option.default_value, option.highest);
      }
    }
    // Values start at the defaults.
    CollisionSettings settings;
    settings.use(*method);
    EXPECT_EQ(settings.method, method);
    for (const OptionSpec& option : method->options) {
      if (option.type == OptionSpec::Type::kChoice) {
        EXPECT_EQ(settings.options.choice(option.name), option.choices.front());
      } else {
        EXPECT_EQ(settings.options.number(option.name), option.default_value);
      }
    }
  }
}

TEST(ContactRegistry, TheRigidMethodsOwnLimitsAreOptionsOfTheirEntries) {
  // FOSSSim's limits of rigid-body contact are registry options, so --help lists them and the
  // loader reads them as every method's options: maxgroupcontacts for every rigid method,
  // maxreflections for the ones that reflect.
  for (const ContactMethod* method : contact_methods()) {
    if (!method->scope.planar_rigid_bodies) continue;
    SCOPED_TRACE(std::string(method->name));
    const OptionValues values(method->options);
    ASSERT_TRUE(values.has("maxgroupcontacts"));
    EXPECT_EQ(values.integer("maxgroupcontacts"), RigidContactSettings::kDefaultMaxGroupContacts);
    EXPECT_EQ(values.has("maxreflections"), method->rigid_response->generalized_reflections);
    if (values.has("maxreflections")) {
      EXPECT_EQ(values.integer("maxreflections"), RigidContactSettings::kDefaultMaxReflections);
    }
  }
}

TEST(ContactRegistry, TheCoursesThemeThreeMessageNamesExactlyTheEntriesThatSaySo) {
  // The course's message: "Valid options are lcp and velocity-projection."; the loader adds the
  // others after it from the entries' in_course_messages field, not from their names.
  const std::set<std::string> course_names = {"lcp", "velocity-projection"};
  int rigid = 0;
  for (const ContactMethod* method : contact_methods()) {
    if (!method->scope.planar_rigid_bodies) {
      EXPECT_TRUE(method->in_course_messages) << method->name;
      continue;
    }
    ++rigid;
    EXPECT_EQ(method->in_course_messages, course_names.count(std::string(method->name)) == 1)
        << method->name;
  }
  EXPECT_EQ(rigid, 4);
}

TEST(ContactRegistry, SuggestsTheMethodAMisspeltNameMeans) {
  constexpr BodyKind kParticles = BodyKind::kParticles;
  EXPECT_EQ(suggest_contact_method("hybird", kParticles), "hybrid");
  EXPECT_EQ(suggest_contact_method("simpel", kParticles), "simple");
  EXPECT_EQ(suggest_contact_method("continuous_time", kParticles), "continuous-time");
  EXPECT_EQ(suggest_contact_method("SIMPLE", kParticles), "");  // six edits: lower case
  EXPECT_EQ(suggest_contact_method("bounce", kParticles), "");
  // Only the methods of the body kind are suggested.
  EXPECT_EQ(suggest_contact_method("gr_lcp", BodyKind::kPlanarRigidBodies), "gr-lcp");
  EXPECT_EQ(suggest_contact_method("gr_lcp", kParticles), "");
  EXPECT_EQ(suggest_contact_method("simpel", BodyKind::kPlanarRigidBodies), "");
}

TEST(ContactRegistry, RefusesBodiesAndDimensionsOutsideAMethodsScope) {
  TestScene plane(2), space(3);
  for (const ContactMethod* method : contact_methods()) {
    EXPECT_EQ(contact_method_refusal(*method, plane.model).empty(),
              method->scope.particles && method->scope.runs_2d)
        << method->name;
    EXPECT_EQ(contact_method_refusal(*method, space.model).empty(),
              method->scope.particles && method->scope.runs_3d)
        << method->name;
  }
  EXPECT_EQ(contact_method_refusal(contact_method("hybrid"), space.model),
            "\"hybrid\" is 2D only (its rigid impact zones rotate in the plane)");
  EXPECT_EQ(contact_method_refusal(contact_method("lcp"), plane.model),
            "\"lcp\" does not handle particles (it is a method of rigid bodies, named by "
            "<rigidbodycollisionhandling response=\"...\">)");
}

TEST(ContactRegistry, RefusesEveryMethodForTheBodyKindsItDoesNotHandle) {
  // Planar rigid bodies: their model's dim counts three coordinates, yet they are 2D.
  auto [rigid, state] = testing::make_rigid_model(
      {{.points = {{0, 0}, {1, 0}, {1, 1}}, .masses = {1, 1, 1}}});
  EXPECT_EQ(body_kind(rigid), BodyKind::kPlanarRigidBodies);
  EXPECT_EQ(body_dimension(rigid), 2);
  TestScene plane(2), space(3);
  EXPECT_EQ(body_kind(plane.model), BodyKind::kParticles);
  EXPECT_EQ(body_dimension(space.model), 3);
  for (const ContactMethod* method : contact_methods()) {
    SCOPED_TRACE(std::string(method->name));
    const std::string refusal = contact_method_refusal(*method, rigid);
    EXPECT_EQ(refusal.empty(), method->scope.planar_rigid_bodies) << refusal;
    if (method->scope.planar_rigid_bodies) {
      // Refused wherever particles are, whatever their dimension.
      EXPECT_NE(contact_method_refusal(*method, plane.model).find("does not handle particles"),
                std::string::npos);
      EXPECT_NE(contact_method_refusal(*method, space.model).find("does not handle particles"),
                std::string::npos);
    } else {
      EXPECT_EQ(refusal, "\"" + std::string(method->name) +
                             "\" does not handle rigid bodies (it is a method of particles, "
                             "named by <collision type=\"...\">)");
    }
  }
}

TEST(ContactRegistry, ThePipelineRunsARigidMethodsStageOnRigidBodies) {
  // A unit square falling at 1 m/s onto a fixed floor it already touches: every rigid method
  // stops it (inelastic) or bounces it (reflections); "none" lets it fall on.
  const std::vector<Vec2> square = {{-0.5, 0.6}, {0.5, 0.6}, {0.5, 0.15}, {-0.5, 0.15}};
  const std::vector<Vec2> floor = {{-5, 0}, {5, 0}, {5, -1}, {-5, -1}};
  const auto falling = [&] {
    return testing::make_rigid_model(
        {{.points = floor, .masses = {1, 1, 1, 1}, .fixed = true},
         {.points = square, .masses = {1, 1, 1, 1}, .velocity = {0, -1}}});
  };
  for (const ContactMethod* method : contact_methods()) {
    if (!method->scope.planar_rigid_bodies) continue;
    SCOPED_TRACE(std::string(method->name));
    auto [model, state] = falling();
    model.collisions.use(*method);
    model.integrator.use(*find_integrator_method("symplectic-euler"));
    model.integrator.dt = 0.01;
    StepPipeline(model).step(state);
    // The square's vertical velocity: 0 when the contact is inelastic, +1 when it is reflected
    // (no forces act).
    const double expected = method->rigid_response->generalized_reflections ? 1.0 : 0.0;
    EXPECT_NEAR(state.v[4], expected, 1e-12);
  }
  auto [model, state] = falling();
  model.integrator.use(*find_integrator_method("symplectic-euler"));
  model.integrator.dt = 0.01;
  StepPipeline(model).step(state);
  EXPECT_EQ(state.v[4], -1.0);
}

/// Two balls of radius 0.1 that overlap (centres 0.19 apart) and approach, over a floor.
TestScene overlapping_balls(const ContactMethod& method) {
  TestScene scene(2, "explicit-euler", 0.01);
  scene.add_particle(1, vec({0, 0.5}), vec({1, 0}));
  scene.add_particle(1, vec({0.19, 0.5}), vec({-1, 0}));
  scene.add_half_plane(vec({0, 0}), vec({0, 1}));
  scene.model.collisions.use(method);
  return scene;
}

/// True for the methods of 2D particle scenes, which the scene below exercises (a rigid-body
/// method's records are its own tests' business).
bool handles_2d_particles(const ContactMethod& method) {
  return method.scope.particles && method.scope.runs_2d;
}

TEST(ContactRegistry, TheForceSetAndThePipelineUseTheEntrysFactories) {
  for (const ContactMethod* method : contact_methods()) {
    if (!handles_2d_particles(*method)) continue;
    SCOPED_TRACE(std::string(method->name));
    TestScene scene = overlapping_balls(*method);
    const ForceSet forces(scene.model);
    EXPECT_EQ(forces.forces().size(),
              scene.model.forces.size() + (method->make_force != nullptr ? 1 : 0));
    EXPECT_EQ(make_contact_stage(scene.model) != nullptr, method->make_stage != nullptr);
  }
}

TEST(ContactRegistry, AStepRecordsWhatTheEntrysLayoutSays) {
  TestScene none = overlapping_balls(no_contact_method());
  StepPipeline(none.model).step(none.initial);
  for (const ContactMethod* method : contact_methods()) {
    if (!handles_2d_particles(*method)) continue;
    SCOPED_TRACE(std::string(method->name));
    TestScene scene = overlapping_balls(*method);
    StepRecord record;
    StepPipeline(scene.model).step(scene.initial, &record);
    // The balls collide: a method that records collisions records them (hybrid records none,
    // as the course's program).
    switch (method->records) {
      case StepRecordLayout::kFrames:
        EXPECT_TRUE(record.collisions.empty());
        EXPECT_TRUE(record.polynomials.empty());
        EXPECT_FALSE(record.sync.has_value());
        break;
      case StepRecordLayout::kCollisions:
        EXPECT_FALSE(record.collisions.empty());
        EXPECT_TRUE(record.polynomials.empty());
        EXPECT_FALSE(record.sync.has_value());
        break;
      case StepRecordLayout::kCollisionsAndPolynomials:
        // One pass over 2 particles and a half-plane: 2·1 + 2·2·1 polynomials at least.
        EXPECT_GE(record.polynomials.size(), 6u);
        EXPECT_TRUE(record.sync.has_value());
        break;
    }
    // Every method but none changes the balls' velocities: they approach inside each other.
    const bool changed = scene.initial.v != none.initial.v;
    EXPECT_EQ(changed, method != &no_contact_method());
  }
}

}  // namespace
}  // namespace fosssim
