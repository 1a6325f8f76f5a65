#pragma once
// Typed tests run once in 2D and once in 3D, and the list of every integrator for tests that
// apply to all of them.

#include <gtest/gtest.h>

#include <span>
#include <string>
#include <type_traits>

#include "core/integrators/integrator_registry.h"

namespace fosssim::testing {

/// Every integrator of the registry, for tests that apply to all of them
/// (core/integrators/integrator_registry.h).
inline std::span<const IntegratorMethod* const> all_integrators() { return integrator_methods(); }

template <int D>
using Dim = std::integral_constant<int, D>;
using Dimensions = ::testing::Types<Dim<2>, Dim<3>>;

struct DimensionName {
  template <typename T>
  static std::string GetName(int) {
    return std::to_string(T::value) + "D";
  }
};

/// Declares the typed test suite `Suite`, run once in 2D and once in 3D; in its tests
/// `TypeParam::value` is the dimension.
#define FOSSSIM_TEST_SUITE_IN_2D_AND_3D(Suite) \
  template <typename T>                        \
  class Suite : public ::testing::Test {};     \
  TYPED_TEST_SUITE(Suite, ::fosssim::testing::Dimensions, ::fosssim::testing::DimensionName)

}  // namespace fosssim::testing
