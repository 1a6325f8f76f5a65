// Tests of the library's finite-difference checker (core/analysis/derivative_check.h), so that
// the force tests that rely on it cannot pass vacuously.
//
// Math checked:
// - the checker FAILS on forces whose derivatives are deliberately wrong by a small amount:
//   hessX scaled by 1 + 1e-4, hessX with the wrong sign, the damping hessX transposed
//   ((b/l)(I - P)[dv nᵀ + (n·dv) I] instead of (b/l)[n dvᵀ + (n·dv) I](I - P)), hessV scaled by
//   1 + 1e-4, hessV missing, an energy that is off by one part in 10⁴, a NaN in hessX; and it
//   names the wrong derivative and only that one. The test's own full-matrix check flags the
//   same faults.
// - the checker PASSES where round-off, not a wrong derivative, is all there is: springs at
//   exactly their rest length (gradE = 0 up to round-off, along an axis and in general
//   position) and a 1e-6-long compressed spring at distance ~1 from the origin, where the
//   rounding of x ± εu is 1e-6 of the step ε = 1e-10.
// - check_model_derivatives covers every force (3 checks each, 2 for forces without a
//   potential) and suggest_finite_difference_step is 1e-4 times the shortest distance, ≤ 1e-4.

#include "core/analysis/derivative_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/forces/spring_force.h"
#include "core/forces/vortex_force.h"
#include "support/closed_forms.h"
#include "support/finite_differences.h"
#include "support/random.h"
#include "support/scene_builder.h"
#include "support/typed_tests.h"

namespace fosssim::testing {
namespace {

enum class Fault {
  kHessianXScaled,
  kHessianXNegated,
  kHessianXTransposed,
  kHessianVScaled,
  kHessianVMissing,
  kEnergyScaled,
  kHessianXNaN,
};

/// A damped spring between particles 0 and 1 with exactly one deliberate mistake.
template <int D>
class FaultySpring final : public Force {
 public:
  explicit FaultySpring(Fault fault) : spring_(0, 1, 3.0, 0.4, 0.6), fault_(fault) {}

  void add_energy(const ForceInput& in, double& energy) const override {
    double own = 0.0;
    spring_.add_energy(in, own);
    energy += fault_ == Fault::kEnergyScaled ? (1.0 + 1e-4) * own : own;
  }
  void add_gradient(const ForceInput& in, Vector& gradient) const override {
    spring_.add_gradient(in, gradient);
  }
  void add_hessian_x(const ForceInput& in, HessianBuilder& hessian) const override {
    HessianBuilder own;
    spring_.add_hessian_x(in, own);
    for (const Triplet& t : own.triplets()) {
      double value = t.value();
      int row = t.row(), col = t.col();
      if (fault_ == Fault::kHessianXScaled) value *= 1.0 + 1e-4;
      if (fault_ == Fault::kHessianXNegated) value = -value;
      if (fault_ == Fault::kHessianXTransposed) std::swap(row, col);
      if (fault_ == Fault::kHessianXNaN && row == 0 && col == 0) value = std::nan("");
      hessian.add_entry(row, col, value);
    }
  }
  void add_hessian_v(const ForceInput& in, HessianBuilder& hessian) const override {
    if (fault_ == Fault::kHessianVMissing) return;
    HessianBuilder own;
    spring_.add_hessian_v(in, own);
    const double factor = fault_ == Fault::kHessianVScaled ? 1.0 + 1e-4 : 1.0;
    for (const Triplet& t : own.triplets()) {
      hessian.add_entry(t.row(), t.col(), factor * t.value());
    }
  }
  bool is_conservative() const override { return false; }
  bool has_symmetric_jacobians() const override { return false; }
  std::string label() const override { return "faulty spring"; }

 private:
  SpringForce<D> spring_;
  Fault fault_;
};

struct FaultCase {
  Fault fault;
  Derivative wrong;
  const char* name;
};

const FaultCase kFaults[] = {
    {Fault::kHessianXScaled, Derivative::kHessianX, "hessX scaled by 1 + 1e-4"},
    {Fault::kHessianXNegated, Derivative::kHessianX, "hessX negated"},
    {Fault::kHessianXTransposed, Derivative::kHessianX, "damping hessX transposed"},
    {Fault::kHessianVScaled, Derivative::kHessianV, "hessV scaled by 1 + 1e-4"},
    {Fault::kHessianVMissing, Derivative::kHessianV, "hessV missing"},
    {Fault::kEnergyScaled, Derivative::kGradient, "energy scaled by 1 + 1e-4"},
    {Fault::kHessianXNaN, Derivative::kHessianX, "NaN in hessX"},
};

FOSSSIM_TEST_SUITE_IN_2D_AND_3D(DerivativeCheckTest);

TYPED_TEST(DerivativeCheckTest, FailsOnEachDeliberatelyWrongDerivative) {
  constexpr int D = TypeParam::value;
  Random random(21);
  const Vector q = random.uniform_vector(3 * D, -1.0, 1.0);
  const Vector v = random.uniform_vector(3 * D, -1.0, 1.0);
  const Vector mass = Vector::Ones(3 * D);
  for (const FaultCase& fault : kFaults) {
    SCOPED_TRACE(fault.name);
    const FaultySpring<D> force(fault.fault);
    DerivativeCheckOptions options;
    options.step = suggest_finite_difference_step(q, D);
    const auto checks = check_force_derivatives(force, q, v, mass, options);
    ASSERT_EQ(checks.size(), 3u);
    for (const DerivativeCheck& check : checks) {
      EXPECT_EQ(check.force, "faulty spring");
      EXPECT_EQ(check.passed(), check.which != fault.wrong)
          << derivative_name(check.which) << ": allowance used " << check.allowance_used;
    }
    // The test's own full-matrix check sees the same fault.
    const double length = configuration_length(q, D);
    const MatrixComparison full =
        fault.wrong == Derivative::kGradient
            ? compare_gradient_full(force, q, mass, kGradientStep * length)
            : compare_hessian_full(force, q, v, mass, fault.wrong == Derivative::kHessianV,
                                   kHessianStep * length);
    EXPECT_FALSE(full.passes(kFullMatrixTolerance)) << "relative error " << full.relative_error();
  }
}

TYPED_TEST(DerivativeCheckTest, PassesOnSpringsAtExactlyTheirRestLength) {
  constexpr int D = TypeParam::value;
  // An axis-aligned chain 0 - 1 - 2 at rest (gradE is exactly 0), the most common scene there
  // is, and a spring in general position whose l0 is its computed length.
  Vector q = Vector::Zero(3 * D);
  q[D] = 1.0;
  q[2 * D] = 2.0;
  const Vector v = Vector::Zero(3 * D), mass = Vector::Ones(3 * D);
  Random random(22);
  Vector general = random.uniform_vector(3 * D, -1.0, 1.0);
  const double rest = (general.segment(D, D) - general.segment(0, D)).norm();
  for (const auto& [positions, l0] : {std::pair{q, 1.0}, std::pair{general, rest}}) {
    for (double b : {0.0, 1.0}) {
      DerivativeCheckOptions options;
      options.step = suggest_finite_difference_step(positions, D);
      for (const auto& check : check_force_derivatives(SpringForce<D>(0, 1, 10.0, l0, b), positions,
                                                       v, mass, options)) {
        EXPECT_TRUE(check.passed())
            << derivative_name(check.which) << " b = " << b << ": absolute error "
            << check.absolute_error << ", allowance used " << check.allowance_used;
        // What is left is round-off: k = 10 times a few ε_machine.
        if (check.which == Derivative::kGradient) {
          EXPECT_LT(check.absolute_error, 1e-13);
        }
      }
    }
  }
  check_force_everywhere(SpringForce<D>(0, 1, 10.0, 1.0, 0.0), D, q, v, mass,
                         {"spring", kAtRest, "axis-aligned chain"});
  check_force_everywhere(SpringForce<D>(0, 1, 10.0, rest, 0.0), D, general, v, mass,
                         {"spring", kAtRest, "general position"});
}

TYPED_TEST(DerivativeCheckTest, PassesOnAShortSpringFarFromTheOrigin) {
  constexpr int D = TypeParam::value;
  Random random(23);
  const Vector c = Vector::Constant(D, 0.9) + random.uniform_vector(D, 0.0, 0.1);
  Vector q(2 * D);
  q << c, c + 1e-6 * random.unit_vector(D);
  const Vector v = random.uniform_vector(2 * D, -1.0, 1.0), mass = Vector::Ones(2 * D);
  DerivativeCheckOptions options;
  options.step = suggest_finite_difference_step(q, D);
  ASSERT_NEAR(options.step, 1e-10, 1e-15);  // the pair's distance is 1e-6 up to rounding at |c|
  for (const auto& check :
       check_force_derivatives(SpringForce<D>(0, 1, 3.0, 1.0, 0.5), q, v, mass, options)) {
    EXPECT_TRUE(check.passed()) << derivative_name(check.which) << ": relative error "
                                << check.relative_error();
    // The Hessians are now checked as tightly as anywhere. (The gradient is checked against
    // differences of U ≈ ½k l0² over 1e-10, which round-off limits to ε|U|/(ε·|gradE|) ≈ 1e-6.)
    if (check.which != Derivative::kGradient) {
      EXPECT_LT(check.relative_error(), 1e-7) << derivative_name(check.which);
    }
  }
}

TEST(DerivativeCheckModel, ChecksEveryForceOfAModel) {
  TestScene scene(2);
  scene.add_particle(1.0, vec({0.0, 0.0}), vec({0.0, 0.0}));
  scene.add_particle(2.0, vec({1.0, 0.5}), vec({0.3, -0.2}));
  scene.add_spring(0, 1, 2.0, 0.5, 0.1);
  scene.add_gravitation(0, 1, 0.7);
  scene.add_force(std::make_unique<VortexForce<2>>(0, 1, 1.0, 0.5, rotation_2d()));
  const auto checks = check_model_derivatives(scene.model, scene.initial.q, scene.initial.v, {});
  ASSERT_EQ(checks.size(), 3u + 3u + 2u);  // the vortex has no potential: no gradient check
  EXPECT_EQ(checks[0].force, "springforce(0, 1)");
  EXPECT_EQ(checks[3].force, "gravitationalforce(0, 1)");
  EXPECT_EQ(checks[6].force, "vortexforce(0, 1)");
  EXPECT_EQ(checks[6].which, Derivative::kHessianX);
  for (const auto& check : checks) EXPECT_TRUE(check.passed()) << check.force;
}

TEST(DerivativeCheckStep, IsATenThousandthOfTheShortestDistanceAtMostOneTenThousandth) {
  const Vector q = vec({0.0, 0.0, 3.0, 4.0, 0.0, 0.0, 0.0, 0.02});  // 0 and 2 coincide
  EXPECT_DOUBLE_EQ(suggest_finite_difference_step(q, 2), 1e-4 * 0.02);
  EXPECT_DOUBLE_EQ(suggest_finite_difference_step(vec({0.0, 0.0, 300.0, 400.0}), 2), 1e-4);
  EXPECT_DOUBLE_EQ(suggest_finite_difference_step(vec({1.0, 2.0, 3.0}), 3), 1e-4);
}

}  // namespace
}  // namespace fosssim::testing
