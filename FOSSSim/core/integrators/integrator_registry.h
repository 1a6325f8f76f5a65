#pragma once
// Every time-stepping method FOSSSim has, by name: adding one is a line in the .cpp.

#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "core/integrators/integrator_method.h"

namespace fosssim {

struct SceneModel;

/// All methods, in the order --help and messages list them.
std::span<const IntegratorMethod* const> integrator_methods();

/// The method with this type string (name or alias), or nullptr.
const IntegratorMethod* find_integrator_method(std::string_view type);

/// The method with this canonical name, for code that names one; an unknown name is a
/// programming error (std::logic_error).
const IntegratorMethod& integrator_method(std::string_view name);

/// The method of a model that does not say (explicit Euler, the course's first).
const IntegratorMethod& default_integrator_method();

/// "explicit-euler, symplectic-euler (or forward-backward-euler, semi-implicit-euler), ...":
/// every type string, for messages about an unknown one.
std::string describe_integrator_names();

}  // namespace fosssim
