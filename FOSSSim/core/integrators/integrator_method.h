#pragma once
// What the registry knows of one time-stepping method: its names, settings, factory and the
// properties its tests rely on.

#include <memory>
#include <span>
#include <string_view>

#include "core/integrators/integrator_options.h"

namespace fosssim {

class Integrator;

/// How the total energy of an undamped oscillator behaves under a method at a stable step.
enum class EnergyTrend {
  kGrows,    ///< explicit Euler: it gains energy every period
  kBounded,  ///< symplectic: it oscillates around the true value without drift
  kDecays,   ///< implicit methods: numerical damping removes energy every step
};

/// What tests and tools may assume of a method (tests/core/integrators/ iterates the registry
/// and checks every property of every method).
struct IntegratorProperties {
  int order = 1;  ///< global convergence order of positions and velocities
  /// The course's own method, step for step: its trajectories are graded with the course's
  /// criteria (residuals below 1e-10 per step against the course's reference).
  bool course_reference = false;
  bool runs_2d = true;  ///< accepts <scene dim="2">
  bool runs_3d = true;  ///< accepts <scene dim="3">
  /// Stiff springs are stable at any step (the end-of-step state is solved for implicitly).
  bool implicit = false;
  /// vⁿ⁺¹ is computed as (qⁿ⁺¹ - qⁿ)/h, so velocities carry the positions' round-off
  /// amplified by 1/h: about ε|q|/h per step instead of ε|v| (local/global).
  bool velocity_from_positions = false;
  EnergyTrend energy = EnergyTrend::kGrows;
};

/// One entry of the integrator registry (integrator_registry.h). Each method's file pair
/// defines its entry; the registry lists the entries.
struct IntegratorMethod {
  std::string_view name;  ///< the canonical type string of <integrator type="...">
  /// Other type strings for the same method (the course's handouts print short forms).
  std::span<const std::string_view> aliases = {};
  std::string_view summary;  ///< one line for --help and messages
  /// The method's settings: attributes of <integrator>, keys of JSON scenes, and
  /// --integrator-option NAME=VALUE.
  std::span<const OptionSpec> options = {};
  IntegratorProperties properties;
  /// Makes an unbound integrator for scenes of dimension `dim` (2 or 3) with these settings
  /// (values of `options`).
  std::unique_ptr<Integrator> (*create)(const OptionValues& options, int dim) = nullptr;

  /// True when `type` is the name or one of the aliases.
  bool is_named(std::string_view type) const;
};

}  // namespace fosssim
