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

/// The names of the methods that handle bodies of `kind` (in some dimension), in registry order,
/// for messages: "none, simple, penalty, continuous-time, hybrid" for particles.
std::string describe_contact_method_names(BodyKind kind);

/// The name of a method for bodies of `kind` that `unknown` probably misspells
/// (core/misspelling.h), the first in registry order, or empty: "hybird" gives "hybrid".
std::string_view suggest_contact_method(std::string_view unknown, BodyKind kind);

/// Why `method` cannot handle the bodies of `model` (their kind and dimension), or empty when
/// it can: "\"hybrid\" is 2D only (its rigid impact zones rotate in the plane)", "\"lcp\" does
/// not handle particles (...)".
std::string contact_method_refusal(const ContactMethod& method, const SceneModel& model);

/// The response stage of model.collisions' method, or null when it has none (particle and
/// rigid-body scenes alike). `model` must outlive it.
std::unique_ptr<StepStage> make_contact_stage(const SceneModel& model);

}  // namespace fosssim
