// Scenes that load: every element and attribute of docs/scene-format.md, its defaults, the
// integrator aliases, and the course-compatible force summation order.

#include "io/scene_loader.h"

#include <gtest/gtest.h>

#include "core/force_evaluation.h"

namespace fosssim {
namespace {

Scene load(const std::string& xml) { return load_scene_text(xml, "test.xml"); }

TEST(SceneLoader, ReadsParticlesEdgesAndSettings) {
  const Scene scene = load(R"(<scene>
    <duration time="4.0"/>
    <integrator type="explicit-euler" dt="0.01"/>
    <maxsimfreq max="250"/>
    <description text="two particles"/>
    <scenetag tag="ParticleFountain"/>
    <particle m="2" px=" 0.7" py="-1" vx="3" vy="4" fixed="0" radius="0.25" tag="teleport"/>
    <particle m="1" px="1" py="2" vx="0" vy="0" fixed="1"/>
    <edge i="0" j="1" radius="0.05"/>
  </scene>)");
  const SceneModel& model = scene.model;
  EXPECT_EQ(model.dim, 2);
  EXPECT_EQ(model.num_particles(), 2);
  EXPECT_EQ(model.num_steps(), 400);  // ceil(4.0 / 0.01) in double precision
  EXPECT_EQ(model.integrator.method->name, "explicit-euler");
  EXPECT_EQ(model.integrator.dt, 0.01);
  EXPECT_EQ(model.mass, (Vector(4) << 2, 2, 1, 1).finished());
  EXPECT_EQ(model.fixed, (std::vector<bool>{false, true}));
  EXPECT_EQ(scene.initial.q, (Vector(4) << 0.7, -1, 1, 2).finished());
  EXPECT_EQ(scene.initial.v, (Vector(4) << 3, 4, 0, 0).finished());
  ASSERT_EQ(model.edges.size(), 1u);
  EXPECT_EQ(model.edges[0].i, 0);
  EXPECT_EQ(model.edges[0].j, 1);
  EXPECT_EQ(scene.model.particle_radius, (std::vector<double>{0.25, 0.1}));
  EXPECT_EQ(scene.model.edge_radius, (std::vector<double>{0.05}));
  EXPECT_EQ(scene.max_sim_frequency, 250.0);
  EXPECT_EQ(scene.description, "two particles");
  EXPECT_EQ(scene.tag, "ParticleFountain");
  EXPECT_EQ(scene.particle_tags, (std::vector<std::string>{"teleport", ""}));
  EXPECT_TRUE(scene.warnings.empty());
}

TEST(SceneLoader, AppliesDocumentedDefaults) {
  const Scene scene = load(R"(<scene>
    <duration time="1"/><integrator type="symplectic-euler" dt="0.1"/>
    <particle m="1" px="0" py="0" vx="0" vy="0" fixed="0"/>
    <particle m="1" px="1" py="0" vx="0" vy="0" fixed="0"/>
    <edge i="0" j="1"/>
  </scene>)");
  EXPECT_EQ(scene.max_sim_frequency, 100.0);
  EXPECT_EQ(scene.model.particle_radius[0], 0.1);
  EXPECT_EQ(scene.model.edge_radius[0], 0.015);
  EXPECT_EQ(scene.appearance.particle_color[1], (Color{0.651, 0.294, 0.0}));
  EXPECT_EQ(scene.appearance.edge_color[0], (Color{0.0, 0.388, 0.388}));
  EXPECT_EQ(scene.appearance.background, (Color{1.0, 1.0, 1.0}));
  EXPECT_FALSE(scene.appearance.viewport.has_value());
}

TEST(SceneLoader, ReadsAppearanceElements) {
  const Scene scene = load(R"(<scene>
    <duration time="1"/><integrator type="explicit-euler" dt="0.1"/>
    <particle m="1" px="0" py="0" vx="0" vy="0" fixed="0"/>
    <particle m="1" px="1" py="0" vx="0" vy="0" fixed="0"/>
    <edge i="0" j="1"/>
    <particlecolor i="1" r="0.1" g="0.2" b="0.3"/>
    <edgecolor i="0" r="1" g="0" b="0.5"/>
    <backgroundcolor r="0" g="0" b="0"/>
    <particlepath i="0" duration="2.5" r="0" g="1" b="0"/>
    <viewport cx="1" cy="-2" size="5"/>
  </scene>)");
  const Appearance& look = scene.appearance;
  EXPECT_EQ(look.particle_color[1], (Color{0.1, 0.2, 0.3}));
  EXPECT_EQ(look.edge_color[0], (Color{1, 0, 0.5}));
  EXPECT_EQ(look.background, (Color{0, 0, 0}));
  ASSERT_EQ(look.paths.size(), 1u);
  EXPECT_EQ(look.paths[0].particle, 0);
  EXPECT_EQ(look.paths[0].duration, 2.5);
  ASSERT_TRUE(look.viewport.has_value());
  EXPECT_EQ(look.viewport->cx, 1);
  EXPECT_EQ(look.viewport->cy, -2);
  EXPECT_EQ(look.viewport->size, 5);
}

TEST(SceneLoader, AcceptsEveryIntegratorAlias) {
  const std::pair<const char*, std::string_view> aliases[] = {
      {"explicit-euler", "explicit-euler"},
      {"symplectic-euler", "symplectic-euler"},
      {"forward-backward-euler", "symplectic-euler"},
      {"semi-implicit-euler", "symplectic-euler"},
      {"linearized-implicit-euler", "linearized-implicit-euler"},
      {"linearized-implicit", "linearized-implicit-euler"},
      {"implicit-euler", "implicit-euler"},
      {"implicit", "implicit-euler"},
  };
  for (const auto& [name, kind] : aliases) {
    const Scene scene = load(std::string(R"(<scene><duration time="1"/><integrator type=")") +
                             name + R"(" dt="0.1"/></scene>)");
    EXPECT_EQ(scene.model.integrator.method->name, kind) << name;
  }
}

// Forces are summed grouped by kind (springforce, simplegravity, gravitationalforce,
// constantforce, dragdamping, vortexforce), each group in document order, whatever the order in
// the file.
TEST(SceneLoader, OrdersForcesByKindThenDocument) {
  const Scene scene = load(R"(<scene>
    <duration time="1"/><integrator type="explicit-euler" dt="0.1"/>
    <vortexforce i="0" j="1" kbs="1" kvc="1"/>
    <dragdamping b="0.1"/>
    <constantforce fx="1" fy="0"/>
    <gravitationalforce i="0" j="2" G="1"/>
    <simplegravity fx="0" fy="-1"/>
    <springforce edge="1" k="1" l0="1"/>
    <springforce edge="0" k="1" l0="1"/>
    <gravitationalforce i="1" j="2" G="1"/>
    <particle m="1" px="0" py="0" vx="0" vy="0" fixed="0"/>
    <particle m="1" px="1" py="0" vx="0" vy="0" fixed="0"/>
    <particle m="1" px="0" py="1" vx="0" vy="0" fixed="0"/>
    <edge i="0" j="1"/>
    <edge i="1" j="2"/>
  </scene>)");
  std::vector<std::string> labels;
  for (const auto& force : scene.model.forces) labels.push_back(force->label());
  EXPECT_EQ(labels,
            (std::vector<std::string>{"springforce(1, 2)", "springforce(0, 1)", "simplegravity",
                                      "gravitationalforce(0, 2)", "gravitationalforce(1, 2)",
                                      "constantforce", "dragdamping", "vortexforce(0, 1)"}));
}

TEST(SceneLoader, ForceParametersReachTheForces) {
  // One particle under simple gravity (acceleration), a constant force and drag:
  // F = m g + f - b v.
  const Scene scene = load(R"(<scene>
    <duration time="1"/><integrator type="explicit-euler" dt="0.1"/>
    <particle m="2" px="0" py="0" vx="1" vy="-1" fixed="0"/>
    <simplegravity fx="0.5" fy="-10"/>
    <constantforce fx="3" fy="4"/>
    <dragdamping b="0.25"/>
  </scene>)");
  const Vector force = compute_force(ForceSet(scene.model), scene.initial.q, scene.initial.v);
  EXPECT_DOUBLE_EQ(force[0], 2 * 0.5 + 3 - 0.25 * 1);
  EXPECT_DOUBLE_EQ(force[1], 2 * -10 + 4 - 0.25 * -1);
}

TEST(SceneLoader, SpringDampingDefaultsToZero) {
  const Scene scene = load(R"(<scene>
    <duration time="1"/><integrator type="explicit-euler" dt="0.1"/>
    <particle m="1" px="0" py="0" vx="0" vy="0" fixed="0"/>
    <particle m="1" px="2" py="0" vx="1" vy="0" fixed="0"/>
    <edge i="0" j="1"/>
    <springforce edge="0" k="3" l0="1"/>
  </scene>)");
  // With b = 0 the relative velocity adds nothing: F_0 = k (l - l0) n = (3, 0).
  const Vector force = compute_force(ForceSet(scene.model), scene.initial.q, scene.initial.v);
  EXPECT_DOUBLE_EQ(force[0], 3.0);
  EXPECT_TRUE(ForceSet(scene.model).has_symmetric_jacobians());
}

TEST(SceneLoader, ZeroRestLengthSpringMayStartCollapsed) {
  const Scene scene = load(R"(<scene>
    <duration time="1"/><integrator type="explicit-euler" dt="0.1"/>
    <particle m="1" px="0" py="0" vx="0" vy="0" fixed="1"/>
    <particle m="1" px="0" py="0" vx="1" vy="0" fixed="0"/>
    <edge i="0" j="1"/>
    <springforce edge="0" k="3" l0="0"/>
  </scene>)");
  EXPECT_EQ(scene.model.forces.size(), 1u);
}

TEST(SceneLoader, ReadsThreeDimensionalScenes) {
  const Scene scene = load(R"(<scene dim="3">
    <duration time="1"/><integrator type="implicit-euler" dt="0.1"/>
    <particle m="1" px="1" py="2" pz="3" vx="4" vy="5" vz="6" fixed="0"/>
    <simplegravity fx="0" fy="0" fz="-9.8"/>
  </scene>)");
  EXPECT_EQ(scene.model.dim, 3);
  EXPECT_EQ(scene.initial.q, (Vector(3) << 1, 2, 3).finished());
  EXPECT_EQ(scene.initial.v, (Vector(3) << 4, 5, 6).finished());
  const Vector force = compute_force(ForceSet(scene.model), scene.initial.q, scene.initial.v);
  EXPECT_EQ(force, (Vector(3) << 0, 0, -9.8).finished());
}

TEST(SceneLoader, WarnsAboutUnknownAttributesWithTheirLine) {
  const Scene scene = load(R"(<scene>
    <duration time="1"/><integrator type="explicit-euler" dt="0.1"/>
    <particle m="1" px="0" py="0" vx="0" vy="0" fixed="0" colour="red"/>
  </scene>)");
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_EQ(scene.warnings[0],
            "test.xml:3: warning: <particle> 0: unknown attribute \"colour\" ignored");
}

TEST(SceneLoader, AcceptsAnEmptySceneWithoutParticles) {
  const Scene scene =
      load(R"(<scene><duration time="0"/><integrator type="implicit" dt="1"/></scene>)");
  EXPECT_EQ(scene.model.num_particles(), 0);
  EXPECT_EQ(scene.model.num_steps(), 0);
}

}  // namespace
}  // namespace fosssim
