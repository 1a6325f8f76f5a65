// The elastic-body shapes (mesh/elastic_shapes.h) and the polygon triangulator: counts from the
// closed forms, every triangle counter-clockwise and of positive area, Euler characteristics,
// hinges at the rod's interior vertices, triangulations that cover the polygon (less its holes)
// exactly, keep its sides and are (constrained) Delaunay, lumped masses that sum to the total,
// and the limits.

#include "mesh/elastic_shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <set>

#include "core/error.h"
#include "mesh/elastic_body.h"
#include "support/thrown.h"

namespace fosssim {
namespace {

using Points = std::vector<Eigen::Vector2d>;

/// What `action` threw, as text.
template <typename Action>
std::string thrown_message(Action&& action) {
  return thrown_by(std::forward<Action>(action)).what();
}

double twice_area(const ElasticShape& s, const std::array<int, 3>& t) {
  return orientation(s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]);
}

/// Every triangle counter-clockwise and non-degenerate, every index in range, no triangle twice.
void expect_valid_triangles(const ElasticShape& s) {
  std::set<std::array<int, 3>> seen;
  for (const auto& t : s.triangles) {
    for (const int v : t) {
      ASSERT_GE(v, 0);
      ASSERT_LT(v, s.num_vertices());
    }
    EXPECT_GT(twice_area(s, t), 0.0) << t[0] << " " << t[1] << " " << t[2];
    auto sorted = t;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_TRUE(seen.insert(sorted).second);
  }
}

/// Each edge is the side of one triangle (boundary) or two with opposite directions (interior):
/// the triangles form a consistently oriented surface with boundary.
void expect_manifold(const ElasticShape& s) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : s.triangles) {
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed)
    EXPECT_EQ(count, 1) << edge.first << "-" << edge.second;
}

int euler_characteristic(const ElasticShape& s) {
  return s.num_vertices() - static_cast<int>(s.edges.size()) + static_cast<int>(s.triangles.size());
}

double total_area(const ElasticShape& s) {
  double sum = 0.0;
  for (const auto& t : s.triangles) sum += 0.5 * twice_area(s, t);
  return sum;
}

double polygon_area(const Points& outline) {
  double twice = 0.0;
  for (std::size_t k = 0; k < outline.size(); ++k) {
    const auto& a = outline[k];
    const auto& b = outline[(k + 1) % outline.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * std::abs(twice);
}

/// No interior edge is illegal: the far corner of each neighbour lies on or outside the
/// circumcircle of the triangle, up to round-off (a constrained Delaunay triangulation whose
/// constraints are the outline).
void expect_delaunay(const ElasticShape& s) {
  std::map<std::pair<int, int>, std::pair<int, int>> opposite;  // directed side -> (tri, corner)
  for (int t = 0; t < static_cast<int>(s.triangles.size()); ++t) {
    const auto& tri = s.triangles[t];
    for (int k = 0; k < 3; ++k) opposite[{tri[(k + 1) % 3], tri[(k + 2) % 3]}] = {t, k};
  }
  for (const auto& [side, where] : opposite) {
    const auto other = opposite.find({side.second, side.first});
    if (other == opposite.end()) continue;
    const auto& tri = s.triangles[where.first];
    const Eigen::Vector2d a = s.vertices[tri[0]], b = s.vertices[tri[1]], c = s.vertices[tri[2]];
    const Eigen::Vector2d d = s.vertices[s.triangles[other->second.first][other->second.second]];
    // Circumcentre of (a, b, c), then compare distances.
    const double D = 2.0 * orientation(a, b, c);
    const double ux = (a.squaredNorm() * (b.y() - c.y()) + b.squaredNorm() * (c.y() - a.y()) +
                       c.squaredNorm() * (a.y() - b.y())) /
                      D;
    const double uy = (a.squaredNorm() * (c.x() - b.x()) + b.squaredNorm() * (a.x() - c.x()) +
                       c.squaredNorm() * (b.x() - a.x())) /
                      D;
    const Eigen::Vector2d centre(ux, uy);
    const double r = (a - centre).norm();
    EXPECT_GE((d - centre).norm(), r * (1.0 - 1e-9))
        << "illegal edge " << side.first << "-" << side.second;
  }
}

TEST(ElasticSheet, HasTheClosedFormCountsAndIsADisc) {
  for (const auto diagonals : {SheetDiagonals::kAlternating, SheetDiagonals::kParallel}) {
    const ElasticShape s = make_sheet(5, 3, 2.0, 1.0, diagonals);
    EXPECT_EQ(s.num_vertices(), 6 * 4);
    EXPECT_EQ(s.triangles.size(), 2u * 5 * 3);
    // Horizontal 5·4 + vertical 6·3 + one diagonal per cell.
    EXPECT_EQ(s.edges.size(), 5u * 4 + 6u * 3 + 5u * 3);
    EXPECT_EQ(euler_characteristic(s), 1);
    EXPECT_TRUE(s.hinges.empty());
    expect_valid_triangles(s);
    expect_manifold(s);
    EXPECT_NEAR(total_area(s), 2.0, 1e-15);
    EXPECT_EQ(s.vertices[6 * 4 - 1], Eigen::Vector2d(2.0, 1.0));
  }
}

TEST(ElasticSheet, DiagonalPatternsAreTheDocumentedOnes) {
  // Cell (0, 0): a = 0, b = 1, d = 4, e = 3 in a 2 × 1 sheet.
  const ElasticShape alternating = make_sheet(2, 1, 2.0, 1.0, SheetDiagonals::kAlternating);
  EXPECT_EQ(alternating.triangles[0], (std::array<int, 3>{0, 1, 4}));
  EXPECT_EQ(alternating.triangles[1], (std::array<int, 3>{0, 4, 3}));
  EXPECT_EQ(alternating.triangles[2], (std::array<int, 3>{1, 2, 4}));  // cell (0, 1): cut b–e
  EXPECT_EQ(alternating.triangles[3], (std::array<int, 3>{2, 5, 4}));
  const ElasticShape parallel = make_sheet(2, 1, 2.0, 1.0, SheetDiagonals::kParallel);
  EXPECT_EQ(parallel.triangles[2], (std::array<int, 3>{1, 2, 5}));
}

TEST(ElasticRod, HingesAreTheInteriorVerticesBetweenConsecutiveSegments) {
  const ElasticShape rod = make_rod(6, 3.0);
  EXPECT_EQ(rod.num_vertices(), 7);
  EXPECT_EQ(rod.edges.size(), 6u);
  ASSERT_EQ(rod.hinges.size(), 5u);
  EXPECT_TRUE(rod.is_rod());
  std::set<std::array<int, 2>> segments(rod.edges.begin(), rod.edges.end());
  for (std::size_t h = 0; h < rod.hinges.size(); ++h) {
    const auto [a, b, c] = rod.hinges[h];
    EXPECT_EQ(b, static_cast<int>(h) + 1);  // every interior vertex once, in order
    EXPECT_TRUE(segments.count({std::min(a, b), std::max(a, b)}));
    EXPECT_TRUE(segments.count({std::min(b, c), std::max(b, c)}));
    EXPECT_NE(a, c);
  }
  EXPECT_EQ(rod.vertices.back(), Eigen::Vector2d(3.0, 0.0));
}

TEST(ElasticRing, AClosedRodHasAHingeAtEveryVertexTurningByTwoPiOverN) {
  const int n = 12;
  const ElasticShape ring = make_ring_rod(n, 2.0);
  EXPECT_EQ(ring.num_vertices(), n);
  EXPECT_EQ(ring.edges.size(), static_cast<std::size_t>(n));
  ASSERT_EQ(ring.hinges.size(), static_cast<std::size_t>(n));
  // V - E = 0 for a closed curve.
  EXPECT_EQ(ring.num_vertices() - static_cast<int>(ring.edges.size()), 0);
  for (const auto& [a, b, c] : ring.hinges) {
    EXPECT_NEAR(hinge_angle(ring.vertices[a], ring.vertices[b], ring.vertices[c]),
                2.0 * std::numbers::pi / n, 1e-14);
  }
}

TEST(ElasticRing, AnAnnulusHasEulerCharacteristicZero) {
  const ElasticShape annulus = make_annulus(16, 3, 0.5, 1.0);
  EXPECT_EQ(annulus.num_vertices(), 16 * 4);
  EXPECT_EQ(annulus.triangles.size(), 2u * 16 * 3);
  EXPECT_EQ(euler_characteristic(annulus), 0);
  expect_valid_triangles(annulus);
  expect_manifold(annulus);
  // The inscribed polygons' area: n/2 sin(2π/n) (R² - r²).
  EXPECT_NEAR(total_area(annulus), 8.0 * std::sin(2.0 * std::numbers::pi / 16) * 0.75, 1e-13);
}

/// A polygon's triangulation: valid, a disc, covering exactly the polygon's area, with every
/// given corner a vertex, Delaunay.
void expect_good_polygon(const Points& outline, double spacing) {
  const ElasticShape s = make_polygon(outline, spacing);
  SCOPED_TRACE(::testing::Message() << s.num_vertices() << " vertices");
  expect_valid_triangles(s);
  expect_manifold(s);
  EXPECT_EQ(euler_characteristic(s), 1);
  EXPECT_NEAR(total_area(s), polygon_area(outline), 1e-12 * polygon_area(outline));
  std::vector<char> used(s.num_vertices(), 0);
  for (const auto& t : s.triangles)
    for (const int v : t) used[v] = 1;
  for (int v = 0; v < s.num_vertices(); ++v) EXPECT_TRUE(used[v]) << "vertex " << v;
  expect_delaunay(s);
}

const Points kArrow = {{0, 0}, {4, 0}, {4, 1}, {2, 0.5}, {1, 3}, {0, 1}};
const Points kComb = {{0, 0}, {5, 0}, {5, 2},   {4, 2},   {4, 0.5}, {3, 0.5},
                      {3, 2}, {2, 2}, {2, 0.5}, {1, 0.5}, {1, 2},   {0, 2}};

TEST(ElasticPolygon, TriangulatesConvexAndConcaveOutlinesWithAndWithoutInteriorPoints) {
  expect_good_polygon({{0, 0}, {1, 0}, {0, 1}}, 0.0);
  expect_good_polygon({{0, 0}, {2, 0}, {2, 1}, {0, 1}}, 0.0);
  expect_good_polygon({{0, 0}, {2, 0}, {2, 1}, {0, 1}}, 0.25);  // a regular grid: cocircular
  expect_good_polygon(kArrow, 0.0);
  expect_good_polygon(kArrow, 0.3);
  expect_good_polygon(kComb, 0.0);
  expect_good_polygon(kComb, 0.2);
  Points circle;
  for (int k = 0; k < 40; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 40;
    circle.emplace_back(std::cos(a), std::sin(a));
  }
  expect_good_polygon(circle, 0.0);
  expect_good_polygon(circle, 0.1);
}

TEST(ElasticPolygon, TriangulatesRandomStarShapedOutlines) {
  std::mt19937 random(19);
  std::uniform_real_distribution<double> radius(0.3, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 5 + trial;
    Points outline;
    for (int k = 0; k < n; ++k) {
      const double a = 2.0 * std::numbers::pi * k / n;
      const double r = radius(random);
      outline.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    SCOPED_TRACE(::testing::Message() << "trial " << trial);
    expect_good_polygon(outline, 0.0);
    expect_good_polygon(outline, 0.05 + 0.005 * trial);
  }
}

TEST(ElasticPolygon, EitherOrientationGivesTheSameCounterClockwiseOutlineFromCornerZero) {
  Points clockwise = kArrow;
  std::reverse(clockwise.begin() + 1, clockwise.end());
  const ElasticShape a = make_polygon(kArrow, 0.3);
  const ElasticShape b = make_polygon(clockwise, 0.3);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.triangles, b.triangles);
}

TEST(ElasticPolygon, SpacingCutsSidesAndFillsTheInterior) {
  const ElasticShape s = make_polygon({{0, 0}, {2, 0}, {2, 1}, {0, 1}}, 0.25);
  // Sides of 2 and 1 cut into 8 and 4 pieces: 7 + 3 + 7 + 3 cut points; grid of 9 × 5 points,
  // of which the 7 × 3 inner ones are at least 0.125 from the sides.
  EXPECT_EQ(s.num_vertices(), 4 + 20 + 21);
  for (const auto& t : s.triangles) {
    for (int k = 0; k < 3; ++k)
      EXPECT_LE((s.vertices[t[k]] - s.vertices[t[(k + 1) % 3]]).norm(),
                0.25 * std::sqrt(2.0) + 1e-12);
  }
}

TEST(ElasticPolygon, RefusesOutlinesThatAreNotSimplePolygons) {
  const auto problem = [](const Points& outline) {
    return thrown_message([&] { make_polygon(outline, 0.0); });
  };
  EXPECT_EQ(problem({{0, 0}, {1, 0}}), "a polygon needs at least 3 corners, found 2");
  EXPECT_EQ(problem({{0, 0}, {1, 0}, {1, 1}, {1, 0}}), "corners 1 and 3 are the same point");
  EXPECT_EQ(problem({{0, 0}, {1, 0}, {0, 1}, {1, 1}}),
            "side 1 (corners 1–2) and side 3 (corners 3–0) cross or touch: the polygon is not "
            "simple");
  EXPECT_EQ(problem({{0, 0}, {2, 0}, {1, 0}, {1, 1}}),
            "the sides from corner 0 to 2 fold back over each other");
  EXPECT_EQ(problem({{0, 0}, {1, 0}, {2, 0}}),
            "the sides from corner 1 to 0 fold back over each other");
}

// --- Polygons with holes ---

using Holes = std::vector<Points>;

/// x strictly inside the closed polygon `loop` (even-odd rule; x on no side).
bool strictly_inside(const Points& loop, const Eigen::Vector2d& x) {
  bool inside = false;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const auto& a = loop[k];
    const auto& b = loop[(k + 1) % loop.size()];
    if ((a.y() > x.y()) != (b.y() > x.y()) &&
        x.x() < a.x() + (x.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
      inside = !inside;
  }
  return inside;
}

/// Distance from x to the segment [a, b].
double distance_to_side(const Eigen::Vector2d& x, const Eigen::Vector2d& a,
                        const Eigen::Vector2d& b) {
  const Eigen::Vector2d side = b - a;
  const double t = std::clamp((x - a).dot(side) / side.squaredNorm(), 0.0, 1.0);
  return (a + t * side - x).norm();
}

/// Every side of every loop, split at the vertices that lie on it, is a side of exactly one
/// triangle, and these pieces are all the sides with one triangle: the triangulation keeps the
/// outline and the holes (constrained) and has no other boundary. Found from the geometry
/// alone: the vertices within 1e-12 of the side's size of its segment, sorted along it.
void expect_sides_kept(const ElasticShape& s, const std::vector<Points>& loops) {
  std::map<std::pair<int, int>, int> count;  // undirected side -> triangles
  for (const auto& t : s.triangles) {
    for (int k = 0; k < 3; ++k)
      ++count[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  }
  std::size_t pieces = 0;
  for (const Points& loop : loops) {
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Eigen::Vector2d a = loop[k], b = loop[(k + 1) % loop.size()];
      std::vector<std::pair<double, int>> on;
      for (int v = 0; v < s.num_vertices(); ++v) {
        if (distance_to_side(s.vertices[v], a, b) <= 1e-12 * (b - a).norm())
          on.push_back({(s.vertices[v] - a).dot(b - a), v});
      }
      std::sort(on.begin(), on.end());
      ASSERT_GE(on.size(), 2u);
      for (std::size_t j = 0; j + 1 < on.size(); ++j) {
        const int u = on[j].second, w = on[j + 1].second;
        const auto found = count.find({std::min(u, w), std::max(u, w)});
        EXPECT_TRUE(found != count.end() && found->second == 1)
            << "side piece " << u << "-" << w << " is not the side of exactly one triangle";
        ++pieces;
      }
    }
  }
  std::size_t boundary = 0;
  for (const auto& [side, n] : count) boundary += n == 1 ? 1 : 0;
  EXPECT_EQ(boundary, pieces);
}

/// A polygon with holes triangulated: valid, consistently oriented, Euler characteristic
/// 1 − holes, covering exactly the outline's area minus the holes', no triangle's centroid in a
/// hole, no vertex in a hole or nearer than spacing/2 to a side unless on it, the sides kept,
/// every vertex used, constrained Delaunay.
ElasticShape expect_good_polygon_with_holes(const Points& outline, const Holes& holes,
                                            double spacing) {
  const ElasticShape s = make_polygon(outline, holes, spacing);
  SCOPED_TRACE(::testing::Message() << s.num_vertices() << " vertices");
  expect_valid_triangles(s);
  expect_manifold(s);
  EXPECT_EQ(euler_characteristic(s), 1 - static_cast<int>(holes.size()));
  double area = polygon_area(outline);
  for (const Points& hole : holes) area -= polygon_area(hole);
  EXPECT_NEAR(total_area(s), area, 1e-12 * polygon_area(outline));
  for (const auto& t : s.triangles) {
    const Eigen::Vector2d centroid = (s.vertices[t[0]] + s.vertices[t[1]] + s.vertices[t[2]]) / 3;
    EXPECT_TRUE(strictly_inside(outline, centroid));
    for (const Points& hole : holes) EXPECT_FALSE(strictly_inside(hole, centroid));
  }
  std::vector<Points> loops = {outline};
  loops.insert(loops.end(), holes.begin(), holes.end());
  std::size_t corners = 0, cuts = 0;
  for (const Points& loop : loops) {
    corners += loop.size();
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const double length = (loop[(k + 1) % loop.size()] - loop[k]).norm();
      cuts += spacing > 0.0 ? static_cast<std::size_t>(std::ceil(length / spacing)) - 1 : 0;
    }
  }
  for (int v = static_cast<int>(corners + cuts); v < s.num_vertices(); ++v) {  // grid points
    for (const Points& hole : holes) EXPECT_FALSE(strictly_inside(hole, s.vertices[v])) << v;
    for (const Points& loop : loops) {
      for (std::size_t k = 0; k < loop.size(); ++k)
        EXPECT_GE(distance_to_side(s.vertices[v], loop[k], loop[(k + 1) % loop.size()]),
                  0.5 * spacing);
    }
  }
  expect_sides_kept(s, loops);
  std::vector<char> used(s.num_vertices(), 0);
  for (const auto& t : s.triangles)
    for (const int v : t) used[v] = 1;
  for (int v = 0; v < s.num_vertices(); ++v) EXPECT_TRUE(used[v]) << "vertex " << v;
  expect_delaunay(s);
  return s;
}

/// n corners on the circle of `radius` around `centre`, counter-clockwise from angle `phase`.
Points circle_loop(const Eigen::Vector2d& centre, double radius, int n, double phase = 0.0) {
  Points loop;
  for (int k = 0; k < n; ++k) {
    const double a = phase + 2.0 * std::numbers::pi * k / n;
    loop.push_back(centre + radius * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  return loop;
}

Points square_loop(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// A letter A: its outline and its triangular counter.
const Points kLetterA = {{0, 0}, {1, 0}, {1.3, 1}, {2.7, 1}, {3, 0}, {4, 0}, {2.5, 5}, {1.5, 5}};
const Points kLetterACounter = {{1.6, 2}, {2.4, 2}, {2, 3.6}};

TEST(ElasticPolygonHoles, TriangulatesPlatesLettersAndWrenchesWithAndWithoutInteriorPoints) {
  const Points plate = square_loop(0, 0, 4, 4);
  for (const double spacing : {0.0, 0.5, 0.3, 0.13}) {
    SCOPED_TRACE(::testing::Message() << "spacing " << spacing);
    // Corners of the hole on the plate's diagonals: bridges collinear with other corners.
    expect_good_polygon_with_holes(plate, {square_loop(1, 1, 3, 3)}, spacing);
    // Two holes of the same largest x, a square and a 24-gon.
    expect_good_polygon_with_holes(
        plate, {square_loop(0.5, 0.5, 1.5, 3.5), circle_loop({2.8, 2}, 0.7, 24)}, spacing);
    expect_good_polygon_with_holes(kLetterA, {kLetterACounter}, spacing);
    expect_good_polygon_with_holes(kComb, {square_loop(0.3, 0.1, 4.7, 0.4)}, spacing);
    // A wrench: a bar with a ring at each end, each ring around a hexagonal hole.
    Points wrench = circle_loop({0, 0}, 1.0, 16, 0.3);
    std::reverse(wrench.begin(), wrench.end());
    expect_good_polygon_with_holes(
        {{-1.2, -0.4},
         {6.2, -0.4},
         {6.2, -1},
         {8, -1},
         {8, 1},
         {6.2, 1},
         {6.2, 0.4},
         {-1.2, 0.4},
         {-1.2, 1},
         {-3, 1},
         {-3, -1},
         {-1.2, -1}},
        {circle_loop({-2.1, 0}, 0.5, 6), circle_loop({7.1, 0}, 0.5, 6, 0.5),
         circle_loop({2.5, 0}, 0.2, 8)},
        spacing);
  }
}

TEST(ElasticPolygonHoles, TriangulatesAGridOfHolesWhoseCornersLineUp) {
  // 5 × 4 square holes in rows and columns: many holes of the same largest x, bridges that
  // would run along other holes' sides.
  Holes holes;
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 4; ++j)
      holes.push_back(square_loop(1 + 2 * i, 1 + 2 * j, 2 + 2 * i, 2 + 2 * j));
  }
  for (const double spacing : {0.0, 0.25, 0.2}) {
    SCOPED_TRACE(::testing::Message() << "spacing " << spacing);
    expect_good_polygon_with_holes(square_loop(0, 0, 11, 9), holes, spacing);
  }
}

TEST(ElasticPolygonHoles, TriangulatesRandomHolesInRandomStarShapedOutlines) {
  std::mt19937 random(29);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int tested = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 8 + trial % 30;
    Points outline;
    for (int k = 0; k < n; ++k) {
      const double a = 2.0 * std::numbers::pi * k / n;
      const double r = 2.0 + unit(random);
      outline.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    // Holes in the disc of radius 1.8 (inside every outline), apart from each other.
    Holes holes;
    std::vector<std::pair<Eigen::Vector2d, double>> discs;
    for (int attempt = 0; attempt < 12; ++attempt) {
      const double rho = 1.5 * std::sqrt(unit(random)),
                   angle = 2.0 * std::numbers::pi * unit(random);
      const Eigen::Vector2d centre(rho * std::cos(angle), rho * std::sin(angle));
      const double radius = 0.08 + 0.25 * unit(random);
      if (centre.norm() + radius > 1.8) continue;
      bool apart = true;
      for (const auto& [c, r] : discs) apart = apart && (c - centre).norm() > r + radius + 0.01;
      if (!apart) continue;
      discs.push_back({centre, radius});
      Points hole;
      const int corners = 3 + static_cast<int>(unit(random) * 9);
      for (int k = 0; k < corners; ++k) {  // star-shaped, either orientation
        const double a = 2.0 * std::numbers::pi * (k + 0.4 * unit(random)) / corners;
        hole.push_back(centre + radius * (0.5 + 0.5 * unit(random)) *
                                    Eigen::Vector2d(std::cos(a), std::sin(a)));
      }
      if (attempt % 2 == 1) std::reverse(hole.begin(), hole.end());
      holes.push_back(hole);
    }
    SCOPED_TRACE(::testing::Message() << "trial " << trial << ", " << holes.size() << " holes");
    expect_good_polygon_with_holes(outline, holes, 0.0);
    expect_good_polygon_with_holes(outline, holes, 0.08 + 0.004 * trial);
    tested += static_cast<int>(holes.size());
  }
  EXPECT_GT(tested, 200);  // the random holes did not all miss
}

TEST(ElasticPolygonHoles, NumberTheOutlineThenEachHoleClockwiseThenCutsThenTheGrid) {
  const Points plate = square_loop(0, 0, 3, 2);
  Points hole = square_loop(1, 0.5, 2, 1.5);  // counter-clockwise: turned from its corner 0
  const ElasticShape s = make_polygon(plate, {hole}, 0.5);
  // Sides 3, 2, 3, 2 cut in 6, 4, 6, 4 pieces; the hole's sides of 1 in 2 pieces each.
  ASSERT_GE(s.num_vertices(), 8 + 16 + 4);
  EXPECT_EQ(Points(s.vertices.begin(), s.vertices.begin() + 8),
            (Points{{0, 0}, {3, 0}, {3, 2}, {0, 2}, {1, 0.5}, {1, 1.5}, {2, 1.5}, {2, 0.5}}));
  EXPECT_EQ(s.vertices[8], Eigen::Vector2d(0.5, 0));     // first cut of the outline's side 0
  EXPECT_EQ(s.vertices[24], Eigen::Vector2d(1, 1));      // the cut of the hole's side 0
  EXPECT_EQ(s.vertices[27], Eigen::Vector2d(1.5, 0.5));  // the cut of its side 3
  // Either orientation of a hole gives the same body.
  std::reverse(hole.begin() + 1, hole.end());
  const ElasticShape same = make_polygon(plate, {hole}, 0.5);
  EXPECT_EQ(s.vertices, same.vertices);
  EXPECT_EQ(s.triangles, same.triangles);
  // No holes: exactly the polygon without them.
  const ElasticShape plain = make_polygon(kArrow, Holes{}, 0.3);
  const ElasticShape before = make_polygon(kArrow, 0.3);
  EXPECT_EQ(plain.vertices, before.vertices);
  EXPECT_EQ(plain.triangles, before.triangles);
}

TEST(ElasticPolygonHoles, RefusesHolesOutsideCrossingTouchingOrNotSimple) {
  const Points plate = square_loop(0, 0, 4, 4);
  const auto problem = [&](const Holes& holes) {
    return thrown_message([&] { make_polygon(plate, holes, 0.0); });
  };
  EXPECT_EQ(problem({square_loop(5, 5, 6, 6)}), "hole 0 is outside the outline");
  EXPECT_EQ(problem({square_loop(1, 1, 2, 2), square_loop(3, 1, 5, 2)}),
            "hole 1 crosses or touches the outline: its side 0 (corners 0–1) and the outline's "
            "side 1 (corners 1–2)");
  // A corner on the outline's side: touching.
  EXPECT_EQ(problem({{{1, 1}, {2, 0}, {2, 1}}}),
            "hole 0 crosses or touches the outline: its side 0 (corners 0–1) and the outline's "
            "side 0 (corners 0–1)");
  // Sharing a corner, sharing part of a side, crossing.
  EXPECT_EQ(problem({square_loop(1, 1, 2, 2), square_loop(2, 2, 3, 3)}),
            "holes 0 and 1 cross or touch: side 1 (corners 1–2) of hole 0 and side 0 (corners "
            "0–1) of hole 1");
  EXPECT_EQ(problem({square_loop(1, 1, 2, 2), square_loop(2, 1.5, 3, 3)}),
            "holes 0 and 1 cross or touch: side 1 (corners 1–2) of hole 0 and side 0 (corners "
            "0–1) of hole 1");
  EXPECT_EQ(problem({square_loop(1, 1, 2, 2), square_loop(1.5, 1.5, 3, 3)}),
            "holes 0 and 1 cross or touch: side 1 (corners 1–2) of hole 0 and side 0 (corners "
            "0–1) of hole 1");
  EXPECT_EQ(problem({square_loop(1, 1, 3, 3), square_loop(1.5, 1.5, 2, 2)}),
            "holes 0 and 1 overlap: one lies inside the other");
  EXPECT_EQ(problem({square_loop(1, 1, 2, 2), {{1, 1}, {2, 1}, {1, 2}, {2, 2}}}),
            "hole 1: side 1 (corners 1–2) and side 3 (corners 3–0) cross or touch: the polygon "
            "is not simple");
  EXPECT_EQ(problem({{{1, 1}, {2, 1}}}), "hole 0: a polygon needs at least 3 corners, found 2");
  // The corner limit counts the outline's and the holes' corners together.
  EXPECT_EQ(thrown_message([&] { make_polygon(plate, {square_loop(1, 1, 2, 2)}, 0.0, 1000, 7); }),
            "a polygon with holes of 8 corners, more than the limit of 7 corners (raise it with "
            "--max-polygon-corners N)");
}

TEST(ElasticShapes, AreRefusedBeforeGenerationOverTheParticleLimit) {
  EXPECT_EQ(thrown_message([] { make_sheet(2000, 2000, 1, 1, SheetDiagonals::kParallel); }),
            "a sheet of 2000 × 2000 cells has 4004001 vertices, more than the limit of 1000000 "
            "particles (raise it with --max-particles N)");
  EXPECT_EQ(thrown_message([] { make_rod(10, 1.0, 5); }),
            "a rod of 10 segments has 11 vertices, more than the limit of 5 particles (raise it "
            "with --max-particles N)");
  EXPECT_EQ(thrown_message([] {
              make_polygon({{0, 0}, {1, 0}, {0, 1}}, 1e-4, 1000);
            }),
            // 3 corners, 2 · 9999 + 14142 cuts, 10001² grid points.
            "the polygon at spacing 1e-04 (its corners, the cuts of its sides and the grid over "
            "its box) may have 100054144 vertices, more than the limit of 1000 particles (raise "
            "it with --max-particles N)");
  EXPECT_EQ(thrown_message([] { make_polygon(kComb, 0.0, 1000, 10); }),
            "a polygon of 12 corners, more than the limit of 10 corners (raise it with "
            "--max-polygon-corners N)");
}

TEST(ElasticMasses, LumpedTotalsSumToTheTotalAndFollowAreaOrLength) {
  const ElasticShape sheet = make_sheet(7, 3, 1.3, 0.7, SheetDiagonals::kAlternating);
  const ElasticShape polygon = make_polygon(kArrow, 0.3);
  const ElasticShape rod = make_rod(9, 2.0);
  for (const ElasticShape* s : {&sheet, &polygon, &rod}) {
    const std::vector<double> m = lump_total_mass(*s, 3.7);
    double sum = 0.0;
    for (const double x : m) {
      EXPECT_GT(x, 0.0);
      sum += x;
    }
    EXPECT_NEAR(sum, 3.7, 3.7 * 1e-14);
  }
  // A rod's end gets half a segment, an interior vertex a whole one.
  const std::vector<double> m = lump_total_mass(rod, 9.0);
  EXPECT_NEAR(m[0], 0.5, 1e-15);
  EXPECT_NEAR(m[4], 1.0, 1e-15);
}

TEST(ElasticParticles, PlaceRotateFixAndRefuseOutOfRangeVertices) {
  const ElasticShape sheet = make_sheet(2, 1, 2.0, 1.0, SheetDiagonals::kAlternating);
  ElasticPlacement placement;
  placement.origin = {1.0, -1.0};
  placement.rotation_degrees = 90.0;
  ElasticFixing fixing;
  fixing.side = ShapeSide::kLeft;
  fixing.vertices = {5};
  const ElasticParticles p =
      make_elastic_particles(sheet, placement, {ElasticMass::kPerParticle, 0.5}, fixing);
  // Vertex 2 at (2, 0) turns to (0, 2), then moves by the origin.
  EXPECT_NEAR(p.positions[2].x(), 1.0, 1e-15);
  EXPECT_NEAR(p.positions[2].y(), 1.0, 1e-15);
  EXPECT_EQ(p.fixed, (std::vector<char>{1, 0, 0, 1, 0, 1}));  // left side (0, 3) and vertex 5
  EXPECT_EQ(p.masses, std::vector<double>(6, 0.5));
  fixing.vertices = {6};
  EXPECT_EQ(thrown_message([&] {
              make_elastic_particles(sheet, placement, {ElasticMass::kTotal, 1.0}, fixing);
            }),
            "fixed vertex 6 is out of range: the body has 6 vertices (0-based)");
}

TEST(ElasticForces, DeclaresSpringsHingesAndTrianglesWithRestValuesFromThePositions) {
  const ElasticShape rod = make_rod(2, 2.0);
  const Points placed = place_vertices(rod, {0.0, 0.0}, 30.0);
  ElasticMaterial material;
  material.stretch = 5.0;
  material.bend = 0.5;
  std::vector<std::string> lines;
  declare_elastic_forces(rod, placed, material, 10,
                         [&](std::string_view tag, std::span<const DeclaredValue> values) {
                           std::string line(tag);
                           for (const auto& v : values)
                             line += std::string(" ") + v.name + "=" + std::to_string(v.value);
                           lines.push_back(line);
                         });
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0],
            "elasticbodyspringforce i1=10.000000 i2=11.000000 alpha=5.000000 l0=1.000000");
  EXPECT_EQ(lines[2],
            "elasticbodybendingforce i1=10.000000 i2=11.000000 i3=12.000000 alpha=0.500000 "
            "theta0=0.000000");
}

}  // namespace
}  // namespace fosssim
