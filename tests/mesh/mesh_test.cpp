// Springs, lumped masses and surfaces derived from a mesh's elements.

#include "mesh/mesh.h"

#include <gtest/gtest.h>

#include "support/thrown.h"

namespace fosssim {
namespace {

using Pairs = std::vector<std::array<int, 2>>;

/// A unit square as one quad and a triangle hanging off its right side.
Mesh quad_and_triangle() {
  Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0.5, 0}};
  mesh.faces = {{0, 1, 2, 3}, {1, 4, 2}};
  return mesh;
}

/// The tet (0,0,0), (1,0,0), (0,1,0), (0,0,1), volume 1/6.
Mesh unit_tet() {
  Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.tets = {{0, 1, 2, 3}};
  return mesh;
}

TEST(SpringPairs, AQuadGetsItsSidesAndBothDiagonalsAndSharedEdgesCountOnce) {
  Mesh mesh = quad_and_triangle();
  mesh.segments = {{4, 0}, {0, 4}};
  EXPECT_EQ(compute_spring_pairs(mesh),
            (Pairs{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}, {1, 4}, {2, 4}, {0, 4}}));
}

TEST(SpringPairs, ATetGetsItsSixEdges) {
  EXPECT_EQ(compute_spring_pairs(unit_tet()),
            (Pairs{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}));
}

TEST(FaceTriangles, FanEachPolygonFromItsFirstCorner) {
  const auto triangles = compute_face_triangles(quad_and_triangle());
  EXPECT_EQ(triangles, (std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}, {1, 4, 2}}));
}

TEST(TetBoundary, FacesOfOneTetPointOutward) {
  for (bool flipped : {false, true}) {
    Mesh mesh = unit_tet();
    if (flipped) std::swap(mesh.tets[0][2], mesh.tets[0][3]);
    const auto boundary = compute_tet_boundary(mesh);
    ASSERT_EQ(boundary.size(), 4u);
    const Eigen::Vector3d centroid(0.25, 0.25, 0.25);
    for (const auto& f : boundary) {
      const Eigen::Vector3d& a = mesh.vertices[f[0]];
      const Eigen::Vector3d normal = (mesh.vertices[f[1]] - a).cross(mesh.vertices[f[2]] - a);
      EXPECT_GT(normal.dot(a - centroid), 0.0);
    }
  }
}

TEST(TetBoundary, TheSharedFaceOfTwoTetsIsInterior) {
  Mesh mesh = unit_tet();
  mesh.vertices.emplace_back(1, 1, 1);
  mesh.tets.push_back({1, 2, 3, 4});
  EXPECT_EQ(compute_tet_boundary(mesh).size(), 6u);
}

TEST(VertexMasses, AreaMassesSumToAreaTimesDensityAndGoToTheCorners) {
  const std::vector<double> m = compute_vertex_masses(quad_and_triangle(), {MassRule::kArea, 3.0});
  double total = 0.0;
  for (double x : m) total += x;
  EXPECT_DOUBLE_EQ(total, 3.0 * 1.5);
  EXPECT_DOUBLE_EQ(m[4], 3.0 * 0.5 / 3.0);
  EXPECT_DOUBLE_EQ(m[3], 3.0 * 0.5 / 3.0);
  EXPECT_DOUBLE_EQ(m[1], 3.0 * (0.5 / 3.0 + 0.5 / 3.0));
}

TEST(VertexMasses, VolumeUniformAndTotalRules) {
  for (double m : compute_vertex_masses(unit_tet(), {MassRule::kVolume, 600.0})) {
    EXPECT_DOUBLE_EQ(m, 600.0 / 6.0 / 4.0);
  }
  EXPECT_EQ(compute_vertex_masses(unit_tet(), {MassRule::kUniform, 2.5}),
            std::vector<double>(4, 2.5));
  EXPECT_EQ(compute_vertex_masses(unit_tet(), {MassRule::kTotal, 2.0}),
            std::vector<double>(4, 0.5));
}

TEST(VertexMasses, RefuseVerticesThatWouldGetNoMass) {
  Mesh mesh = quad_and_triangle();
  mesh.vertices.emplace_back(5, 5, 5);  // on no face
  const Error error = thrown_by([&] { compute_vertex_masses(mesh, {MassRule::kArea, 1.0}); });
  EXPECT_EQ(error.kind(), ErrorKind::kBadInput);
  EXPECT_NE(std::string(error.what()).find("vertex 5"), std::string::npos) << error.what();
  EXPECT_THROW(compute_vertex_masses(quad_and_triangle(), {MassRule::kVolume, 1.0}), Error);
  EXPECT_THROW(compute_vertex_masses(unit_tet(), {MassRule::kArea, 1.0}), Error);
}

TEST(ExtremeVertices, SelectsWithinADistanceOfTheLowestOrHighest) {
  const Mesh mesh = quad_and_triangle();
  EXPECT_EQ(select_extreme_vertices(mesh, 1, false, 0.0), (std::vector<int>{0, 1}));
  EXPECT_EQ(select_extreme_vertices(mesh, 1, false, 0.5), (std::vector<int>{0, 1, 4}));
  EXPECT_EQ(select_extreme_vertices(mesh, 0, true, 0.1), (std::vector<int>{4}));
}

}  // namespace
}  // namespace fosssim
