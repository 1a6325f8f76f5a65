#pragma once
// The attributes of <integrator> that only some methods have.

#include "core/scene_model.h"
#include "io/element_reader.h"

namespace fosssim {

/// Reads the method-specific attributes of an <integrator> element whose kind is already in
/// settings.kind, with their defaults (docs/scenes-3d.md):
///   local-global:  iterations (≥ 1, 10), tolerance (m, ≥ 0, 0 = none),
///                  pins ("elimination" | "penalty"), penalty (N/m, > 0, 1e10),
///                  solver ("auto" | "dense" | "sparse")
///   linearly-implicit-euler:  hessian ("exact" | "projected")
/// Other methods read nothing here, so their other attributes are reported as unknown.
void read_integrator_options(ElementReader& reader, IntegratorSettings& settings);

}  // namespace fosssim
