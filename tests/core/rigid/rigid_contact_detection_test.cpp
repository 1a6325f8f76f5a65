// Tests of rigid-body contact detection (core/rigid/rigid_contact_detection.h): the course's
// strict vertex–edge test, arms in body space, the normal's direction, the de-duplicating set
// (worked example E: 16 reports, 6 records), and the broad phase against all pairs on random
// piles (the same records, bit for bit).

#include "core/rigid/rigid_contact_detection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/rigid/rigid_contact_test_models.h"
#include "core/rigid_test_models.h"
#include "support/random.h"

namespace fosssim::testing {
namespace {

/// Every vertex–edge report in the course's order, before the set removes duplicates.
int count_reports(const RigidBodies& bodies, const Vector& q) {
  int reports = 0;
  RigidContact contact;
  for (int i = 0; i < bodies.size(); ++i) {
    for (int j = i + 1; j < bodies.size(); ++j) {
      for (const auto& [a, b] : {std::pair{i, j}, std::pair{j, i}}) {
        const RigidBody& A = bodies.bodies[a];
        const RigidBody& B = bodies.bodies[b];
        for (int k = 0; k < A.num_vertices(); ++k) {
          for (int e = 0; e < B.num_vertices(); ++e) {
            reports += test_vertex_edge(bodies, q, a, world_vertex(A, q, a, k), b,
                                        world_vertex(B, q, b, e),
                                        world_vertex(B, q, b, (e + 1) % B.num_vertices()), contact);
          }
        }
      }
    }
  }
  return reports;
}

TEST(RigidContactDetection, DistanceEqualToTheRadiiIsNoContact) {
  // A box whose lowest vertices are exactly 0.5 above the floor's top edge: radii 0.25 + 0.25
  // do not touch (strict <), 0.25 + 0.2500000000000001 do (the course's measured rule).
  for (const auto& [radius, expected] : {std::pair{0.25, 0}, std::pair{0.2500000000000001, 2}}) {
    const auto [model, state] =
        make_rigid_model({body(box(-5, -1, 5, 0), 0.25, true), body(box(-1, 0.5, 1, 1.5), radius)});
    const auto contacts = detect_rigid_contacts_all_pairs(*model.rigid_bodies, state.q);
    EXPECT_EQ(static_cast<int>(contacts.size()), expected) << "radius " << radius;
  }
}

TEST(RigidContactDetection, NormalPointsFromLowerToHigherIndexAndArmsAreInBodySpace) {
  // A square (body 0) tilted by θ = 0.3 above a fixed floor (body 1): its lowest vertex is near
  // the floor. The normal points from body 0 to body 1 (downwards); each arm, rotated by its
  // body's angle and added to its centre, is the contact point on that body's surface.
  auto [model, state] =
      make_rigid_model({body(box(-1, -1, 1, 1), 0.2), body(box(-5, -4, 5, -3), 0.15, true)});
  state.q[2] = 0.3;
  state.q[1] = -3.0 + 0.3 + std::sqrt(2.0) * std::cos(std::numbers::pi / 4 - 0.3);
  const RigidBodies& bodies = *model.rigid_bodies;
  const auto contacts = detect_rigid_contacts_all_pairs(bodies, state.q);
  ASSERT_EQ(contacts.size(), 1u);
  const RigidContact& c = contacts[0];
  EXPECT_EQ(c.i0, 0);
  EXPECT_EQ(c.i1, 1);
  EXPECT_NEAR(c.normal.x(), 0.0, 1e-15);
  EXPECT_NEAR(c.normal.y(), -1.0, 1e-15);
  // The vertex is at height −2.7 (0.3 above the floor at −3): contact points 0.2 below it and
  // 0.15 above the floor.
  const Vec2 q0 = rotate(state.q[2], c.arm0) + body_center(state.q, 0);
  const Vec2 q1 = rotate(state.q[5], c.arm1) + body_center(state.q, 1);
  EXPECT_NEAR(q0.y(), -2.9, 1e-14);
  EXPECT_NEAR(q1.y(), -2.85, 1e-14);
  EXPECT_NEAR(q0.x(), q1.x(), 1e-14);
  // Body space: the arm of body 0 is its lowest vertex's body point plus 0.2 along the
  // normal turned back by −θ.
  const Vec2 vertex = bodies.bodies[0].body_points[3];  // (−1, −1): the lowest for θ = 0.3
  const Vec2 expected = vertex + rotate(-0.3, Vec2(0, -0.2));
  EXPECT_NEAR(c.arm0.x(), expected.x(), 1e-14);
  EXPECT_NEAR(c.arm0.y(), expected.y(), 1e-14);
}

TEST(RigidContactDetection, VertexVertexContactIsOneRecord) {
  // Corner (0, 0) of one square and corner (0.1, 0.1) of the other, radii 0.1: each corner is
  // reported against both edges at the other's corner (4 reports, same points, normals ±),
  // which the set keeps once.
  const auto [model, state] =
      make_rigid_model({body(box(-1, -1, 0, 0)), body(box(0.1, 0.1, 1.1, 1.1))});
  const RigidBodies& bodies = *model.rigid_bodies;
  EXPECT_EQ(count_reports(bodies, state.q), 4);
  const auto contacts = detect_rigid_contacts_all_pairs(bodies, state.q);
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_NEAR(contacts[0].normal.x(), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(contacts[0].normal.y(), std::sqrt(0.5), 1e-15);
}

TEST(RigidContactDetection, WorkedExampleERecordsSixOfSixteenReports) {
  // Worked example E after its first integration (block 0 moved by 0.01): 16 reports, 6 records.
  auto [model, state] =
      make_rigid_model({body(box(-0.5, -0.5, 0.5, 0.5)), body(box(0.65, -0.5, 1.65, 0.5)),
                        body({{1.8, 0.6}, {2.8, 0.4}, {2.8, -0.6}, {1.8, -0.4}})});
  state.q[0] += 0.01;
  EXPECT_EQ(count_reports(*model.rigid_bodies, state.q), 16);
  const auto contacts = detect_rigid_contacts_all_pairs(*model.rigid_bodies, state.q);
  EXPECT_EQ(contacts.size(), 6u);
  for (std::size_t k = 1; k < contacts.size(); ++k) {
    EXPECT_TRUE(RigidContactOrder{}(contacts[k - 1], contacts[k])) << "records out of order";
  }
}

TEST(RigidContactDetection, OrderComparesWithinTolerance) {
  RigidContact a{0, 1, {1.0, 2.0}, {0.5, 0.5}, {0.0, 1.0}};
  RigidContact b = a;
  b.arm0.x() += 0.9e-9;  // equal within 1e-9: later fields decide
  b.normal.y() -= 1e-3;
  EXPECT_TRUE(RigidContactOrder{}(b, a));
  EXPECT_FALSE(RigidContactOrder{}(a, b));
  b.arm0.x() = a.arm0.x() + 1.1e-9;  // beyond the tolerance: arm0.x decides
  EXPECT_TRUE(RigidContactOrder{}(a, b));
  RigidContactSet set;
  set.insert(a);
  RigidContact close = a;
  close.arm1.y() += 1e-10;
  EXPECT_FALSE(set.insert(close).second);  // the first one stays
  EXPECT_EQ(set.begin()->arm1.y(), 0.5);
}

void expect_same_records(const std::vector<RigidContact>& a, const std::vector<RigidContact>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].i0, b[k].i0);
    EXPECT_EQ(a[k].i1, b[k].i1);
    EXPECT_EQ(a[k].arm0, b[k].arm0);  // bit for bit
    EXPECT_EQ(a[k].arm1, b[k].arm1);
    EXPECT_EQ(a[k].normal, b[k].normal);
  }
}

TEST(RigidContactDetection, BroadPhaseFindsExactlyTheRecordsOfAllPairs) {
  for (unsigned seed = 1; seed <= 12; ++seed) {
    // Dense piles (most bodies touch several others) and sparse ones.
    const double spread = seed % 2 ? 6.0 : 20.0;
    const auto [model, state] = random_pile(seed, 120, spread, 0.6);
    const auto all = detect_rigid_contacts_all_pairs(*model.rigid_bodies, state.q);
    const auto fast = detect_rigid_contacts(*model.rigid_bodies, state.q);
    EXPECT_GT(all.size(), 20u) << "seed " << seed << ": the pile should touch";
    expect_same_records(all, fast);
  }
}

TEST(RigidContactDetection, BroadPhaseOfAThousandBodiesTestsFewPairs) {
  const auto [model, state] = random_pile(99, 1000, 60.0, 0.8);
  const auto pairs = rigid_candidate_pairs(*model.rigid_bodies, state.q);
  // 1002 bodies have 501,501 pairs; the broad phase keeps those whose boxes overlap: the
  // floor and the stick with the bodies along them, and a few neighbours per body.
  EXPECT_LT(pairs.size(), 20000u);
  expect_same_records(detect_rigid_contacts_all_pairs(*model.rigid_bodies, state.q),
                      detect_rigid_contacts(*model.rigid_bodies, state.q));
}

TEST(RigidContactDetection, NonFinitePositionsGiveNoContactsEitherWay) {
  auto [model, state] = random_pile(7, 30, 5.0, 0.6);
  state.q[3] = NAN;
  expect_same_records(detect_rigid_contacts_all_pairs(*model.rigid_bodies, state.q),
                      detect_rigid_contacts(*model.rigid_bodies, state.q));
  for (const RigidContact& c : detect_rigid_contacts(*model.rigid_bodies, state.q)) {
    EXPECT_TRUE(c.i0 != 1 && c.i1 != 1);
  }
}

}  // namespace
}  // namespace fosssim::testing
