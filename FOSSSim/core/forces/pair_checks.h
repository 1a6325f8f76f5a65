#pragma once

#include <string>
#include <utility>

#include "core/force_parameters.h"
#include "core/scene_model.h"

namespace fosssim {

/// Reads the particle indices "i" and "j" of a pair force and rejects i = j and particles that
/// start at the same point, where the pair's direction is undefined.
inline std::pair<int, int> read_distinct_separated_pair(ForceParameters& params,
                                                        const ForceContext& context) {
  const int i = params.particle_index("i");
  const int j = params.particle_index("j");
  if (i == j) params.fail("j", "must differ from i (both are " + std::to_string(i) + ")");
  const int dim = context.model.dim;
  if (context.positions.segment(dim * i, dim) == context.positions.segment(dim * j, dim)) {
    params.fail("particles " + std::to_string(i) + " and " + std::to_string(j) +
                " start at the same point, where the force is undefined");
  }
  return {i, j};
}

}  // namespace fosssim
