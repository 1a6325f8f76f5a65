#include "core/limits.h"

#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/scene_model.h"
#include "core/text.h"

namespace fosssim {

double step_count(double duration, double dt) { return std::ceil(duration / dt); }

void check_step_count(const SceneModel& model, const Limits& limits) {
  const double dt = model.integrator.dt;
  const double steps = step_count(model.duration, dt);
  if (steps <= static_cast<double>(limits.max_steps)) return;
  const std::string run = "duration " + to_text(model.duration) + " s at dt " + to_text(dt) + " s";
  if (!std::isfinite(steps)) {
    throw Error(ErrorKind::kBadInput,
                run +
                    ": duration / dt overflows, more steps than a double can count; use a "
                    "larger dt or a shorter duration");
  }
  const std::string count =
      steps < 0x1p63 ? std::to_string(static_cast<std::int64_t>(steps)) : to_text(steps);
  throw Error(ErrorKind::kBadInput, run + " takes " + count + " steps, " +
                                        over_limit(limits.max_steps, "steps", "--max-steps"));
}

std::string over_limit(std::int64_t limit, const std::string& unit, const std::string& option) {
  return "more than the limit of " + std::to_string(limit) + " " + unit + " (raise it with " +
         option + " N)";
}

void check_vertex_count(std::int64_t vertices, std::int64_t max_vertices, const std::string& what,
                        const char* counted) {
  if (vertices <= max_vertices) return;
  const std::string count = vertices == std::numeric_limits<std::int64_t>::max()
                                ? "more than " + std::to_string(vertices)
                                : std::to_string(vertices);
  throw Error(ErrorKind::kBadInput, what + " " + counted + " " + count + " vertices, " +
                                        over_limit(max_vertices, "particles", "--max-particles"));
}

std::int64_t saturating_product(std::initializer_list<std::int64_t> factors) {
  std::int64_t product = 1;
  for (const std::int64_t factor : factors) {
    if (factor == 0) return 0;
  }
  for (const std::int64_t factor : factors) {
    if (__builtin_mul_overflow(product, factor, &product))
      return std::numeric_limits<std::int64_t>::max();
  }
  return product;
}

}  // namespace fosssim
