// A mesh becomes particles, edges, springs and surfaces of a scene.

#include "mesh/mesh_scene.h"

#include <gtest/gtest.h>

#include "core/forces/spring_set_force.h"
#include "mesh/generators.h"
#include "support/thrown.h"

namespace fosssim {
namespace {

TEST(AppendMesh, AddsParticlesAfterExistingOnesWithSpringsAtRest) {
  Scene scene;
  scene.model.dim = 3;
  scene.model.mass = Vector::Constant(3, 5.0);  // one particle already there
  scene.model.fixed = {false};
  scene.initial.q = Vector::Zero(3);
  scene.initial.v = Vector::Zero(3);
  scene.particle_tags = {""};
  scene.model.particle_radius = {0.1};
  scene.appearance.particle_color = {Appearance::kDefaultParticleColor};
  const GeneratedMesh cloth = generate_cloth(3, 3, 1.0, 1.0, false, false);
  MeshMaterial material;
  material.k = 7.0;
  material.b = 0.5;
  material.mass = {MassRule::kArea, 2.0};
  material.velocity = Eigen::Vector3d(0.0, 0.0, 1.0);
  const auto force = append_mesh(scene, cloth.mesh, material, {0, 2}, "cloth");
  EXPECT_EQ(scene.model.num_particles(), 10);
  EXPECT_TRUE(scene.model.fixed[1] && scene.model.fixed[3] && !scene.model.fixed[2]);
  EXPECT_EQ(scene.initial.q.segment<3>(3 * 9), Eigen::Vector3d(0.5, -1.0, 0.0));
  EXPECT_EQ(scene.initial.v.segment<3>(3 * 9), Eigen::Vector3d(0.0, 0.0, 1.0));
  EXPECT_EQ(scene.initial.v.segment<3>(3 * 1), Eigen::Vector3d::Zero()) << "pins start at rest";
  EXPECT_DOUBLE_EQ(scene.model.mass.tail(27).sum() / 3.0, 2.0);  // 1 m² at 2 kg/m²
  EXPECT_EQ(scene.model.mass[0], 5.0);
  const auto* set = dynamic_cast<const SpringSetForce<3>*>(force.get());
  ASSERT_NE(set, nullptr);
  const std::vector<SpringTerm>& springs = set->springs();
  ASSERT_EQ(springs.size(), 12u + 8u);
  ASSERT_EQ(scene.model.edges.size(), springs.size());
  for (std::size_t s = 0; s < springs.size(); ++s) {
    EXPECT_EQ(scene.model.edges[s].i, springs[s].i);
    const double length = (scene.initial.q.segment<3>(3 * springs[s].i) -
                           scene.initial.q.segment<3>(3 * springs[s].j))
                              .norm();
    EXPECT_EQ(springs[s].l0, length);
    EXPECT_EQ(springs[s].k, 7.0);
    EXPECT_EQ(springs[s].b, 0.5);
  }
  EXPECT_EQ(scene.appearance.triangles.size(), 8u);
  EXPECT_EQ(scene.appearance.triangles[0][0], 1);
  EXPECT_EQ(scene.model.particle_radius.size(), 10u);
  EXPECT_EQ(scene.particle_tags.size(), 10u);
}

TEST(AppendMesh, TetMeshesGetTheirBoundaryToDraw) {
  Scene scene;
  scene.model.dim = 3;
  MeshMaterial material;
  material.k = 1.0;
  material.mass = {MassRule::kVolume, 1000.0};
  append_mesh(scene, generate_tet_box(2, 1, 1, 2.0, 1.0, 1.0).mesh, material, {}, "box");
  EXPECT_EQ(scene.appearance.triangles.size(), 2u * (2 + 2 + 1 + 1 + 2 + 2));
  EXPECT_DOUBLE_EQ(scene.model.mass.sum() / 3.0, 2000.0);
}

TEST(AppendMesh, ListsTheTetMeshesInteriorVerticesAndGivesVerticesTheMeshColour) {
  Scene scene;
  scene.model.dim = 3;
  scene.model.mass = Vector::Ones(3);
  scene.model.fixed = {false};
  scene.initial.q = Vector::Zero(3);
  scene.initial.v = Vector::Zero(3);
  scene.model.particle_radius = {0.1};
  scene.appearance.particle_color = {Appearance::kDefaultParticleColor};
  MeshMaterial material;
  material.k = 1.0;
  // 3 × 3 × 3 vertices centred on the origin; only the centre is inside.
  append_mesh(scene, generate_tet_box(2, 2, 2, 1.0, 1.0, 1.0).mesh, material, {}, "box");
  ASSERT_EQ(scene.appearance.interior_particles.size(), 1u);
  const int centre = scene.appearance.interior_particles[0];
  EXPECT_GE(centre, 1) << "numbered after particle 0";
  EXPECT_EQ(scene.initial.q.segment<3>(3 * centre), Eigen::Vector3d::Zero());
  EXPECT_EQ(scene.appearance.particle_color[0], Appearance::kDefaultParticleColor);
  EXPECT_EQ(scene.appearance.particle_color[centre], Appearance::kDefaultMeshColor);
  Scene cloth;
  cloth.model.dim = 3;
  append_mesh(cloth, generate_cloth(3, 3, 1.0, 1.0, true, false).mesh, material, {}, "cloth");
  EXPECT_TRUE(cloth.appearance.interior_particles.empty());
}

TEST(AppendMesh, RefusesBadMeshesWithoutChangingTheScene) {
  MeshMaterial material;
  material.k = 1.0;
  Mesh twins;
  twins.vertices = {{0, 0, 0}, {0, 0, 0}};
  twins.segments = {{0, 1}};
  Scene scene;
  scene.model.dim = 3;
  const auto problem = [&](Scene& into, const Mesh& mesh, const std::vector<int>& pins) {
    return std::string(thrown_by([&] { append_mesh(into, mesh, material, pins, "m"); }).what());
  };
  EXPECT_NE(problem(scene, twins, {}).find("coincide"), std::string::npos);
  EXPECT_NE(problem(scene, generate_chain(2, 1.0).mesh, {3}).find("pinned vertex 3"),
            std::string::npos);
  EXPECT_EQ(scene.model.num_particles(), 0);

  Scene flat;  // 2D
  EXPECT_NO_THROW(append_mesh(flat, generate_chain(2, 1.0).mesh, material, {0}, "chain"));
  const std::string raised = problem(flat, generate_cloth(2, 2, 1.0, 1.0, true, false).mesh, {});
  EXPECT_NE(raised.find("2D"), std::string::npos)
      << "a cloth in the xz plane has z ≠ 0: " << raised;
  EXPECT_EQ(flat.model.num_particles(), 3);
}

}  // namespace
}  // namespace fosssim
