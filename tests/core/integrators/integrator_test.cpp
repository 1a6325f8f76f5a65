// Tests common to every integrator of the registry (core/integrators/integrator.h,
// integrator_registry.h), in 2D and 3D.
//
// Checked:
// - make_integrator builds the method named by the model, bound to it; an integrator binds to
//   one model, refuses to step before precompute, and refuses a state of another size;
// - the registry: names and aliases unique and found, options' defaults valid, the course's
//   four methods and their aliases marked as the course's reference;
// - a fixed particle with a non-zero velocity, pulled by a spring and gravity and dragged, gets
//   no force (docs/integrators.md, 'Fixed particles'): its velocity stays exactly u and it moves
//   in a straight line, x₀ + n h u after n steps, with every method; a fixed particle at rest
//   stays exactly put;
// - step and time bookkeeping: after n steps, step = n and time = n h.

#include "core/integrators/integrator.h"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

#include "core/integrators/explicit_euler.h"
#include "core/integrators/implicit_euler.h"
#include "core/integrators/integrator_registry.h"
#include "core/integrators/linearized_implicit_euler.h"
#include "core/integrators/linearly_implicit_euler.h"
#include "core/integrators/local_global.h"
#include "core/integrators/solver_option.h"
#include "core/integrators/symplectic_euler.h"
#include "support/closed_forms.h"
#include "support/random.h"
#include "support/scene_builder.h"
#include "support/typed_tests.h"

namespace fosssim::testing {
namespace {

FOSSSIM_TEST_SUITE_IN_2D_AND_3D(IntegratorTest);

TEST(MakeIntegrator, BuildsTheNamedMethodBoundToTheModel) {
  SceneModel model;
  const std::pair<const char*, bool (*)(const Integrator*)> kinds[] = {
      {"explicit-euler",
       [](const Integrator* i) { return !!dynamic_cast<const ExplicitEuler*>(i); }},
      {"symplectic-euler",
       [](const Integrator* i) { return !!dynamic_cast<const SymplecticEuler*>(i); }},
      {"linearized-implicit-euler",
       [](const Integrator* i) { return !!dynamic_cast<const LinearizedImplicitEuler*>(i); }},
      {"implicit-euler",
       [](const Integrator* i) { return !!dynamic_cast<const ImplicitEuler*>(i); }},
      {"local-global",
       [](const Integrator* i) { return !!dynamic_cast<const LocalGlobal<2>*>(i); }},
      {"linearly-implicit-euler",
       [](const Integrator* i) { return !!dynamic_cast<const LinearlyImplicitEuler*>(i); }},
  };
  for (const auto& [name, is_it] : kinds) {
    model.integrator.use(integrator_method(name));
    const auto integrator = make_integrator(model);
    EXPECT_TRUE(is_it(integrator.get())) << name;
    EXPECT_TRUE(integrator->is_bound()) << name;
    EXPECT_EQ(&integrator->model(), &model) << name;
  }
}

TEST(MakeIntegrator, AnIntegratorIsBoundToOneModelAndStepsOnlyItsStates) {
  TestScene scene(2, "explicit-euler");
  scene.add_particle(1.0, vec({0.0, 0.0}), vec({1.0, 0.0}));
  ExplicitEuler unbound;
  State state = scene.initial;
  EXPECT_THROW(unbound.step(state), std::logic_error) << "step before precompute";
  const auto integrator = make_integrator(scene.model);
  EXPECT_THROW(integrator->precompute(scene.model), std::logic_error) << "bound twice";
  State wrong;
  wrong.q = Vector::Zero(4);
  wrong.v = Vector::Zero(4);
  EXPECT_THROW(integrator->step(wrong), std::logic_error) << "a state of another model";
  integrator->step(state);
  EXPECT_EQ(state.step, 1);
}

TEST(IntegratorRegistry, EveryNameAndAliasFindsItsMethodAndNamesAreUnique) {
  std::set<std::string_view> seen;
  for (const IntegratorMethod* method : integrator_methods()) {
    EXPECT_TRUE(seen.insert(method->name).second) << method->name;
    EXPECT_EQ(find_integrator_method(method->name), method);
    EXPECT_EQ(&integrator_method(method->name), method);
    for (std::string_view alias : method->aliases) {
      EXPECT_TRUE(seen.insert(alias).second) << alias;
      EXPECT_EQ(find_integrator_method(alias), method) << alias;
    }
    EXPECT_FALSE(method->summary.empty()) << method->name;
    EXPECT_NE(method->create, nullptr) << method->name;
    // Every option's default is a valid value of it.
    OptionValues values(method->options);
    for (const OptionSpec& spec : method->options) {
      if (spec.type == OptionSpec::Type::kChoice) {
        EXPECT_NO_THROW(values.set(spec.name, values.choice(spec.name))) << spec.name;
      } else {
        EXPECT_NO_THROW(values.set(spec.name, spec.default_value)) << spec.name;
      }
    }
  }
  EXPECT_EQ(find_integrator_method("Explicit-Euler"), nullptr) << "names are case-sensitive";
  EXPECT_THROW(integrator_method("no-such-method"), std::logic_error);
  // The course's four, with the aliases its handouts print.
  for (const char* type :
       {"explicit-euler", "symplectic-euler", "forward-backward-euler", "semi-implicit-euler",
        "linearized-implicit-euler", "linearized-implicit", "implicit-euler", "implicit"}) {
    ASSERT_NE(find_integrator_method(type), nullptr) << type;
    EXPECT_TRUE(find_integrator_method(type)->properties.course_reference) << type;
  }
}

TYPED_TEST(IntegratorTest, FixedParticlesGetNoForceAndMoveInAStraightLine) {
  constexpr int D = TypeParam::value;
  Random random(171);
  const Vector start = random.uniform_vector(D, -1.0, 1.0);
  const Vector u = random.uniform_vector(D, -1.0, 1.0);
  const Vector anchor = random.uniform_vector(D, -1.0, 1.0);
  for (const IntegratorMethod* method : all_integrators()) {
    const std::string_view kind = method->name;
    SCOPED_TRACE(std::string(kind));
    const double h = 0.01;
    TestScene scene(D, kind, h);
    scene.add_particle(2.0, start, u, /*fixed=*/true);
    scene.add_particle(1.0, start + random.unit_vector(D), random.uniform_vector(D, -1.0, 1.0));
    scene.add_particle(3.0, anchor, Vector::Zero(D), /*fixed=*/true);
    scene.add_spring(0, 1, 50.0, 0.5, 0.2);
    scene.add_spring(1, 2, 30.0, 0.8);
    scene.add_simple_gravity(random.uniform_vector(D, -10.0, 10.0));
    scene.add_drag(0.3);
    const State end = run_steps(scene.model, scene.initial, 100);
    EXPECT_EQ(end.step, 100);
    EXPECT_DOUBLE_EQ(end.time, 100 * h);
    EXPECT_EQ(Vector(end.v.head(D)), u);
    expect_close(end.q.head(D), start + 100 * h * u, 1e-13, "moving fixed particle");
    EXPECT_EQ(Vector(end.q.tail(D)), anchor);
    EXPECT_TRUE(end.v.tail(D).isZero(0.0));
    EXPECT_GT((end.q.segment(D, D) - scene.initial.q.segment(D, D)).norm(), 1e-3)
        << "free one moved";
  }
}

}  // namespace
// Issue 23: "cholmod" meant MUMPS, CHOLMOD or UMFPACK; the option is named after what it does,
// and the old name stays an alias so that old scenes keep working.
TEST(SolverOption, SparseDirectAndItsOldNameCholmodChooseTheSparseDirectLibraries) {
  OptionValues values(std::span<const OptionSpec>(&kSolverOption, 1));
  EXPECT_EQ(solver_choice(values), SolverChoice::kAuto);
  values.set("solver", "sparse-direct");
  EXPECT_EQ(solver_choice(values), SolverChoice::kSparseDirect);
  values.set("solver", "cholmod");
  EXPECT_EQ(solver_choice(values), SolverChoice::kSparseDirect);
  values.set("solver", "eigen");
  EXPECT_EQ(solver_choice(values), SolverChoice::kEigen);
  values.set("solver", "amg");
  EXPECT_EQ(solver_choice(values), SolverChoice::kAmg);
  EXPECT_EQ(kSolverOption.describe_values(),
            "\"auto\", \"eigen\", \"sparse-direct\", \"cholmod\" or \"amg\"");
}

}  // namespace fosssim::testing
