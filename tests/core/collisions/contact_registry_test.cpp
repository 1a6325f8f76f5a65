// The contact registry: the invariants every entry must keep, and that the step pipeline, the
// force set and the records follow the entries (a new method is covered without changes here).

#include "core/collisions/contact_registry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

#include "core/force_set.h"
#include "core/step/step_pipeline.h"
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
  EXPECT_EQ(describe_contact_method_names(), "none, simple, penalty, continuous-time, hybrid");
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
    // It handles some body kind in some dimension, and says why it refuses the others.
    const ContactScope& scope = method->scope;
    EXPECT_TRUE(scope.particles || scope.planar_rigid_bodies);
    EXPECT_TRUE(scope.runs_2d || scope.runs_3d);
    if (!(scope.particles && scope.runs_2d && scope.runs_3d)) {
      EXPECT_FALSE(scope.restriction.empty());
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

TEST(ContactRegistry, SuggestsTheMethodAMisspeltNameMeans) {
  EXPECT_EQ(suggest_contact_method("hybird"), "hybrid");
  EXPECT_EQ(suggest_contact_method("simpel"), "simple");
  EXPECT_EQ(suggest_contact_method("continuous_time"), "continuous-time");
  EXPECT_EQ(suggest_contact_method("SIMPLE"), "");  // six edits: the message says lower case
  EXPECT_EQ(suggest_contact_method("bounce"), "");
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
