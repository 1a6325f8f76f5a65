// Tests of VortexForce (docs/forces.md) in 2D and 3D.
//
// Math checked:
// - values: w = (kvc / l²)(kbs R n - dv), F_j = w, F_i = -w, worked out by hand in 2D, in 3D
//   about the z axis (same numbers) and about the x axis (R n = x × y = z); the factory
//   normalizes a 3D axis (ax, ay, az) = (0, 0, 2) to the z axis;
// - derivatives by finite differences (library checker and full-matrix check): hessX = -J in the
//   pair pattern with J = kvc [kbs (R/l³ - 3 R d dᵀ/l⁵) + 2 dv dᵀ/l⁴], hessV = (kvc/l²) I in the
//   pair pattern, on random configurations (random positions, velocities, kbs, kvc and, in 3D,
//   random axes; several seeds) and on nearly coincident particles l = 1e-4..1e-6;
// - symmetry: has_symmetric_jacobians() is false and hessX is really non-symmetric (R/l³ is
//   antisymmetric), while hessV is symmetric.

#include "core/forces/vortex_force.h"

#include <gtest/gtest.h>

#include <map>
#include <stdexcept>

#include "core/scene_model.h"
#include "core/text.h"
#include "support/closed_forms.h"
#include "support/dense.h"
#include "support/finite_differences.h"
#include "support/random.h"
#include "support/scene_builder.h"
#include "support/typed_tests.h"

namespace fosssim::testing {
namespace {

FOSSSIM_TEST_SUITE_IN_2D_AND_3D(VortexForceTest);

/// gradE of a vortex between particle 0 at the origin and particle 1 at d with velocity dv.
template <int D>
Vector vortex_gradient(const VortexForce<D>& vortex, const Vector& d, const Vector& dv) {
  Vector q = Vector::Zero(2 * D), v = Vector::Zero(2 * D);
  q.tail(D) = d;
  v.tail(D) = dv;
  return gradient_of(vortex, q, v, Vector::Ones(2 * D));
}

TYPED_TEST(VortexForceTest, ForceMatchesTheFormulaByHand) {
  constexpr int D = TypeParam::value;
  const VortexForce<D> vortex(0, 1, 3.0, 2.0, vortex_rotation<D>(Vec<3>(0.0, 0.0, 1.0)));
  // d = (2, 0), dv = (0, 1): n = (1, 0), R n = (0, 1), w = (2/4)(3 (0, 1) - (0, 1)) = (0, 1).
  Vector d = Vector::Zero(D), dv = Vector::Zero(D);
  d[0] = 2.0;
  dv[1] = 1.0;
  const Vector g = vortex_gradient(vortex, d, dv);
  Vector expected = Vector::Zero(2 * D);
  expected[1] = 1.0;       // gradE_i = -F_i = w
  expected[D + 1] = -1.0;  // gradE_j = -F_j = -w
  EXPECT_TRUE(g.isApprox(expected, 1e-15)) << g.transpose();
  EXPECT_FALSE(vortex.has_potential());
  EXPECT_FALSE(vortex.has_symmetric_jacobians());
}

TEST(VortexForce3D, SwirlsAboutItsAxis) {
  // Axis x, d = (0, 2, 0), dv = (0, 0, -1): R n = x × y = z, w = (2/4)(3 z + z) = (0, 0, 2).
  const VortexForce<3> vortex(0, 1, 3.0, 2.0, cross_product_matrix(Vec<3>(1.0, 0.0, 0.0)));
  const Vector g = vortex_gradient(vortex, vec({0.0, 2.0, 0.0}), vec({0.0, 0.0, -1.0}));
  EXPECT_TRUE(g.isApprox(vec({0.0, 0.0, 2.0, 0.0, 0.0, -2.0}), 1e-15)) << g.transpose();
}

/// Parameters from a map, as a scene file would give them, for testing factories in C++.
class MapParameters final : public ForceParameters {
 public:
  explicit MapParameters(std::map<std::string, double> values) : values_(std::move(values)) {}
  double number(const char* name) override { return values_.at(name); }
  double number_or(const char* name, double fallback) override {
    const auto found = values_.find(name);
    return found == values_.end() ? fallback : found->second;
  }
  int particle_index(const char* name) override { return static_cast<int>(values_.at(name)); }
  int edge_index(const char* name) override { return static_cast<int>(values_.at(name)); }
  [[noreturn]] void fail(const std::string& problem) override {
    throw std::invalid_argument(problem);
  }
  [[noreturn]] void fail(const char* name, const std::string& problem) override {
    throw std::invalid_argument(std::string(name) + ": " + problem);
  }

 private:
  std::map<std::string, double> values_;
};

TEST(VortexForce3D, FactoryNormalizesTheAxisAndDefaultsToZ) {
  SceneModel model;
  model.dim = 3;
  model.fixed = {false, false};
  const Vector positions = vec({0.0, 0.0, 0.0, 2.0, 0.0, 0.0});
  const ForceContext context{model, positions};
  const Vector d = vec({2.0, 0.0, 0.0}), dv = vec({0.0, 1.0, 0.0});
  const Vector expected = vec({0.0, 1.0, 0.0, 0.0, -1.0, 0.0});  // as in 2D, about z
  for (const auto& axis :
       {std::map<std::string, double>{{"az", 2.0}}, std::map<std::string, double>{}}) {
    std::map<std::string, double> values{{"i", 0}, {"j", 1}, {"kbs", 3.0}, {"kvc", 2.0}};
    values.insert(axis.begin(), axis.end());
    MapParameters params(values);
    const auto force = make_vortex_force(params, context);
    const auto& vortex = dynamic_cast<const VortexForce<3>&>(*force);
    EXPECT_TRUE(vortex_gradient(vortex, d, dv).isApprox(expected, 1e-15));
  }
  MapParameters zero_axis({{"i", 0}, {"j", 1}, {"kbs", 3.0}, {"kvc", 2.0}, {"az", 0.0}});
  EXPECT_THROW(make_vortex_force(zero_axis, context), std::invalid_argument);
}

TYPED_TEST(VortexForceTest, DerivativesOnRandomConfigurations) {
  constexpr int D = TypeParam::value;
  for (unsigned seed = 71; seed <= 76; ++seed) {
    Random random(seed);
    const PairCase c = random_pair_case(D, random);
    const VortexForce<D> vortex(c.i, c.j, random.uniform(-3.0, 3.0), random.uniform(0.1, 2.0),
                                vortex_rotation<D>(Vec<3>(random.unit_vector(3))));
    check_force_everywhere(vortex, D, c.q, c.v, c.mass,
                           {"vortex", "random", "seed " + std::to_string(seed)});
    EXPECT_GT(asymmetry(hessian_x_of(vortex, c.q, c.v, c.mass)), 1e-3);
    EXPECT_LE(asymmetry(hessian_v_of(vortex, c.q, c.v, c.mass)), 1e-15);
  }
}

TYPED_TEST(VortexForceTest, DerivativesOfNearlyCoincidentParticles) {
  constexpr int D = TypeParam::value;
  Random random(77);
  for (double l : {1e-4, 1e-5, 1e-6}) {
    const PairCase c = pair_at_distance(D, random, l);
    const VortexForce<D> vortex(1, 0, 1.5, 0.4, vortex_rotation<D>(Vec<3>(random.unit_vector(3))));
    check_force_everywhere(vortex, D, c.q, c.v, c.mass,
                           {"vortex", "near-degenerate", "l = " + to_text(l)});
  }
}

}  // namespace
}  // namespace fosssim::testing
