// Springs, lumped masses and surfaces derived from a mesh's elements.

#include "mesh/mesh.h"

#include <gtest/gtest.h>

#include <cmath>

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

/// One triangle with the given corners.
Mesh triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  Mesh mesh;
  mesh.vertices = {a, b, c};
  mesh.faces = {{0, 1, 2}};
  return mesh;
}

/// The Voronoi area of each corner of a triangle without obtuse angles, by Meyer et al.'s
/// cotangent formula: corner P gets (|PQ|² cot R + |PR|² cot Q) / 8.
std::array<double, 3> cotangent_voronoi_areas(const Mesh& mesh) {
  const auto& x = mesh.vertices;
  const auto cot = [&](int c) {
    const Eigen::Vector3d u = x[(c + 1) % 3] - x[c], w = x[(c + 2) % 3] - x[c];
    return u.dot(w) / u.cross(w).norm();
  };
  std::array<double, 3> areas{};
  for (int p = 0; p < 3; ++p) {
    const int q = (p + 1) % 3, r = (p + 2) % 3;
    areas[p] = ((x[q] - x[p]).squaredNorm() * cot(r) + (x[r] - x[p]).squaredNorm() * cot(q)) / 8;
  }
  return areas;
}

TEST(VoronoiAreas, AcuteTrianglesShareByTheCircumcentre) {
  const Mesh equilateral = triangle({0, 0, 0}, {2, 0, 0}, {1, std::sqrt(3.0), 0});
  for (double share : compute_voronoi_corner_areas(equilateral, {0, 1, 2}))
    EXPECT_NEAR(share, std::sqrt(3.0) / 3.0, 1e-15);
  const Mesh acute = triangle({0.1, -0.2, 0.3}, {2.0, 0.1, -0.4}, {0.9, 1.7, 0.5});
  const auto expected = cotangent_voronoi_areas(acute);
  const auto shares = compute_voronoi_corner_areas(acute, {0, 1, 2});
  double sum = 0.0;
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(shares[c], expected[c], 1e-14) << "corner " << c;
    sum += shares[c];
  }
  EXPECT_NEAR(sum, compute_triangle_area(acute, {0, 1, 2}), 1e-15);
  EXPECT_GT(std::abs(shares[0] - sum / 3.0), 0.01) << "not a third each";
}

TEST(VoronoiAreas, AnObtuseCornerGetsHalfAndTheOthersAQuarter) {
  // Obtuse at corner 1 (the origin).
  const Mesh obtuse = triangle({-2, 0.5, 0}, {0, 0, 0}, {1.5, 0.25, 0});
  const double area = compute_triangle_area(obtuse, {0, 1, 2});
  const auto shares = compute_voronoi_corner_areas(obtuse, {0, 1, 2});
  EXPECT_DOUBLE_EQ(shares[1], area / 2.0);
  EXPECT_DOUBLE_EQ(shares[0], area / 4.0);
  EXPECT_DOUBLE_EQ(shares[2], area / 4.0);
}

TEST(VoronoiAreas, ARightCornerGetsHalfAndTheOthersAQuarterFromEitherSide) {
  // A 3-4-5 triangle, right-angled at corner 2, and the same angle opened or closed by 1e-9:
  // the rule is continuous there, whichever side round-off puts the cosine on.
  for (double tilt : {0.0, 1e-9, -1e-9}) {
    const Mesh right = triangle({3, 0, 0}, {tilt, 4, 0}, {0, 0, 0});
    const double area = compute_triangle_area(right, {0, 1, 2});
    const auto shares = compute_voronoi_corner_areas(right, {0, 1, 2});
    EXPECT_NEAR(shares[2], area / 2.0, 1e-8) << tilt;
    EXPECT_NEAR(shares[0], area / 4.0, 1e-8) << tilt;
    EXPECT_NEAR(shares[1], area / 4.0, 1e-8) << tilt;
  }
}

TEST(VertexMasses, VoronoiMassesFanPolygonsAndSumToAreaTimesDensity) {
  // quad_and_triangle: the unit square fans into two right isosceles triangles (0,1,2) and
  // (0,2,3), right-angled at 1 and 3; the triangle (1,4,2) is acute with sides √1.25, 1, √1.25.
  const std::vector<double> m =
      compute_vertex_masses(quad_and_triangle(), {MassRule::kVoronoi, 3.0});
  const Mesh side = triangle({1, 0, 0}, {2, 0.5, 0}, {1, 1, 0});
  const auto acute = cotangent_voronoi_areas(side);
  EXPECT_NEAR(m[0], 3.0 * (0.5 / 4 + 0.5 / 4), 1e-15);
  EXPECT_NEAR(m[1], 3.0 * (0.5 / 2 + acute[0]), 1e-15);
  EXPECT_NEAR(m[2], 3.0 * (0.5 / 4 + 0.5 / 4 + acute[2]), 1e-15);
  EXPECT_NEAR(m[3], 3.0 * (0.5 / 2), 1e-15);
  EXPECT_NEAR(m[4], 3.0 * acute[1], 1e-15);
  double total = 0.0;
  for (double x : m) total += x;
  EXPECT_NEAR(total, 3.0 * 1.5, 1e-14);
  // Barycentric lumping gives the right corners a third instead.
  EXPECT_NE(m[3], compute_vertex_masses(quad_and_triangle(), {MassRule::kArea, 3.0})[3]);
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
  EXPECT_THROW(compute_vertex_masses(unit_tet(), {MassRule::kVoronoi, 1.0}), Error);
  const Error voronoi = thrown_by([&] { compute_vertex_masses(mesh, {MassRule::kVoronoi, 1.0}); });
  EXPECT_NE(std::string(voronoi.what()).find("vertex 5"), std::string::npos) << voronoi.what();
}

TEST(ExtremeVertices, SelectsWithinADistanceOfTheLowestOrHighest) {
  const Mesh mesh = quad_and_triangle();
  EXPECT_EQ(select_extreme_vertices(mesh, 1, false, 0.0), (std::vector<int>{0, 1}));
  EXPECT_EQ(select_extreme_vertices(mesh, 1, false, 0.5), (std::vector<int>{0, 1, 4}));
  EXPECT_EQ(select_extreme_vertices(mesh, 0, true, 0.1), (std::vector<int>{4}));
}

}  // namespace
}  // namespace fosssim
