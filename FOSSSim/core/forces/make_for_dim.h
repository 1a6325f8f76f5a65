#pragma once

#include <memory>

#include "core/force.h"

namespace fosssim {

/// Constructs ForceT<2> or ForceT<3> according to the scene's dimension.
template <template <int> class ForceT, typename... Args>
std::unique_ptr<Force> make_for_dim(int dim, Args&&... args) {
  if (dim == 3) return std::make_unique<ForceT<3>>(std::forward<Args>(args)...);
  return std::make_unique<ForceT<2>>(std::forward<Args>(args)...);
}

}  // namespace fosssim
