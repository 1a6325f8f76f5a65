#pragma once
// Maps each force's scene-file tag to its factory, in the compat summation order.

#include <span>
#include <string_view>

#include "core/force_parameters.h"

namespace fosssim {

struct ForceKind {
  constexpr ForceKind(std::string_view tag_, ForceFactory create_, int course_theme_ = 1)
      : tag(tag_), create(create_), course_theme(course_theme_) {}

  std::string_view tag;  ///< element name in scene files
  ForceFactory create;
  /// The course theme that introduced the force: a scene with a Theme 4 force is graded with
  /// the Theme 4 program's criteria (Scene::grading_theme).
  int course_theme;
};

/// All force kinds. Forces are summed grouped by kind in this order, each group in document
/// order (course-compatible; docs/scene-format.md, 'Forces'): adding a force is one line here.
std::span<const ForceKind> force_kinds();

/// The kind with this tag, or nullptr.
const ForceKind* find_force_kind(std::string_view tag);

}  // namespace fosssim
