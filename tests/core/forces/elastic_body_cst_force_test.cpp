// Tests of ElasticBodyCstForce (docs/forces.md, 'Elastic bodies'): the course's constant strain
// triangle in 2D and FOSSSim's membrane version of it in 3D.
//
// Math checked:
// - rest data: B = D̄⁻¹ and Ā for a right triangle, in 2D and for the same triangle tilted in 3D;
// - values: SPEC-elastica's worked example E3 (ε = (0.22, -0.19, 0.09), U = 0.19439560439560455,
//   the forces to the course's bits in 2D, to 1e-15 in 3D);
// - invariance: U and |∇U| do not change under a rotation and a translation of the current
//   corners, nor under a reflection (an inverted triangle has a zero-energy mirror state);
// - derivatives by finite differences on random triangles and on nasty ones: squashed to zero
//   area, inverted, nearly coincident corners, ν near 0.5 and negative, a needle-shaped rest
//   triangle.
// - the semi-definite Hessian (ForceInput::definite_hessian): on random, compressed, squashed
//   and inverted triangles its eigenvalues are those of the exact block with the negative ones
//   set to 0 (so it is semi-definite, xᵀHx ≥ 0, and it differs from an indefinite exact block);
//   on a stretched triangle, whose exact block is already semi-definite, it is the exact block.

#include "core/forces/elastic_body_cst_force.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/Eigenvalues>
#include <cmath>

#include "core/force_evaluation.h"
#include "support/dense.h"
#include "support/finite_differences.h"
#include "support/random.h"
#include "support/typed_tests.h"

namespace fosssim::testing {
namespace {

FOSSSIM_TEST_SUITE_IN_2D_AND_3D(ElasticBodyCstForceTest);

/// Three 2D points as a D-dimensional state (z = 0).
template <int D>
Vector planar(std::initializer_list<double> xy) {
  Vector q = Vector::Zero(3 * D);
  int k = 0;
  for (double value : xy) {
    q[D * (k / 2) + k % 2] = value;
    ++k;
  }
  return q;
}

template <int D>
CstRest rest_of(const Vector& q) {
  return compute_cst_rest<D>(particle_vec<D>(q, 0), particle_vec<D>(q, 1), particle_vec<D>(q, 2));
}

/// A rotation by angle t about a fixed oblique axis (3D) or about the origin (2D).
template <int D>
Mat<D> rotation(double t) {
  if constexpr (D == 2) {
    Mat<2> R;
    R << std::cos(t), -std::sin(t), std::sin(t), std::cos(t);
    return R;
  } else {
    return Eigen::AngleAxisd(t, Eigen::Vector3d(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  }
}

template <int D>
Vector transformed(const Vector& q, const Mat<D>& A, const Vec<D>& shift) {
  Vector out(q.size());
  for (int p = 0; p < q.size() / D; ++p) out.segment<D>(D * p) = A * q.segment<D>(D * p) + shift;
  return out;
}

TYPED_TEST(ElasticBodyCstForceTest, RestDataOfARightTriangle) {
  constexpr int D = TypeParam::value;
  const Vector rest = planar<D>({0, 0, 2, 0, 0, 1});
  const CstRest data = rest_of<D>(rest);
  EXPECT_DOUBLE_EQ(data.area, 1.0);
  EXPECT_TRUE(data.B.isApprox((Mat<2>() << 0.5, 0, 0, 1).finished(), 1e-15));
  // Tilted out of the plane (3D) or turned (2D): same area, and F = I for the rest shape.
  const Vector tilted = transformed<D>(rest, rotation<D>(0.7), Vec<D>::Constant(0.3));
  const CstRest turned = rest_of<D>(tilted);
  EXPECT_NEAR(turned.area, 1.0, 1e-15);
  const ElasticBodyCstForce<D> cst({0, 1, 2}, 5.0, 0.3, turned);
  EXPECT_NEAR(energy_of(cst, tilted, Vector::Zero(3 * D), Vector::Ones(3 * D)), 0.0, 1e-28);
  EXPECT_LE(gradient_of(cst, tilted, Vector::Zero(3 * D), Vector::Ones(3 * D)).norm(), 1e-14);
}

TYPED_TEST(ElasticBodyCstForceTest, ItsElementForPicturesHasThePrincipalStretchAndDensity) {
  constexpr int D = TypeParam::value;
  const Vector rest = planar<D>({0, 0, 1, 0, 0, 1});
  const ElasticBodyCstForce<D> force({0, 1, 2}, 10.0, 0.3, rest_of<D>(rest));
  std::vector<ForceElement> elements;
  force.append_elements(rest, elements);
  ASSERT_EQ(elements.size(), 1u);
  EXPECT_EQ(elements[0].kind, ForceElement::Kind::kTriangle);
  EXPECT_EQ(elements[0].particles, (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(elements[0].strain, 0.0);
  EXPECT_EQ(elements[0].energy_density, 0.0);
  // Stretched 30% along x and compressed 10% along y, then rotated: principal stretches 1.3
  // and 0.9, so λ - 1 = 0.3 wins; ε = (0.69, -0.19, 0), U / Ā = E/(2(1-ν²)) (εxx² + 2ν εxx εyy
  // + εyy²).
  const Vector stretched = transformed<D>(
      rest, rotation<D>(0.7) * Vec<D>(Vec<D>::Ones() + Vec<D>::Unit(0) * 0.3 - Vec<D>::Unit(1) * 0.1)
                                   .asDiagonal(),
      Vec<D>::Constant(0.25));
  force.append_elements(stretched, elements);
  ASSERT_EQ(elements.size(), 2u);
  EXPECT_NEAR(elements[1].strain, 0.3, 1e-14);
  const double exx = 0.69, eyy = -0.19;
  EXPECT_NEAR(elements[1].energy_density,
              10.0 / (2.0 * (1.0 - 0.09)) * (exx * exx + 0.6 * exx * eyy + eyy * eyy), 1e-13);
  // Compressed more than stretched: the negative principal value wins.
  const Vector squeezed = transformed<D>(
      rest, Vec<D>(Vec<D>::Ones() + Vec<D>::Unit(0) * 0.05 - Vec<D>::Unit(1) * 0.2).asDiagonal(),
      Vec<D>::Zero());
  force.append_elements(squeezed, elements);
  EXPECT_NEAR(elements[2].strain, -0.2, 1e-14);
}

TYPED_TEST(ElasticBodyCstForceTest, MatchesWorkedExampleE3) {
  constexpr int D = TypeParam::value;
  const CstRest rest = rest_of<D>(planar<D>({0, 0, 1, 0, 0, 1}));
  const Vector q = planar<D>({0, 0, 1.1, 0.1, 0, 0.9});
  const Vector v = Vector::Zero(3 * D);
  const Vector mass = Vector::Ones(3 * D);
  const ElasticBodyCstForce<D> cst({0, 1, 2}, 10.0, 0.3, rest);
  EXPECT_NEAR(energy_of(cst, q, v, mass), 0.19439560439560455, 1e-16);
  const Vector F = -gradient_of(cst, q, v, mass);
  const double expected[6] = {2.7318681318681346, -0.35494505494505368, -1.9703296703296729,
                              -0.80219780219780246, -0.7615384615384615, 1.1571428571428561};
  for (int p = 0; p < 3; ++p) {
    for (int c = 0; c < 2; ++c) {
      if constexpr (D == 2) {
        EXPECT_EQ(F[2 * p + c], expected[2 * p + c]) << "particle " << p << " coordinate " << c;
      } else {
        EXPECT_NEAR(F[3 * p + c], expected[2 * p + c], 1e-15);
        EXPECT_EQ(F[3 * p + 2], 0.0);
      }
    }
  }
}

TYPED_TEST(ElasticBodyCstForceTest, InvariantUnderRigidMotionsAndReflections) {
  constexpr int D = TypeParam::value;
  Random random(91);
  const Vector rest_q = random.uniform_vector(3 * D, -1.0, 1.0);
  const ElasticBodyCstForce<D> cst({0, 1, 2}, 3.0, 0.25, rest_of<D>(rest_q));
  const Vector q = random.uniform_vector(3 * D, -1.0, 1.0);
  const Vector v = Vector::Zero(3 * D);
  const Vector mass = Vector::Ones(3 * D);
  const double U = energy_of(cst, q, v, mass);
  const double force_size = gradient_of(cst, q, v, mass).norm();
  Mat<D> mirror = Mat<D>::Identity();
  mirror(0, 0) = -1.0;
  for (const Mat<D>& A : {rotation<D>(1.1), Mat<D>(mirror), Mat<D>(rotation<D>(-0.4) * mirror)}) {
    const Vector moved = transformed<D>(q, A, Vec<D>::Constant(2.5));
    EXPECT_NEAR(energy_of(cst, moved, v, mass), U, 1e-12 * U);
    EXPECT_NEAR(gradient_of(cst, moved, v, mass).norm(), force_size, 1e-12 * force_size);
  }
  // The mirror image of the rest shape is a zero-energy state of the inverted triangle, where
  // the derivatives are still right (checked, not recorded: its gradient is round-off).
  const Vector mirrored_rest = transformed<D>(rest_q, mirror, Vec<D>::Zero());
  EXPECT_NEAR(energy_of(cst, mirrored_rest, v, mass), 0.0, 1e-24);
  check_force_everywhere(cst, D, mirrored_rest, v, mass, {"elastic-cst", kAtRest, "mirrored"});
}

TYPED_TEST(ElasticBodyCstForceTest, DerivativesOnRandomTriangles) {
  constexpr int D = TypeParam::value;
  for (unsigned seed = 92; seed <= 98; ++seed) {
    Random random(seed);
    const Vector rest_q = random.uniform_vector(3 * D, -1.0, 1.0);
    const Vector q = random.uniform_vector(4 * D, -1.0, 1.0);  // particle 3 is a bystander
    const Vector v = random.uniform_vector(4 * D, -1.0, 1.0);
    const Vector mass = random.uniform_vector(4 * D, 0.5, 2.0);
    const ElasticBodyCstForce<D> cst({3, 0, 2}, random.uniform(0.5, 100.0),
                                     random.uniform(-0.9, 0.9), rest_of<D>(rest_q));
    check_force_everywhere(cst, D, q, v, mass,
                           {"elastic-cst", "random", "seed " + std::to_string(seed)});
    EXPECT_LE(asymmetry(hessian_x_of(cst, q, v, mass)), 1e-12);
    EXPECT_TRUE(hessian_v_of(cst, q, v, mass).isZero(0.0));
  }
}

TYPED_TEST(ElasticBodyCstForceTest, DerivativesOnNastyTriangles) {
  constexpr int D = TypeParam::value;
  const Vector v = Vector::Zero(3 * D);
  const Vector mass = Vector::Ones(3 * D);
  const CstRest right = rest_of<D>(planar<D>({0, 0, 1, 0, 0, 1}));
  const CstRest needle = rest_of<D>(planar<D>({0, 0, 1, 0, 0.5, 1e-3}));
  struct Case {
    Vector q;
    const CstRest* rest;
    double nu;
    const char* name;
  };
  const Case cases[] = {
      {planar<D>({0, 0, 1, 0, 2, 0}), &right, 0.3, "squashed to a segment"},
      {planar<D>({0.2, 0.2, 0.2, 0.2, 0.2, 0.2}), &right, 0.3, "squashed to a point"},
      {planar<D>({0, 0, 1, 0, 0.3, -0.8}), &right, 0.3, "inverted"},
      {planar<D>({0.1, 0, 1.3, 0.2, 0.5, -0.05}), &right, 0.45, "inverted, nearly flat"},
      {planar<D>({0, 0, 1, 0, 0.3, 1e-9}), &right, 0.3, "nearly flat"},
      {planar<D>({0, 0, 1e-4, 0, 0, 1e-4}), &right, 0.3, "tiny"},
      {planar<D>({0, 0, 1.2, 0.1, -0.1, 0.8}), &right, 0.499, "nu near 0.5"},
      {planar<D>({0, 0, 1.2, 0.1, -0.1, 0.8}), &right, -0.9, "negative nu"},
      {planar<D>({0, 0, 1.5, 0.2, 0.4, 0.3}), &needle, 0.45, "needle rest shape"},
  };
  for (const Case& c : cases) {
    const ElasticBodyCstForce<D> cst({0, 1, 2}, 7.0, c.nu, *c.rest);
    check_force_everywhere(cst, D, c.q, v, mass, {"elastic-cst", "near-degenerate", c.name});
    EXPECT_TRUE(std::isfinite(energy_of(cst, c.q, v, mass))) << c.name;
    EXPECT_TRUE(gradient_of(cst, c.q, v, mass).allFinite()) << c.name;
    EXPECT_TRUE(hessian_x_of(cst, c.q, v, mass).allFinite()) << c.name;
  }
}

TYPED_TEST(ElasticBodyCstForceTest, DefiniteHessianIsTheExactBlockWithNegativeEigenvaluesClamped) {
  constexpr int D = TypeParam::value;
  const CstRest right = rest_of<D>(planar<D>({0, 0, 1, 0, 0, 1}));
  struct Case {
    Vector q;
    const char* name;
  };
  // Each exact block has an eigenvalue below -1e-3 of its largest (checked below).
  const Case cases[] = {
      {planar<D>({0, 0, 0.6, 0, 0, 0.7}), "compressed"},
      {planar<D>({0, 0, 0.5, 0.1, -0.1, 1.2}), "compressed in x, stretched in y"},
      {planar<D>({0, 0, 0.5, 0, 0.25, 0}), "squashed to a short segment"},
      {planar<D>({0.2, 0.2, 0.2, 0.2, 0.2, 0.2}), "squashed to a point"},
      {planar<D>({0, 0, 1, 0, 0.3, -0.8}), "inverted"},
  };
  for (const Case& c : cases) {
    const ElasticBodyCstForce<D> cst({0, 1, 2}, 7.0, 0.3, right);
    const Eigen::MatrixXd exact = hessian_x_of(cst, c.q, Vector::Zero(3 * D), Vector::Ones(3 * D));
    const Eigen::MatrixXd projected =
        definite_hessian_x_of(cst, c.q, Vector::Zero(3 * D), Vector::Ones(3 * D));
    const double relative_min = expect_semidefinite_projection(exact, projected, c.name);
    EXPECT_LT(relative_min, -1e-3) << c.name << ": the case should test a projection";
    EXPECT_GT((projected - exact).norm(), 1e-3 * exact.norm()) << c.name;
  }
  {
    // Squashed onto a segment twice the rest legs' length: stretched (ε = (0, 3, 2)), and its
    // exact block happens to be semi-definite; the projection must keep it.
    const ElasticBodyCstForce<D> cst({0, 1, 2}, 7.0, 0.3, right);
    const Vector q = planar<D>({0, 0, 1, 0, 2, 0});
    const Eigen::MatrixXd exact = hessian_x_of(cst, q, Vector::Zero(3 * D), Vector::Ones(3 * D));
    EXPECT_GT(expect_semidefinite_projection(
                  exact, definite_hessian_x_of(cst, q, Vector::Zero(3 * D), Vector::Ones(3 * D)),
                  "squashed to a long segment"),
              -1e-12);
  }
  for (unsigned seed = 92; seed <= 98; ++seed) {
    Random random(seed);
    const Vector rest_q = random.uniform_vector(3 * D, -1.0, 1.0);
    const Vector q = random.uniform_vector(4 * D, -1.0, 1.0);  // particle 3 is a bystander
    const ElasticBodyCstForce<D> cst({3, 0, 2}, random.uniform(0.5, 100.0),
                                     random.uniform(-0.9, 0.9), rest_of<D>(rest_q));
    const Eigen::MatrixXd exact = hessian_x_of(cst, q, Vector::Zero(4 * D), Vector::Ones(4 * D));
    expect_semidefinite_projection(
        exact, definite_hessian_x_of(cst, q, Vector::Zero(q.size()), Vector::Ones(q.size())),
        "random, seed " + std::to_string(seed));
  }
}

TYPED_TEST(ElasticBodyCstForceTest, DefiniteHessianOfAStretchedTriangleIsTheExactOne) {
  constexpr int D = TypeParam::value;
  const Vector rest = planar<D>({0, 0, 1, 0, 0, 1});
  // Stretched by 1.2 in every direction, then turned: ε = 0.44 I, σ ≥ 0 and εxy = 0, so every
  // term of the exact block is semi-definite.
  const Vector q = transformed<D>(1.2 * rest, rotation<D>(0.4), Vec<D>::Constant(0.1));
  const ElasticBodyCstForce<D> cst({0, 1, 2}, 7.0, 0.3, rest_of<D>(rest));
  const Eigen::MatrixXd exact = hessian_x_of(cst, q, Vector::Zero(3 * D), Vector::Ones(3 * D));
  const Eigen::VectorXd lambda =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(exact, Eigen::EigenvaluesOnly).eigenvalues();
  ASSERT_GE(lambda.minCoeff(), -1e-12 * lambda.maxCoeff());
  const Eigen::MatrixXd projected =
      definite_hessian_x_of(cst, q, Vector::Zero(q.size()), Vector::Ones(q.size()));
  EXPECT_LE((projected - exact).cwiseAbs().maxCoeff(), 1e-12 * lambda.maxCoeff());
}

}  // namespace
}  // namespace fosssim::testing
