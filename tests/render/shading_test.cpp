#include "render/shading.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace fosssim {
namespace {

constexpr Color kGrey{0.8, 0.8, 0.8};

double brightness(const Color& c) { return c.r + c.g + c.b; }

TEST(ShadeLambert, AFaceTowardTheLightIsBrighterThanOneAway) {
  Lighting light;
  light.to_key = Eigen::Vector3d::UnitY();
  light.to_eye = Eigen::Vector3d::UnitZ();
  const Color toward = shade_lambert(kGrey, Eigen::Vector3d(0, 1, 1), light);
  const Color sideways = shade_lambert(kGrey, Eigen::Vector3d(1, 0, 1), light);
  const Color away = shade_lambert(kGrey, Eigen::Vector3d(0, -1, 1), light);
  EXPECT_GT(brightness(toward), brightness(sideways));
  EXPECT_EQ(sideways, away);  // no key light on either: only the headlight's cos 45°
}

TEST(ShadeLambert, FollowsLambertsCosineLaw) {
  Lighting light;
  light.to_key = Eigen::Vector3d::UnitY();
  light.to_eye = Eigen::Vector3d::UnitZ();
  const Color base{0.5, 0.25, 1.0};
  // Normal at 60° from the key light and 30° from the eye; any length.
  const Eigen::Vector3d normal = 3.0 * Eigen::Vector3d(0.0, 0.5, std::sqrt(0.75));
  const double amount = light.ambient + light.key * 0.5 + light.head * std::sqrt(0.75);
  const Color shaded = shade_lambert(base, normal, light);
  EXPECT_NEAR(shaded.r, 0.5 * amount, 1e-12);
  EXPECT_NEAR(shaded.g, 0.25 * amount, 1e-12);
  EXPECT_NEAR(shaded.b, std::min(1.0, 1.0 * amount), 1e-12);
  // A degenerate face gets the ambient light only.
  EXPECT_NEAR(shade_lambert(base, Eigen::Vector3d::Zero(), light).r, 0.5 * light.ambient, 1e-12);
}

TEST(ShadeTriangle, IsTwoSidedWithTheBackInItsOwnColour) {
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);          // normal +z
  const Eigen::Vector3d from_front(0, 0, -1), from_behind(0, 0, 1);  // view directions
  Lighting light;
  light.to_key = Eigen::Vector3d(0, 0, 1);
  const Color front = shade_triangle(kGrey, a, b, c, from_front, light);
  // Seen from behind with the light behind too: lit the same, but in the back colour.
  light.to_key = Eigen::Vector3d(0, 0, -1);
  const Color back = shade_triangle(kGrey, a, b, c, from_behind, light);
  light.to_eye = -from_behind;  // what shade_triangle takes the eye's direction to be
  EXPECT_EQ(back, shade_lambert(back_side_color(kGrey), Eigen::Vector3d(0, 0, -1), light));
  EXPECT_NE(front, back);
  // Reversing the corners swaps the sides.
  EXPECT_EQ(shade_triangle(kGrey, a, c, b, from_behind, light),
            shade_lambert(kGrey, Eigen::Vector3d(0, 0, -1), light));
}

TEST(CameraLighting, LightsFromAboveLeftAndInFront) {
  const Eigen::Vector3d right = Eigen::Vector3d::UnitX(), up = Eigen::Vector3d::UnitY(),
                        forward = -Eigen::Vector3d::UnitZ();
  const Lighting light = camera_lighting(right, up, forward);
  EXPECT_NEAR(light.to_key.norm(), 1.0, 1e-12);
  EXPECT_LT(light.to_key.dot(right), 0.0);
  EXPECT_GT(light.to_key.dot(up), 0.0);
  EXPECT_LT(light.to_key.dot(forward), 0.0);
  EXPECT_EQ(light.to_eye, -forward);
}

}  // namespace
}  // namespace fosssim
