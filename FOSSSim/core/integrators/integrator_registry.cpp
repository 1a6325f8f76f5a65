#include "core/integrators/integrator_registry.h"

#include <array>
#include <stdexcept>

#include "core/integrators/explicit_euler.h"
#include "core/integrators/implicit_euler.h"
#include "core/integrators/linearized_implicit_euler.h"
#include "core/integrators/linearly_implicit_euler.h"
#include "core/integrators/local_global.h"
#include "core/integrators/newton.h"
#include "core/integrators/quasi_newton.h"
#include "core/integrators/symplectic_euler.h"

namespace fosssim {

namespace {
/// The course's four methods first, in the order its milestones introduce them; then the
/// methods for meshes.
const std::array kMethods = {
    &kExplicitEulerMethod,         &kSymplecticEulerMethod, &kLinearizedImplicitEulerMethod,
    &kImplicitEulerMethod,         &kLocalGlobalMethod,     &kAcceleratedLocalGlobalMethod,
    &kLinearlyImplicitEulerMethod, &kNewtonMethod,          &kQuasiNewtonMethod,
};
}  // namespace

bool IntegratorMethod::is_named(std::string_view type) const {
  if (type == name) return true;
  for (std::string_view alias : aliases) {
    if (type == alias) return true;
  }
  return false;
}

std::span<const IntegratorMethod* const> integrator_methods() { return kMethods; }

const IntegratorMethod* find_integrator_method(std::string_view type) {
  for (const IntegratorMethod* method : kMethods) {
    if (method->is_named(type)) return method;
  }
  return nullptr;
}

const IntegratorMethod& integrator_method(std::string_view name) {
  for (const IntegratorMethod* method : kMethods) {
    if (method->name == name) return *method;
  }
  throw std::logic_error("no integrator is named \"" + std::string(name) + "\"");
}

const IntegratorMethod& default_integrator_method() { return kExplicitEulerMethod; }

std::string describe_integrator_names() {
  std::string out;
  for (const IntegratorMethod* method : kMethods) {
    if (!out.empty()) out += ", ";
    out += method->name;
    if (!method->aliases.empty()) {
      out += " (or ";
      for (std::size_t k = 0; k < method->aliases.size(); ++k) {
        out += (k > 0 ? ", " : "") + std::string(method->aliases[k]);
      }
      out += ")";
    }
  }
  return out;
}

}  // namespace fosssim
