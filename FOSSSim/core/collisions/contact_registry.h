#pragma once
// Every contact method FOSSSim has, by name: adding one is a file pair and a line in the .cpp.

#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "core/collisions/contact_method.h"

namespace fosssim {

/// All methods, in the order --help and messages list them.
std::span<const ContactMethod* const> contact_methods();

/// The method with this type string, or nullptr.
const ContactMethod* find_contact_method(std::string_view name);

/// The method with this name, for code that names one; an unknown name is a programming error
/// (std::logic_error).
const ContactMethod& contact_method(std::string_view name);

/// The method of a model without a <collision> element: "none".
const ContactMethod& no_contact_method();

/// "none, simple, penalty, continuous-time, hybrid": every type string, for messages.
std::string describe_contact_method_names();

/// The registered name that `unknown` probably misspells (core/misspelling.h), the first in
/// registry order, or empty: "hybird" gives "hybrid".
std::string_view suggest_contact_method(std::string_view unknown);

/// Why `method` cannot handle the bodies of `model` (its body kind and dimension), or empty when
/// it can: "\"hybrid\" is 2D only (its rigid impact zones rotate in the plane)".
std::string contact_method_refusal(const ContactMethod& method, const SceneModel& model);

/// The response stage of model.collisions' method, or null when it has none. `model` must
/// outlive it.
std::unique_ptr<StepStage> make_contact_stage(const SceneModel& model);

}  // namespace fosssim
