// The real-root finder on easy, degenerate and ill-conditioned polynomials.

#include "core/collisions/real_roots.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "support/closed_forms.h"
#include "support/finite_differences.h"
#include "support/random.h"
#include "support/scene_builder.h"

namespace fosssim {
namespace {

/// The coefficients, highest first, of scale · Π (t - r).
std::vector<double> from_roots(const std::vector<double>& roots, double scale = 1.0) {
  std::vector<double> c = {scale};
  for (double r : roots) {
    c.push_back(0.0);
    for (std::size_t k = c.size() - 1; k > 0; --k) c[k] -= r * c[k - 1];
  }
  return c;
}

TEST(RealRoots, SimpleAndMixedRoots) {
  EXPECT_EQ(real_roots({2.0, -1.0}), (std::vector<double>{0.5}));
  const auto r = real_roots(from_roots({-2.0, 0.5, 3.0}));
  ASSERT_EQ(r.size(), 3u);
  EXPECT_NEAR(r[0], -2.0, 1e-15);
  EXPECT_NEAR(r[1], 0.5, 1e-15);
  EXPECT_NEAR(r[2], 3.0, 1e-15);
  EXPECT_TRUE(real_roots({1.0, 0.0, 1.0}).empty());  // t² + 1
  EXPECT_TRUE(real_roots({5.0}).empty());
}

TEST(RealRoots, ZeroConstantTermsGiveRootsAtExactlyZero) {
  const auto r = real_roots({1.0, -1.0, 0.0, 0.0});  // t²(t - 1)
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[0], 0.0);
  EXPECT_EQ(r[1], 0.0);
  EXPECT_EQ(r[2], 1.0);
}

TEST(RealRoots, DoubleRootsAreFound) {
  const auto r = real_roots(from_roots({0.5, 0.5}));
  ASSERT_FALSE(r.empty());
  for (double x : r) EXPECT_NEAR(x, 0.5, 1e-7);
}

TEST(RealRoots, IllConditionedPolynomials) {
  // Wilkinson-like quintic with roots 1..5: each root to 1e-12.
  {
    const std::vector<double> roots = {1, 2, 3, 4, 5};
    const auto r = real_roots(from_roots(roots));
    ASSERT_EQ(r.size(), 5u);
    for (int k = 0; k < 5; ++k) EXPECT_NEAR(r[k], roots[k], 1e-12);
  }
  // Clustered roots 10⁻⁴ apart, scaled by a tiny leading coefficient as contact polynomials
  // are: condition numbers near 1e8, so errors up to 1e-8 are the method's limit in doubles.
  {
    const std::vector<double> roots = {0.1, 0.1001, 0.1002, 0.7, 0.9};
    const auto r = real_roots(from_roots(roots, 1e-6));
    ASSERT_EQ(r.size(), 5u);
    for (int k = 0; k < 5; ++k) EXPECT_NEAR(r[k], roots[k], 1e-8) << k;
  }
  // Coefficients spanning 16 orders of magnitude: roots 1e-6, 1, 1e6.
  {
    const auto r = real_roots(from_roots({1e-6, 1.0, 1e6}));
    ASSERT_EQ(r.size(), 3u);
    EXPECT_NEAR(r[0], 1e-6, 1e-18);
    EXPECT_NEAR(r[1], 1.0, 1e-12);
    EXPECT_NEAR(r[2], 1e6, 1e-6);
  }
  // Random quintics with known real roots in [-1, 2] and a pair of complex roots: every real
  // root found to 1e-9 and none invented.
  testing::Random random(11);
  for (int trial = 0; trial < 500; ++trial) {
    std::vector<double> roots = {random.uniform(-1, 2), random.uniform(-1, 2),
                                 random.uniform(-1, 2)};
    std::sort(roots.begin(), roots.end());
    if (roots[1] - roots[0] < 1e-3 || roots[2] - roots[1] < 1e-3) continue;
    std::vector<double> c = from_roots(roots, random.uniform(0.1, 10));
    // Times (t - a)² + b², b > 0.
    const double a = random.uniform(-1, 2), b = random.uniform(0.01, 1);
    std::vector<double> q = {1.0, -2.0 * a, a * a + b * b}, product(c.size() + 2, 0.0);
    for (std::size_t i = 0; i < c.size(); ++i) {
      for (std::size_t j = 0; j < 3; ++j) product[i + j] += c[i] * q[j];
    }
    const auto r = real_roots(product);
    ASSERT_EQ(r.size(), 3u) << "trial " << trial;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(r[k], roots[k], 1e-9) << "trial " << trial;
  }
}

}  // namespace
}  // namespace fosssim
