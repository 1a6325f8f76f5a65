// Procedural meshes: counts, shapes, orientation and pin sets.

#include "mesh/generators.h"

#include <gtest/gtest.h>

#include <map>
#include <numbers>

namespace fosssim {
namespace {

double total_volume(const Mesh& mesh, double* smallest = nullptr) {
  double total = 0.0, least = 1e300;
  for (const auto& tet : mesh.tets) {
    const double v = compute_tet_volume(mesh, tet);
    total += v;
    least = std::min(least, v);
  }
  if (smallest) *smallest = least;
  return total;
}

/// Every face of the tets is shared by at most two tets, and by two unless on the boundary.
void expect_conforming(const Mesh& mesh) {
  std::map<std::array<int, 3>, int> uses;
  for (const auto& t : mesh.tets) {
    for (const auto& f : {std::array<int, 3>{t[0], t[1], t[2]},
                          {t[0], t[1], t[3]},
                          {t[0], t[2], t[3]},
                          {t[1], t[2], t[3]}}) {
      auto key = f;
      std::sort(key.begin(), key.end());
      ++uses[key];
    }
  }
  std::size_t once = 0;
  for (const auto& [face, count] : uses) {
    EXPECT_LE(count, 2);
    once += count == 1;
  }
  EXPECT_EQ(once, compute_tet_boundary(mesh).size());
}

double boundary_area(const Mesh& mesh) {
  double area = 0.0;
  for (const auto& t : compute_tet_boundary(mesh)) area += compute_triangle_area(mesh, t);
  return area;
}

TEST(GenerateCloth, HasStructuralShearAndBendSprings) {
  const int nx = 7, ny = 5;
  const GeneratedMesh cloth = generate_cloth(nx, ny, 2.0, 1.0, false, true);
  EXPECT_EQ(cloth.mesh.num_vertices(), nx * ny);
  EXPECT_EQ(cloth.mesh.faces.size(), static_cast<std::size_t>((nx - 1) * (ny - 1)));
  const int structural = nx * (ny - 1) + ny * (nx - 1);
  const int shear = 2 * (nx - 1) * (ny - 1);
  const int bend = (nx - 2) * ny + nx * (ny - 2);
  EXPECT_EQ(compute_spring_pairs(cloth.mesh).size(),
            static_cast<std::size_t>(structural + shear + bend));
  EXPECT_EQ(compute_spring_pairs(generate_cloth(nx, ny, 2.0, 1.0, false, false).mesh).size(),
            static_cast<std::size_t>(structural + shear));
  EXPECT_EQ(cloth.mesh.vertices[nx * ny - 1], Eigen::Vector3d(1.0, -1.0, 0.0));
  EXPECT_EQ(*cloth.find_pins("corners"), (std::vector<int>{0, nx - 1}));
  EXPECT_EQ(cloth.find_pins("top-row")->size(), static_cast<std::size_t>(nx));
  EXPECT_EQ(cloth.default_pins, "corners");
  EXPECT_EQ(cloth.find_pins("middle"), nullptr);
  EXPECT_EQ(*cloth.find_pins("left-column"), (std::vector<int>{0, 7, 14, 21, 28}));
  EXPECT_EQ(cloth.pin_set_names(), "corners, top-row, left-column or none");
  const GeneratedMesh flat = generate_cloth(nx, ny, 2.0, 1.0, true, true);
  EXPECT_EQ(flat.mesh.vertices[nx * ny - 1], Eigen::Vector3d(1.0, 0.0, 1.0));
}

TEST(GenerateChainAndNet, HaveTheirSpringsAndPins) {
  const GeneratedMesh chain = generate_chain(10, 2.0);
  EXPECT_EQ(chain.mesh.num_vertices(), 11);
  EXPECT_EQ(compute_spring_pairs(chain.mesh).size(), 10u);
  EXPECT_EQ(chain.mesh.vertices.back(), Eigen::Vector3d(2.0, 0.0, 0.0));
  EXPECT_EQ(*chain.find_pins("ends"), (std::vector<int>{0, 10}));
  const GeneratedMesh net = generate_net(4, 3, 1.0, 1.0);
  EXPECT_EQ(compute_spring_pairs(net.mesh).size(), static_cast<std::size_t>(4 * 2 + 3 * 3));
  EXPECT_TRUE(net.mesh.faces.empty());
  EXPECT_EQ(net.find_pins("corners")->size(), 4u);
  EXPECT_EQ(net.find_pins("border")->size(), 10u);
}

TEST(GenerateSkirt, IsAClosedBandOfRingsPinnedAtTheTop) {
  const GeneratedMesh skirt = generate_skirt(12, 4, 0.5, 1.0, 2.0, true);
  EXPECT_EQ(skirt.mesh.num_vertices(), 48);
  EXPECT_EQ(skirt.mesh.faces.size(), 36u);  // wraps around: 12 quads per band
  const int sides = 12 * 4 + 12 * 3, shear = 2 * 36, bend = 12 * 4 + 12 * 2;
  EXPECT_EQ(compute_spring_pairs(skirt.mesh).size(),
            static_cast<std::size_t>(sides + shear + bend));
  EXPECT_NEAR(skirt.mesh.vertices[36].norm(), std::hypot(1.0, 2.0), 1e-12);
  EXPECT_EQ(skirt.find_pins("top")->size(), 12u);
}

TEST(GenerateTetBox, FillsTheBoxWithPositiveConformingTets) {
  const GeneratedMesh box = generate_tet_box(3, 2, 2, 3.0, 1.0, 2.0);
  EXPECT_EQ(box.mesh.num_vertices(), 4 * 3 * 3);
  EXPECT_EQ(box.mesh.tets.size(), 12u * 6u);
  double smallest = 0.0;
  EXPECT_NEAR(total_volume(box.mesh, &smallest), 6.0, 1e-12);
  EXPECT_GT(smallest, 0.0);
  expect_conforming(box.mesh);
  EXPECT_NEAR(boundary_area(box.mesh), 2.0 * (3.0 + 6.0 + 2.0), 1e-12);
  EXPECT_EQ(box.find_pins("bottom")->size(), 4u * 3u);
  EXPECT_EQ(box.find_pins("left")->size(), 3u * 3u);
  for (int v : *box.find_pins("left")) EXPECT_DOUBLE_EQ(box.mesh.vertices[v].x(), -1.5);
}

TEST(GenerateTetBall, ApproachesTheBallsVolume) {
  const GeneratedMesh ball = generate_tet_ball(12, 0.5);
  double smallest = 0.0;
  const double volume = total_volume(ball.mesh, &smallest);
  EXPECT_GT(smallest, 0.0);
  EXPECT_NEAR(volume, 4.0 / 3.0 * std::numbers::pi * 0.125, 0.08 * 0.5236);
  expect_conforming(ball.mesh);
  for (const auto& x : ball.mesh.vertices)
    EXPECT_LE(x.norm(), 0.5 + std::sqrt(3.0) * (1.0 / 12.0) + 1e-12);
}

}  // namespace
}  // namespace fosssim
