// FOSSSim's broad phase (core/collisions/box_grid.h, grid_pairs.h) against brute force: no
// overlap missed on random scenes in 2D and 3D, static, swept and moving queries, and whole
// simulations equal to all pairs bit for bit.

#include "core/collisions/grid_pairs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <tuple>
#include <vector>

#include "core/collisions/box_grid.h"
#include "core/collisions/candidate_pairs.h"
#include "core/collisions/proximity.h"
#include "core/collisions/swept_detection.h"
#include "core/step/step_pipeline.h"
#include "support/random.h"
#include "support/scene_builder.h"

namespace fosssim {
namespace {

using testing::Random;
using testing::TestScene;

// ---- BoxGrid ------------------------------------------------------------------------------

/// A size spread over four orders of magnitude, sometimes zero.
double random_size(Random& random) {
  if (random.uniform(0, 1) < 0.05) return 0.0;
  return std::pow(10.0, random.uniform(-3.0, 1.0));
}

template <int D>
std::vector<Box<D>> random_boxes(Random& random, int count) {
  std::vector<Box<D>> boxes;
  for (int k = 0; k < count; ++k) {
    Vec<D> lo;
    for (int a = 0; a < D; ++a) lo[a] = random.uniform(-5.0, 5.0);
    if (k % 97 == 5) lo *= 1e7;  // a few far away
    Vec<D> size;
    for (int a = 0; a < D; ++a) size[a] = random_size(random);
    boxes.push_back({lo, lo + size});
  }
  const double inf = std::numeric_limits<double>::infinity();
  Vec<D> far = Vec<D>::Constant(1e300);
  boxes.push_back({-far, far});                                       // huge
  boxes.push_back({Vec<D>::Constant(-inf), Vec<D>::Zero()});          // unbounded
  boxes.push_back({Vec<D>::Constant(std::nan("")), Vec<D>::Zero()});  // not a number
  return boxes;
}

template <int D>
void check_box_grid(unsigned seed) {
  Random random(seed);
  const std::vector<Box<D>> boxes = random_boxes<D>(random, 600);
  BoxGrid<D> grid;
  for (const double base_cell : {0.05, 0.7, 20.0}) {
    grid.build(boxes, base_cell);
    for (int q = 0; q < 200; ++q) {
      Box<D> query = q < 190 ? random_boxes<D>(random, 1)[0] : boxes[random.index(600)];
      const int min_level = q % 3 == 0 ? 0 : random.index(12);
      std::vector<int> got;
      grid.query(query, min_level, [&](int k) { got.push_back(k); });
      std::vector<int> expected;
      for (int k = 0; k < static_cast<int>(boxes.size()); ++k) {
        if (grid.level_of(k) >= min_level && boxes[k].overlaps(query)) expected.push_back(k);
      }
      std::sort(got.begin(), got.end());
      ASSERT_EQ(got, expected) << "seed " << seed << ", base cell " << base_cell << ", query " << q;
    }
  }
}

TEST(BoxGrid, QueriesFindExactlyTheOverlappingBoxesOnceIn2D) {
  for (unsigned seed = 1; seed <= 4; ++seed) check_box_grid<2>(seed);
}

TEST(BoxGrid, QueriesFindExactlyTheOverlappingBoxesOnceIn3D) {
  for (unsigned seed = 1; seed <= 4; ++seed) check_box_grid<3>(seed);
}

TEST(BoxGrid, EveryBoxSpansAtMostTwoCellsOfItsLevel) {
  Random random(9);
  const std::vector<Box<2>> boxes = random_boxes<2>(random, 500);
  BoxGrid<2> grid;
  grid.build(boxes, 0.1);
  for (int k = 0; k < 500; ++k) {
    const int level = grid.level_of(k);
    ASSERT_LT(level, BoxGrid<2>::kUnbounded);
    const double cell = std::ldexp(0.1, level);
    for (int a = 0; a < 2; ++a) {
      EXPECT_LE(std::floor(boxes[k].hi[a] / cell) - std::floor(boxes[k].lo[a] / cell), 1.0);
    }
    // And it is not filed higher than needed by more than one level.
    if (level > 0) {
      EXPECT_GT(boxes[k].extent(), std::ldexp(0.1, level - 2));
    }
  }
  EXPECT_EQ(grid.level_of(501), BoxGrid<2>::kUnbounded);  // infinite
  EXPECT_EQ(grid.level_of(502), BoxGrid<2>::kUnbounded);  // NaN
}

// ---- random scenes ------------------------------------------------------------------------

/// n particles of radii from 0.002 to 0.5 (a few of 1 to 3), clustered in [-2, 2]^D, edges
/// between nearby particles and a few long ones, and `planes` half-planes (or half-spaces).
TestScene random_scene(int dim, unsigned seed, int n, int edges, int planes) {
  Random random(seed);
  TestScene scene(dim, "symplectic-euler", 0.01);
  std::vector<Vector> centres;
  for (int c = 0; c < 5; ++c) centres.push_back(random.uniform_vector(dim, -2.0, 2.0));
  for (int p = 0; p < n; ++p) {
    const double r =
        p % 50 == 7 ? random.uniform(1.0, 3.0) : std::pow(10.0, random.uniform(-2.7, -0.3));
    const Vector x = centres[p % 5] + random.uniform_vector(dim, -1.0, 1.0);
    scene.add_particle(random.uniform(0.5, 2.0), x, random.uniform_vector(dim, -3.0, 3.0),
                       p % 13 == 0, r);
  }
  const auto nearest = [&](int i) {
    int best = i == 0 ? 1 : 0;
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      const auto xi = scene.initial.q.segment(dim * i, dim),
                 xj = scene.initial.q.segment(dim * j, dim);
      const auto xb = scene.initial.q.segment(dim * best, dim);
      if ((xj - xi).norm() < (xb - xi).norm()) best = j;
    }
    return best;
  };
  for (int e = 0; e < edges; ++e) {
    // Mostly between near neighbours, as in a mesh or a chain; one in ten across the scene.
    const int i = random.index(n);
    int j = e % 10 == 0 ? random.index(n) : nearest(i);
    if (j == i) j = (i + 1) % n;
    scene.add_edge(i, j, std::pow(10.0, random.uniform(-2.5, -0.5)));
  }
  for (int h = 0; h < planes; ++h) {
    scene.add_half_plane(random.uniform_vector(dim, -2.0, 2.0),
                         random.uniform(0.3, 3.0) * random.unit_vector(dim));
  }
  return scene;
}

std::vector<CandidatePair> collect(const CandidatePairs& pairs, const PairQuery& query) {
  std::vector<CandidatePair> out;
  pairs.for_each(query, [&out](const CandidatePair& pair) { out.push_back(pair); });
  return out;
}

/// Expects `found` sorted in the course's order, without repeats, without a particle paired
/// with its own edge, and holding every pair of `needed`.
void expect_valid_candidates(const SceneModel& model, const std::vector<CandidatePair>& found,
                             const std::vector<CandidatePair>& needed, const std::string& what) {
  for (std::size_t k = 1; k < found.size(); ++k) {
    ASSERT_TRUE(precedes_in_course_order(found[k - 1], found[k])) << what << " at " << k;
  }
  for (const CandidatePair& pair : found) {
    if (pair.kind == CollisionKind::kParticleEdge) {
      const Edge& edge = model.edges[pair.other];
      ASSERT_TRUE(edge.i != pair.particle && edge.j != pair.particle) << what;
    }
    if (pair.kind == CollisionKind::kParticleParticle) {
      ASSERT_LT(pair.particle, pair.other);
    }
  }
  for (const CandidatePair& pair : needed) {
    ASSERT_TRUE(std::binary_search(found.begin(), found.end(), pair, precedes_in_course_order))
        << what << ": missed (" << static_cast<int>(pair.kind) << ", " << pair.particle << ", "
        << pair.other << ")";
  }
}

template <int D>
void check_static_queries(unsigned seed) {
  for (const double margin : {0.0, 0.05}) {
    TestScene scene = random_scene(D, seed, 400, 300, 4);
    const SceneModel& model = scene.model;
    const Vector& q = scene.initial.q;
    const PairQuery query{q, q, margin};
    const std::vector<CandidatePair> all = collect(AllPairs(model), query);
    std::vector<CandidatePair> needed;
    for (const CandidatePair& pair : all) {
      const Separation<D> s = separation<D>(model, pair, q);
      if (s.n.norm() < s.radii + margin) needed.push_back(pair);
    }
    ASSERT_GT(needed.size(), 100u);  // the scene is crowded enough to test something
    const std::vector<CandidatePair> found = collect(GridPairs<D>(model), query);
    expect_valid_candidates(model, found, needed, "seed " + std::to_string(seed));
    // Far fewer than all pairs.
    EXPECT_LT(found.size(), all.size() / 4);
  }
}

TEST(GridPairs, StaticQueriesMissNoOverlapIn2D) {
  for (unsigned seed = 1; seed <= 5; ++seed) check_static_queries<2>(seed);
}

TEST(GridPairs, StaticQueriesMissNoOverlapIn3D) {
  for (unsigned seed = 1; seed <= 5; ++seed) check_static_queries<3>(seed);
}

/// One GridPairs asked again and again as the particles move a little (within the skin, whose
/// pairs it reuses) and sometimes far (a new search): never a pair missed.
template <int D>
void check_repeated_static_queries(unsigned seed) {
  TestScene scene = random_scene(D, seed, 300, 200, 3);
  const SceneModel& model = scene.model;
  const GridPairs<D> grid(model);
  Vector q = scene.initial.q;
  constexpr int kRounds = 16;
  for (int round = 0; round < kRounds; ++round) {
    q += (round % 8 == 7 ? 0.05 : 0.003) * scene.initial.v;  // up to 0.009 or 0.15 per axis
    const PairQuery query{q, q, 0.01};
    std::vector<CandidatePair> needed;
    for (const CandidatePair& pair : collect(AllPairs(model), query)) {
      const Separation<D> s = separation<D>(model, pair, q);
      if (s.n.norm() < s.radii + query.margin) needed.push_back(pair);
    }
    expect_valid_candidates(model, collect(grid, query), needed,
                            "seed " + std::to_string(seed) + ", round " + std::to_string(round));
  }
  // The small moves reused the pairs, the large ones searched again.
  EXPECT_LT(grid.searches(), kRounds / 2) << "seed " << seed;
  EXPECT_GE(grid.searches(), 2) << "seed " << seed;
}

TEST(GridPairs, RepeatedStaticQueriesReuseTheirPairsAndMissNoOverlapIn2D) {
  for (unsigned seed = 1; seed <= 4; ++seed) check_repeated_static_queries<2>(seed);
}

TEST(GridPairs, RepeatedStaticQueriesReuseTheirPairsAndMissNoOverlapIn3D) {
  for (unsigned seed = 1; seed <= 4; ++seed) check_repeated_static_queries<3>(seed);
}

/// How far the objects of `pair` move from xs to xe at most, added up: a bound on how much
/// their separation can shrink.
double largest_approach(const SceneModel& model, const CandidatePair& pair, const Vector& xs,
                        const Vector& xe) {
  const int dim = model.dim;
  const auto moved = [&](int p) { return (xe - xs).segment(dim * p, dim).norm(); };
  double sum = moved(pair.particle);
  if (pair.kind == CollisionKind::kParticleParticle) sum += moved(pair.other);
  if (pair.kind == CollisionKind::kParticleEdge) {
    sum += moved(model.edges[pair.other].i) + moved(model.edges[pair.other].j);
  }
  return sum;
}

/// The smallest separation over the motion from xs to xe, sampled at 65 times, less its radii.
template <int D>
double closest_gap(const SceneModel& model, const CandidatePair& pair, const Vector& xs,
                   const Vector& xe) {
  double gap = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= 64; ++k) {
    const Vector x = xs + (k / 64.0) * (xe - xs);
    const Separation<D> s = separation<D>(model, pair, x);
    gap = std::min(gap, s.n.norm() - s.radii);
  }
  return gap;
}

template <int D>
void check_swept_queries(unsigned seed) {
  TestScene scene = random_scene(D, seed, 300, 200, 3);
  const SceneModel& model = scene.model;
  const Vector xs = scene.initial.q;
  const Vector xe = xs + 0.05 * scene.initial.v;  // up to 0.15 per axis
  const PairQuery query{xs, xe, 0.0};
  std::vector<CandidatePair> needed;
  for (const CandidatePair& pair : collect(AllPairs(model), query)) {
    const Separation<D> start = separation<D>(model, pair, xs);
    if (start.n.norm() - start.radii > largest_approach(model, pair, xs, xe)) continue;
    if (closest_gap<D>(model, pair, xs, xe) < 0 || detect_swept<D>(model, pair, xs, xe, nullptr)) {
      needed.push_back(pair);
    }
  }
  ASSERT_GT(needed.size(), 50u);
  expect_valid_candidates(model, collect(GridPairs<D>(model), query), needed,
                          "seed " + std::to_string(seed));
}

TEST(GridPairs, SweptQueriesMissNoContactDuringTheStepIn2D) {
  for (unsigned seed = 1; seed <= 5; ++seed) check_swept_queries<2>(seed);
}

TEST(GridPairs, SweptQueriesMissNoContactDuringTheStepIn3D) {
  for (unsigned seed = 1; seed <= 5; ++seed) check_swept_queries<3>(seed);
}

/// A Gauss-Seidel pass that acts on every pair closer than its radii at the end positions as
/// they are when the pair comes: it moves the pair's particles (throwing them some distance,
/// sometimes far), as a response would. Returns the pairs it acted on, in order.
template <int D>
std::vector<CandidatePair> moving_pass(const CandidatePairs& pairs, const SceneModel& model,
                                       const Vector& xs, Vector& xe) {
  std::vector<CandidatePair> acted;
  pairs.for_each_moving(PairQuery{xs, xe, 0.0}, [&](const CandidatePair& pair) {
    MovedParticles moved;
    const Separation<D> s = separation<D>(model, pair, xe);
    if (!(s.n.norm() < s.radii)) return moved;
    acted.push_back(pair);
    const int k = static_cast<int>(acted.size());
    const int p = pair.particle;
    // Deterministic "responses": back along the step, sideways, or far away.
    Vec<D> shift = -(particle_vec<D>(xe, p) - particle_vec<D>(xs, p));
    if (k % 3 == 1) shift = Vec<D>::Constant(0.3 * ((k % 7) - 3));
    xe.template segment<D>(D * p) += shift;
    moved.particle[moved.count++] = p;
    if (pair.kind == CollisionKind::kParticleParticle && k % 2 == 0) {
      xe.template segment<D>(D * pair.other) -= 0.5 * shift;
      moved.particle[moved.count++] = pair.other;
    }
    return moved;
  });
  return acted;
}

template <int D>
void check_moving_queries(unsigned seed) {
  TestScene scene = random_scene(D, seed, 300, 200, 3);
  const SceneModel& model = scene.model;
  const Vector xs = scene.initial.q;
  Vector xe_all = xs + 0.05 * scene.initial.v;
  Vector xe_grid = xe_all;
  const std::vector<CandidatePair> acted_all = moving_pass<D>(AllPairs(model), model, xs, xe_all);
  const std::vector<CandidatePair> acted_grid =
      moving_pass<D>(GridPairs<D>(model), model, xs, xe_grid);
  ASSERT_GT(acted_all.size(), 30u);
  EXPECT_EQ(acted_grid, acted_all) << "seed " << seed;
  EXPECT_EQ(xe_grid, xe_all) << "seed " << seed;
}

TEST(GridPairs, MovingQueriesActOnTheSamePairsAsAllPairsIn2D) {
  for (unsigned seed = 1; seed <= 6; ++seed) check_moving_queries<2>(seed);
}

TEST(GridPairs, MovingQueriesActOnTheSamePairsAsAllPairsIn3D) {
  for (unsigned seed = 1; seed <= 6; ++seed) check_moving_queries<3>(seed);
}

// ---- whole simulations ----------------------------------------------------------------------

/// Runs `steps` steps; returns every state and every record.
std::pair<std::vector<State>, std::vector<StepRecord>> simulate(const SceneModel& model,
                                                                State state, int steps) {
  StepPipeline pipeline(model);
  std::vector<State> states;
  std::vector<StepRecord> records;
  for (int k = 0; k < steps; ++k) {
    StepRecord record;
    pipeline.step(state, &record);
    states.push_back(state);
    records.push_back(std::move(record));
  }
  return {states, records};
}

void expect_same_records(const StepRecord& a, const StepRecord& b, const std::string& what) {
  ASSERT_EQ(a.collisions.size(), b.collisions.size()) << what;
  for (std::size_t k = 0; k < a.collisions.size(); ++k) {
    ASSERT_TRUE(a.collisions[k].same_pair(b.collisions[k])) << what;
    ASSERT_EQ(a.collisions[k].normal, b.collisions[k].normal) << what;
    ASSERT_EQ(a.collisions[k].time, b.collisions[k].time) << what;
  }
}

// ---- crowds: the direct visits past the candidate budget -----------------------------------

/// The random scenes with a budget too small for their candidates: the grid visits the pairs
/// directly, and they are exactly those of its list (static and swept queries), and a moving
/// pass acts exactly as with all pairs.
template <int D>
void check_direct_visits(unsigned seed) {
  TestScene scene = random_scene(D, seed, 300, 200, 3);
  const SceneModel& model = scene.model;
  const Vector xs = scene.initial.q;
  const Vector xe = xs + 0.05 * scene.initial.v;
  const std::string what = "seed " + std::to_string(seed);
  for (const bool swept : {false, true}) {
    const PairQuery query{xs, swept ? xe : xs, swept ? 0.0 : 0.02};
    GridPairs<D> listed(model), direct(model);
    direct.set_candidate_budget(10);
    const std::vector<CandidatePair> from_list = collect(listed, query);
    EXPECT_FALSE(listed.visits_directly()) << what;
    ASSERT_GT(from_list.size(), 100u) << what;
    EXPECT_EQ(collect(direct, query), from_list) << what << (swept ? ", swept" : ", static");
    EXPECT_TRUE(direct.visits_directly()) << what;
    if (!swept) {  // a second static query reuses the skin's boxes, still directly
      EXPECT_EQ(collect(direct, query), from_list) << what;
      EXPECT_EQ(direct.searches(), 1) << what;
    }
  }
  GridPairs<D> direct(model);
  direct.set_candidate_budget(10);
  Vector xe_all = xe, xe_direct = xe;
  const std::vector<CandidatePair> acted_all = moving_pass<D>(AllPairs(model), model, xs, xe_all);
  const std::vector<CandidatePair> acted_direct = moving_pass<D>(direct, model, xs, xe_direct);
  EXPECT_TRUE(direct.visits_directly()) << what;
  ASSERT_GT(acted_all.size(), 30u);
  EXPECT_EQ(acted_direct, acted_all) << what;
  EXPECT_EQ(xe_direct, xe_all) << what;
}

TEST(GridPairs, DirectVisitsPastTheBudgetGiveTheListsPairsIn2D) {
  for (unsigned seed = 1; seed <= 3; ++seed) check_direct_visits<2>(seed);
}

TEST(GridPairs, DirectVisitsPastTheBudgetGiveTheListsPairsIn3D) {
  for (unsigned seed = 1; seed <= 3; ++seed) check_direct_visits<3>(seed);
}

/// n balls of radius 0.1 within 0.01 of the origin, so that every box overlaps every other,
/// and a half-plane (or half-space) per axis that every ball overlaps.
TestScene clustered_scene(int dim, int n, unsigned seed) {
  Random random(seed);
  TestScene scene(dim, "symplectic-euler", 0.01);
  for (int p = 0; p < n; ++p) {
    scene.add_particle(1.0, random.uniform_vector(dim, -0.01, 0.01),
                       random.uniform_vector(dim, -1.0, 1.0), false, 0.1);
  }
  for (int a = 0; a < dim; ++a) {
    Vector point = Vector::Zero(dim), normal = Vector::Zero(dim);
    point[a] = -0.05;  // every ball overlaps it too
    normal[a] = 1.0;
    scene.add_half_plane(point, normal);
  }
  return scene;
}

/// A crowd over the default budget: the grid lists nothing (no memory per pair) and visits the
/// same pairs as all pairs, in the same order; simulations equal all pairs bit for bit.
template <int D>
void check_crowd() {
  constexpr int kBalls = 1200;  // 719,400 pairs, over the budget of 256 per ball
  TestScene scene = clustered_scene(D, kBalls, 7);
  SceneModel& model = scene.model;
  const Vector& q = scene.initial.q;
  const PairQuery query{q, q, 0.0};
  GridPairs<D> grid(model);
  ASSERT_LT(grid.candidate_budget(), std::size_t{kBalls} * (kBalls - 1) / 2);
  const std::vector<CandidatePair> all = collect(AllPairs(model), query);
  std::size_t count = 0;
  bool same = true;
  grid.for_each(query, [&](const CandidatePair& pair) {
    same = same && count < all.size() && pair == all[count];
    ++count;
  });
  EXPECT_TRUE(grid.visits_directly());
  EXPECT_TRUE(same);
  EXPECT_EQ(count, all.size());
  for (const ContactMethod* method : {&contact_method("penalty"), &contact_method("simple")}) {
    model.collisions.method = method;
    model.collisions.stiffness = 100;
    model.collisions.thickness = 0.01;
    model.collisions.detection = PairDetection::kAllPairs;
    const auto [states_all, records_all] = simulate(model, scene.initial, 2);
    model.collisions.detection = PairDetection::kDefault;
    ASSERT_TRUE(uses_grid_pairs(model));
    const auto [states_grid, records_grid] = simulate(model, scene.initial, 2);
    for (std::size_t k = 0; k < states_all.size(); ++k) {
      ASSERT_EQ(states_grid[k].q, states_all[k].q) << method->name << " " << k;
      ASSERT_EQ(states_grid[k].v, states_all[k].v) << method->name << " " << k;
      expect_same_records(records_grid[k], records_all[k], "crowd, step " + std::to_string(k));
    }
  }
}

TEST(GridPairs, CrowdsPastTheBudgetAreVisitedLikeAllPairsIn2D) { check_crowd<2>(); }

TEST(GridPairs, CrowdsPastTheBudgetAreVisitedLikeAllPairsIn3D) { check_crowd<3>(); }

/// A crowded random scene in a box, stepped with the grid and with all pairs: the states are
/// equal bit for bit, and so are the collisions found.
void check_same_simulation(int dim, const ContactMethod* method, unsigned seed) {
  constexpr int kSteps = 25;
  TestScene scene = random_scene(dim, seed, 80, 40, 0);
  // Smaller particles, so that the scene is crowded but not jammed, all free (fixed particles
  // against edges with fixed ends give the course's 0/0), in a box of half-planes.
  for (double& r : scene.model.particle_radius) r = std::min(r, dim == 2 ? 0.08 : 0.25);
  scene.model.fixed.assign(scene.model.fixed.size(), false);
  for (int a = 0; a < dim; ++a) {
    for (const double side : {-1.0, 1.0}) {
      Vector point = Vector::Zero(dim), normal = Vector::Zero(dim);
      point[a] = 3.5 * side;
      normal[a] = -side * (a + 1);
      scene.add_half_plane(point, normal);
    }
  }
  scene.model.collisions.method = method;
  scene.model.collisions.cor = 0.7;
  if (method == &contact_method("penalty")) {
    scene.model.collisions.stiffness = 200;
    scene.model.collisions.thickness = 0.02;
  }
  const std::string what = "dim " + std::to_string(dim) + ", method " + std::string(method->name) +
                           ", seed " + std::to_string(seed);
  SceneModel& model = scene.model;
  model.collisions.detection = PairDetection::kAllPairs;
  ASSERT_FALSE(uses_grid_pairs(model));
  SCOPED_TRACE(what);
  const auto [states_all, records_all] = simulate(model, scene.initial, kSteps);
  model.collisions.detection = PairDetection::kContest;
  ASSERT_TRUE(uses_grid_pairs(model));
  const auto [states_grid, records_grid] = simulate(model, scene.initial, kSteps);
  int collisions = 0;
  std::size_t polynomials_all = 0, polynomials_grid = 0;
  for (int k = 0; k < kSteps; ++k) {
    ASSERT_EQ(states_grid[k].q, states_all[k].q) << what << ", step " << k;
    ASSERT_EQ(states_grid[k].v, states_all[k].v) << what << ", step " << k;
    expect_same_records(records_grid[k], records_all[k], what + ", step " + std::to_string(k));
    collisions += static_cast<int>(records_all[k].collisions.size());
    polynomials_all += records_all[k].polynomials.size();
    polynomials_grid += records_grid[k].polynomials.size();
  }
  if (method == &contact_method("simple") || method == &contact_method("continuous-time")) {
    EXPECT_GT(collisions, 5);
  }
  if (method == &contact_method("continuous-time") || method == &contact_method("hybrid")) {
    // The same responses from far fewer pair tests (hybrid records no collisions).
    EXPECT_GT(polynomials_grid, 0u);
    EXPECT_LT(2 * polynomials_grid, polynomials_all);
  }
}

TEST(GridPairs, SimulationsEqualAllPairsBitForBit) {
  for (const int dim : {2, 3}) {
    for (const ContactMethod* method : {&contact_method("penalty"), &contact_method("simple"),
                                        &contact_method("continuous-time")}) {
      for (unsigned seed = 1; seed <= 2; ++seed) check_same_simulation(dim, method, seed);
    }
  }
  for (unsigned seed = 1; seed <= 2; ++seed) {
    check_same_simulation(2, &contact_method("hybrid"), seed);
  }
}

TEST(GridPairs, DefaultIsTheGridWhereResultsAreThoseOfAllPairs) {
  SceneModel model;
  model.collisions.detection = PairDetection::kDefault;
  for (const int dim : {2, 3}) {
    model.dim = dim;
    for (const ContactMethod* method :
         {&contact_method("none"), &contact_method("simple"), &contact_method("penalty"),
          &contact_method("continuous-time"), &contact_method("hybrid")}) {
      model.collisions.method = method;
      const bool logs_every_pair =
          method == &contact_method("continuous-time") || method == &contact_method("hybrid");
      EXPECT_EQ(uses_grid_pairs(model), dim == 3 || !logs_every_pair)
          << dim << "D " << method->name;
    }
  }
}

}  // namespace
}  // namespace fosssim
