#pragma once
// The straightforward solutions the implicit integrators are measured against, as integrators.

#include <memory>
#include <string_view>

#include "core/integrators/integrator.h"

namespace fosssim::bench {

/// Makes the baseline named `name`, unbound, or nullptr when there is none of that name:
/// - "levin": linearly implicit Euler as the CSC417 a2 solution writes it (Levin's recipe):
///   K assembled from triplets every step, A = P (M - h²K - hD) Pᵀ and b = P (M v + h f - h D v)
///   by sparse products, Eigen's SimplicialLDLT analysed and factored every step;
/// - "sparselu": the same with Eigen's SparseLU (COLAMD ordering);
/// - "old-lie", "old-linearized", "old-implicit": FOSSSim's linearly implicit, linearized
///   implicit and implicit (Newton) Euler before this solver work: step matrices from
///   triplets sorted by setFromTriplets every assembly, Eigen's LDLᵀ (symbolic analysis kept)
///   accepted at round-off residual, else LU;
/// - "dense-lu": linearized implicit Euler with a dense step matrix and a dense LU with partial
///   pivoting every step: the course's own program solves its dense matrices this way (a
///   stand-in; the course's program is not in this repository);
/// - "student-lg": the local/global solver as a straightforward sparse solution writes it:
///   Q = M/h² + Lᵀ K L + w CᵀC prefactored once by Eigen's SimplicialLLT, every iteration a
///   local step, b = M y/h² + f + J d + w C p_pins by a sparse product and Eigen's solve of
///   the three columns; penalty pins, iterations from the model's "iterations" option.
std::unique_ptr<Integrator> make_baseline(std::string_view name);

}  // namespace fosssim::bench
