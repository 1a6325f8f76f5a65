#pragma once
// Sizes FOSSSim refuses before it allocates or loops on them (docs/limits-and-failures.md).

#include <cstdint>
#include <initializer_list>
#include <string>

namespace fosssim {

struct SceneModel;

/// The largest particle limit that may be set: three coordinates of every particle must stay
/// within the range of an int, the index type of FOSSSim's vectors.
constexpr std::int64_t kMaxParticlesLimit = std::int64_t{1} << 28;

/// Generous caps on what one run may ask for, so that a careless or hostile input ends with a
/// message naming the limit and how to raise it instead of exhausting memory or time. Each is
/// overridable on FOSSSim's command line (the option named beside it).
struct Limits {
  /// Steps of a run or of a graded trajectory: ceil(duration / dt) (--max-steps).
  std::int64_t max_steps = 1'000'000'000;
  /// Particles of a scene, the vertices of its meshes included; a mesh generator is refused
  /// before it generates more vertices than this (--max-particles).
  std::int64_t max_particles = 1'000'000;
  /// Bytes of one scene or mesh file (--max-file-size, given in MiB).
  std::int64_t max_file_bytes = std::int64_t{256} << 20;
  /// Corners of one OBJ face: a face of n corners becomes n (n - 1) / 2 springs
  /// (--max-face-corners).
  std::int64_t max_face_corners = 64;
  /// Attributes of one XML element: the XML reader checks each new attribute against the
  /// earlier ones, so an element of n attributes costs n² (--max-attributes).
  std::int64_t max_attributes = 100;
  /// Impulse passes of one step of hybrid collision handling: a larger `maxiters` is read as
  /// this many, with a warning. Each pass tests and logs every pair, so the default is a
  /// hundred times the course's default of 10 (--max-hybrid-passes).
  std::int64_t max_hybrid_passes = 1000;
  /// Corners of one <elasticbody shape="polygon">, its outline's and its holes' together:
  /// checking that it is simple with its holes apart, bridging the holes and clipping its ears
  /// take time quadratic in them (--max-polygon-corners).
  std::int64_t max_polygon_corners = 10'000;
};

/// The step count ceil(duration / dt) as a double, without converting it to an integer (it may
/// be infinite or beyond any integer type).
double step_count(double duration, double dt);

/// Throws Error (kBadInput) when a run of the model takes more than `limits.max_steps` steps:
///   "duration 1e+300 s at dt 1e-300 s takes 1e+600 steps, more than the limit of 1000000000
///    steps (raise it with --max-steps N)"
void check_step_count(const SceneModel& model, const Limits& limits);

/// The end of a message about a size over a limit: "more than the limit of 10000000 particles
/// (raise it with --max-particles N)".
std::string over_limit(std::int64_t limit, const std::string& unit, const std::string& option);

/// Throws Error (kBadInput) when a generated mesh or body would have more than `max_vertices`
/// vertices (its particles); `what` describes what was asked for ("a sheet of 2000 × 2000
/// cells") and `counted` is the verb before the count ("has", or "would have"). `vertices` is
/// counted in 64 bits, saturating (saturating_product): INT64_MAX reads "more than".
void check_vertex_count(std::int64_t vertices, std::int64_t max_vertices, const std::string& what,
                        const char* counted = "has");

/// The product of the factors (each ≥ 0), saturating at INT64_MAX instead of overflowing, for
/// sizes computed from counts a user wrote.
std::int64_t saturating_product(std::initializer_list<std::int64_t> factors);

}  // namespace fosssim
