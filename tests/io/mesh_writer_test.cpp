// Written meshes read back exactly.

#include "io/mesh_writer.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "io/medit_reader.h"
#include "io/obj_reader.h"
#include "mesh/generators.h"
#include "support/scratch_folder.h"
#include "support/thrown.h"

namespace fosssim {
namespace {

TEST(MeshWriter, ObjRoundTripKeepsVerticesFacesAndSprings) {
  testing::ScratchFolder dir;
  const Mesh skirt = generate_skirt(9, 4, 0.3, 0.7, 1.1, true).mesh;  // irrational coordinates
  const std::string path = (dir / "skirt.obj");
  write_obj_file(path, skirt);
  EXPECT_FALSE(std::filesystem::exists(path + ".partial"));
  const auto read = read_obj_file(path);
  EXPECT_EQ(read.vertices, skirt.vertices);
  EXPECT_EQ(read.faces, skirt.faces);
  EXPECT_EQ(compute_spring_pairs(read), compute_spring_pairs(skirt));
}

TEST(MeshWriter, MeditRoundTripKeepsVerticesAndTets) {
  testing::ScratchFolder dir;
  const Mesh ball = generate_tet_ball(5, 0.7).mesh;
  const std::string path = (dir / "ball.mesh");
  write_medit_file(path, ball);
  const auto read = read_medit_file(path);
  EXPECT_EQ(read.vertices, ball.vertices);
  EXPECT_EQ(read.tets, ball.tets);
}

TEST(MeshWriter, ReportsAnUnwritablePath) {
  testing::ScratchFolder dir;
  const Error error = thrown_by(
      [&] { write_obj_file((dir / "missing/dir/cloth.obj"), generate_chain(2, 1.0).mesh); });
  EXPECT_EQ(error.kind(), ErrorKind::kCannotWrite);
  EXPECT_NE(std::string(error.what()).find("cannot create"), std::string::npos) << error.what();
}

}  // namespace
}  // namespace fosssim
