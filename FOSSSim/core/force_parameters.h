#pragma once
// How a force factory reads its parameters without knowing the file format they came from.

#include <memory>
#include <string>

#include "core/text.h"
#include "core/types.h"

namespace fosssim {

struct SceneModel;
class Force;

/// Named parameters of one force declaration (an XML element, for instance). Every accessor
/// validates and throws an error that names where the declaration came from, so factories hold
/// no error plumbing of their own.
class ForceParameters {
 public:
  virtual ~ForceParameters() = default;
  /// A required finite number.
  virtual double number(const char* name) = 0;
  /// An optional finite number with a documented default.
  virtual double number_or(const char* name, double fallback) = 0;
  /// A required particle index in [0, number of particles).
  virtual int particle_index(const char* name) = 0;
  /// A required edge index in [0, number of edges).
  virtual int edge_index(const char* name) = 0;
  /// Reports a problem with the declaration as a whole; never returns.
  [[noreturn]] virtual void fail(const std::string& problem) = 0;
  /// Reports a problem with one parameter; never returns.
  [[noreturn]] virtual void fail(const char* name, const std::string& problem) = 0;
  /// Records a warning about the declaration (an unusual but valid value); loading goes on.
  /// Sources without a warning channel drop it.
  virtual void warn(const std::string& /*problem*/) {}
  /// Declares `name` a parameter that is known but not supported (a handout's attribute that
  /// the course's program never read): if present, it is ignored with a warning that says
  /// `why`, rather than reported as unknown.
  virtual void unsupported(const char* /*name*/, const std::string& /*why*/) {}

  /// A required non-negative number.
  double non_negative(const char* name);
  /// An optional non-negative number with a documented default.
  double non_negative_or(const char* name, double fallback);
  /// A D-vector from the attributes prefix+"x", prefix+"y" (and prefix+"z" in 3D), all required.
  template <int D>
  Vec<D> vector(const char* x_name, const char* y_name, const char* z_name);
};

/// What a force factory may consult when it validates its parameters.
struct ForceContext {
  const SceneModel& model;  ///< particles, edges and dimension declared so far
  const Vector& positions;  ///< initial positions, to reject degenerate geometry
};

/// Creates a force of dimension model.dim from its parameters.
using ForceFactory = std::unique_ptr<Force> (*)(ForceParameters&, const ForceContext&);

template <int D>
Vec<D> ForceParameters::vector(const char* x_name, const char* y_name, const char* z_name) {
  Vec<D> out;
  out[0] = number(x_name);
  out[1] = number(y_name);
  if constexpr (D == 3) out[2] = number(z_name);
  return out;
}

inline double ForceParameters::non_negative(const char* name) {
  const double value = number(name);
  if (value < 0.0) fail(name, "must be non-negative, found " + to_text(value));
  return value;
}

inline double ForceParameters::non_negative_or(const char* name, double fallback) {
  const double value = number_or(name, fallback);
  if (value < 0.0) fail(name, "must be non-negative, found " + to_text(value));
  return value;
}

}  // namespace fosssim
