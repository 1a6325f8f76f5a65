#pragma once
// Shading of surfaces in 3D pictures: Lambert's law for a key light and a headlight, two-sided.

#include <Eigen/Core>

#include "core/scene.h"

namespace fosssim {

/// How much light reaches a surface: a constant ambient part, a key light from above and to
/// the left of the viewer, and a headlight from the viewer, each by Lambert's cosine law. The
/// headlight keeps every face in view lit, darker as it turns edge-on.
struct Lighting {
  Eigen::Vector3d to_key = Eigen::Vector3d::UnitY();  ///< unit, toward the key light
  Eigen::Vector3d to_eye = Eigen::Vector3d::UnitZ();  ///< unit, toward the viewer
  double ambient = 0.35;
  double key = 0.45;
  double head = 0.3;
};

/// Lambert shading: base · (ambient + key · max(0, n · l) + head · max(0, n · e)) for the unit
/// surface normal n (toward the side seen), l toward the key light and e toward the eye, each
/// component clamped to [0, 1]. `normal` need not be unit length; a zero normal gets the
/// ambient part only.
Color shade_lambert(const Color& base, const Eigen::Vector3d& normal, const Lighting& light);

/// The colour of the back of a two-sided surface (the side opposite its corners'
/// counter-clockwise normal): the front colour mixed a third of the way toward grey, so the
/// inside of a cloth reads apart from its outside.
Color back_side_color(const Color& front);

/// How the back of a two-sided surface is coloured.
enum class BackSide {
  kTinted,  ///< back_side_color(front): the inside of a cloth reads apart from its outside
  kSame,    ///< the front colour: the colour carries a value (strain, energy) on either side
};

/// The shaded colour of a triangle with corners a, b, c seen along `view` (from the eye toward
/// the triangle): two-sided, so the normal (b - a) × (c - a) is turned toward the viewer, and
/// the back side takes back_side_color(front) unless `back` is BackSide::kSame.
/// `light.to_eye` is taken as -view (normalised).
Color shade_triangle(const Color& front, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                     const Eigen::Vector3d& c, const Eigen::Vector3d& view, Lighting light,
                     BackSide back = BackSide::kTinted);

/// The lighting of a 3D picture, fixed to the camera: the key light from above, to the left of
/// and in front of the viewer. right, up, forward: the camera's unit axes (forward from the eye
/// into the scene).
Lighting camera_lighting(const Eigen::Vector3d& right, const Eigen::Vector3d& up,
                         const Eigen::Vector3d& forward);

}  // namespace fosssim
