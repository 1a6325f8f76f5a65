// 3D scenes end to end: load, simulate, write the trajectory, grade it.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/step/simulation.h"
#include "grading/grader.h"
#include "io/scene_loader.h"
#include "io/trajectory_file.h"
#include "support/scratch_folder.h"
#include "support/trajectories.h"

namespace fosssim {
namespace {

/// Runs the scene, writes its trajectory, and grades it against the scene.
GradeReport run_and_grade(const Scene& scene, const std::string& path) {
  testing::write_simulated_trajectory(scene, path);
  auto file = TrajectoryReader::open(path, scene.model.num_dofs());
  return grade_trajectory(scene, file);
}

TEST(Scene3D, ParticlesWithZComponentsRunAndGradeWithEveryIntegrator) {
  for (const char* type : {"explicit-euler", "symplectic-euler", "linearized-implicit-euler",
                           "implicit-euler", "local-global", "linearly-implicit-euler"}) {
    const std::string text = std::string(R"(<scene dim="3">
  <duration time="0.5"/>
  <integrator type=")") + type +
                             R"(" dt="0.01"/>
  <particle m="1" px="0" py="0" pz="0" vx="0" vy="0" vz="0" fixed="1"/>
  <particle m="1" px="1" py="0" pz="0.5" vx="0" vy="0.3" vz="-0.2" fixed="0"/>
  <particle m="2" px="1" py="1" pz="0" vx="0.1" vy="0" vz="0.2" fixed="0"/>
  <edge i="0" j="1"/>
  <edge i="1" j="2"/>
  <springforce edge="0" k="10" l0="1"/>
  <springforce edge="1" k="20" l0="0.8"/>
  <simplegravity fx="0" fy="-9.8" fz="0.5"/>
  <constantforce fx="0" fy="0" fz="-0.25"/>
</scene>)";
    const auto scene = load_scene_text(text, "three.xml");
    testing::ScratchFolder dir;
    const GradeReport report = run_and_grade(scene, (dir / "out.bin"));
    EXPECT_TRUE(report.passed()) << type;
    EXPECT_EQ(report.steps, 50);
    EXPECT_EQ(std::filesystem::file_size((dir / "out.bin")), 51u * 2u * 9u * 8u) << type;
  }
}

TEST(Scene3D, MeshScenesFromTheAssetsRunAndGrade) {
  const std::string assets = std::string(FOSSSIM_SOURCE_DIR) + "/assets3d/";
  for (const char* name : {"scenes/cloth_obj.xml", "scenes/tet_box.xml", "json/cloth_9x9.json"}) {
    auto scene = load_scene_file(assets + name);
    scene.model.duration = 10 * scene.model.integrator.dt;
    testing::ScratchFolder dir;
    EXPECT_TRUE(run_and_grade(scene, (dir / "out.bin")).passed()) << name;
  }
}

/// The least distance, over the particles of `state`, of a particle's surface from the
/// obstacles (half-spaces and spheres), in units of its radius: 1 when a particle touches an
/// obstacle, 0 when its centre is on the boundary, negative when its centre is inside.
double least_clearance_in_radii(const SceneModel& model, const State& state) {
  double least = INFINITY;
  for (int p = 0; p < model.num_particles(); ++p) {
    const Eigen::Vector3d x = state.q.segment<3>(3 * p);
    const double r = model.particle_radius[p];
    for (const HalfPlane& plane : model.half_planes) {
      const Eigen::Vector3d n = plane.normal.head<3>().normalized();
      least = std::min(least, (x - plane.point.head<3>()).dot(n) / r);
    }
    for (const Sphere& sphere : model.spheres) {
      least = std::min(least, ((x - sphere.center.head<3>()).norm() - sphere.radius) / r);
    }
  }
  return least;
}

TEST(Scene3D, CollisionScenesKeepEveryParticleOutOfTheObstaclesAndGrade) {
  const std::string assets = std::string(FOSSSIM_SOURCE_DIR) + "/assets3d/collisions/";
  for (const char* name : {"cloth_on_sphere.xml", "balls_in_box.xml", "soft_ball_bounce.xml"}) {
    const Scene scene = load_scene_file(assets + name);
    Simulation simulation(scene.model, scene.initial);
    double least = INFINITY;
    while (!simulation.finished()) {
      simulation.step();
      least = std::min(least, least_clearance_in_radii(scene.model, simulation.state()));
    }
    std::printf("%-22s least clearance %.3f radii\n", name, least);
    // Touching (1) less what penalty contact sinks in; never half a radius in.
    EXPECT_GT(least, 0.5) << name;
    EXPECT_LT(least, 2.0) << name << ": reached an obstacle";
    Scene shorter = load_scene_file(assets + name);
    shorter.model.duration = 20 * scene.model.integrator.dt;
    testing::ScratchFolder dir;
    EXPECT_TRUE(run_and_grade(shorter, (dir / "out.bin")).passed()) << name;
  }
}

TEST(Scene3D, TwoRunsGiveIdenticalBytes) {
  const std::string path = std::string(FOSSSIM_SOURCE_DIR) + "/assets3d/scenes/hanging_cloth.xml";
  auto scene = load_scene_file(path);
  scene.model.duration = 20 * scene.model.integrator.dt;
  std::vector<Vector> finals;
  for (int run = 0; run < 2; ++run) {
    Simulation simulation(scene.model, scene.initial);
    while (!simulation.finished()) simulation.step();
    finals.push_back(simulation.state().q);
  }
  EXPECT_EQ(finals[0], finals[1]);
}

}  // namespace
}  // namespace fosssim
