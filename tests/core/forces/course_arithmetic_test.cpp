// The forces' kernels give the course's floating-point results bit for bit (docs/forces.md,
// 'Course-exact arithmetic').
//
// Math checked, with values the course's reference program printed (worked example E1 of the
// course-compatibility notes) or the formulas written out here in their order of operations:
// - E1: a spring k = 2, l0 = 1 from (0, 0) to (0.1, 0.2), both of mass 1 at rest, one symplectic
//   Euler step with h = 1: v1 = (0.69442719099991579, 1.3888543819998316) exactly, where
//   n = d ÷ l would give (0.6944271909999159, 1.3888543819998318);
// - E1's hessX elastic entry H_xx = ((((1 - n_x²)(l - l0)) (1/l)) + n_x²) k =
//   -5.1554175279993277 exactly (k (P + ((l - l0) ÷ l)(I - P)) gives -5.1554175279993268);
// - the damping block (b/l)(M - M P), M = n dvᵀ + (n·dv) I, entry by entry, and hessV
//   (b n_r) n_c, against the formulas written out here;
// - Newtonian gravity's gradient ((d_c (1/l)) (((m_j G) m_i) ÷ l²)) and hessX
//   (δ_rc - (3 n_r) n_c) (((m_j G) m_i) ÷ l³), and the vortex's
//   (((R n)_c kbs - dv_c)(1/l²)) kvc, against the formulas written out here.

#include <gtest/gtest.h>

#include <cmath>

#include "core/force_evaluation.h"
#include "core/forces/gravitational_force.h"
#include "core/forces/spring_force.h"
#include "core/forces/spring_kernel.h"
#include "core/forces/vortex_force.h"
#include "support/dense.h"
#include "support/scene_builder.h"

namespace fosssim::testing {
namespace {

TEST(CourseArithmetic, SpringStepOfWorkedExampleE1IsTheCoursesToTheLastBit) {
  TestScene scene(2, "symplectic-euler", 1.0);
  scene.add_particle(1.0, vec({0.0, 0.0}), vec({0.0, 0.0}));
  scene.add_particle(1.0, vec({0.1, 0.2}), vec({0.0, 0.0}));
  scene.add_spring(0, 1, 2.0, 1.0);
  const State next = run_steps(scene.model, scene.initial, 1);
  EXPECT_EQ(next.v[0], -0.69442719099991579);
  EXPECT_EQ(next.v[1], -1.3888543819998316);
  EXPECT_EQ(next.v[2], 0.69442719099991579);
  EXPECT_EQ(next.v[3], 1.3888543819998316);
  // The naive n = d ÷ l is one unit in the last place away: the test can tell them apart.
  EXPECT_NE(next.v[2], 0.6944271909999159);
}

TEST(CourseArithmetic, SpringElasticHessianOfWorkedExampleE1) {
  const Vec<2> d(0.1, 0.2);
  EXPECT_EQ(ordered_norm<2>(d), 0.22360679774997899);
  const SpringHessianParts<2> parts =
      spring_hessian_x_parts<2>(d, Vec<2>::Zero(), 2.0, 1.0, 0.0, false);
  EXPECT_EQ(parts.elastic(0, 0), -5.1554175279993277);
  EXPECT_NE(parts.elastic(0, 0), -5.1554175279993268);
  // Through the force and its pair pattern: +H on (0, 0), -H on (0, 1).
  Vector q = vec({0.0, 0.0, 0.1, 0.2});
  Vector v = Vector::Zero(4);
  Vector mass = Vector::Ones(4);
  const SpringForce<2> spring(0, 1, 2.0, 1.0, 0.0);
  HessianBuilder builder;
  spring.add_hessian_x(ForceInput{q, v, mass}, builder);
  const Eigen::MatrixXd H(builder.build(4));
  EXPECT_EQ(H(0, 0), -5.1554175279993277);
  EXPECT_EQ(H(0, 2), 5.1554175279993277);
}

TEST(CourseArithmetic, SpringDampingBlocksAreWrittenInTheCoursesOrder) {
  const Vec<2> d(0.3, -0.7), dv(1.3, 0.45);
  const double k = 3.0, l0 = 0.5, b = 0.7;
  const double l = std::sqrt(d[0] * d[0] + d[1] * d[1]);
  const double r = 1.0 / l;
  const double nx = d[0] * r, ny = d[1] * r;
  const double pxx = nx * nx, pxy = nx * ny, pyy = ny * ny;
  const double t1 = nx * dv[0], t2 = nx * dv[1], t3 = ny * dv[1], t4 = ny * dv[0];
  const double c = t1 + t3;
  const double mxx = t1 + c, mxy = t2, myx = t4, myy = c + t3;
  const double qxx = mxx * pxx + pxy * t2, qxy = mxx * pxy + pyy * t2;
  const double qyx = pxx * t4 + pxy * myy, qyy = pxy * t4 + pyy * myy;
  const double phi = (-b) / l;
  const SpringHessianParts<2> parts = spring_hessian_x_parts<2>(d, dv, k, l0, b, false);
  EXPECT_EQ(parts.damping(0, 0), -((mxx - qxx) * phi));
  EXPECT_EQ(parts.damping(0, 1), -((mxy - qxy) * phi));
  EXPECT_EQ(parts.damping(1, 0), -((myx - qyx) * phi));
  EXPECT_EQ(parts.damping(1, 1), -((myy - qyy) * phi));
  const double lambda = l - l0;
  EXPECT_EQ(parts.elastic(0, 1), ((((0.0 - pxy) * lambda) * r) + pxy) * k);
  EXPECT_EQ(parts.elastic(1, 1), ((((1.0 - pyy) * lambda) * r) + pyy) * k);
  const Mat<2> V = spring_hessian_v<2>(d, l0, b);
  EXPECT_EQ(V(0, 1), (b * nx) * ny);
  EXPECT_EQ(V(1, 0), nx * (b * ny));
  // The gradient: elastic and damping accumulated one after the other.
  const SpringForceParts<2> f = spring_force_on_i<2>(d, dv, k, l0, b);
  EXPECT_EQ(f.elastic[0], ((l - l0) * k) * nx);
  EXPECT_EQ(f.damping[1], ((dv[0] * nx + dv[1] * ny) * b) * ny);
  Vector g = vec({0.25, -1.5, 0.125, 3.0});
  add_spring_gradient<2>(0, 1, f, g);
  EXPECT_EQ(g[0], (0.25 - f.elastic[0]) - f.damping[0]);
  EXPECT_EQ(g[3], (3.0 + f.elastic[1]) + f.damping[1]);
}

TEST(CourseArithmetic, GravitationAndVortexFollowTheCoursesOrder) {
  const Vector q = vec({0.1, -0.3, 1.7, 0.9});
  const Vector v = vec({0.2, 0.5, -0.4, 1.1});
  const Vector mass = vec({2.5, 2.5, 0.7, 0.7});
  const double G = 0.37;
  const double dx = 1.7 - 0.1, dy = 0.9 - (-0.3);
  const double l = std::sqrt(dx * dx + dy * dy);
  const double r = 1.0 / l;
  const Vector g = gradient_of(GravitationalForce<2>(0, 1, G), q, v, mass);
  const double s = ((0.7 * G) * 2.5) / (l * l);
  EXPECT_EQ(g[0], 0.0 - (dx * r) * s);
  EXPECT_EQ(g[3], 0.0 + (dy * r) * s);
  HessianBuilder builder;
  GravitationalForce<2>(0, 1, G).add_hessian_x(ForceInput{q, v, mass}, builder);
  const Eigen::MatrixXd H(builder.build(4));
  const double sigma = ((0.7 * G) * 2.5) / ((l * l) * l);
  const double nx = dx * r, ny = dy * r;
  EXPECT_EQ(H(0, 0), (1.0 - nx * (3.0 * nx)) * sigma);
  EXPECT_EQ(H(0, 1), (0.0 - (3.0 * nx) * ny) * sigma);
  EXPECT_EQ(H(1, 0), (0.0 - nx * (3.0 * ny)) * sigma);

  Mat<2> rotation;
  rotation << 0.0, -1.0, 1.0, 0.0;
  const double kbs = 1.3, kvc = 0.8;
  const Vector w = gradient_of(VortexForce<2>(0, 1, kbs, kvc, rotation), q, v, mass);
  const double inverse_square = 1.0 / (l * l);
  const double wx = ((-(ny * kbs) - (-0.4 - 0.2)) * inverse_square) * kvc;
  const double wy = ((nx * kbs - (1.1 - 0.5)) * inverse_square) * kvc;
  EXPECT_EQ(w[0], wx);
  EXPECT_EQ(w[1], wy);
  EXPECT_EQ(w[2], -wx);
  EXPECT_EQ(w[3], -wy);
}

}  // namespace
}  // namespace fosssim::testing
