// Fuzz target: the JSON scene reader (io/json_scene_reader.h), then a few steps of every scene
// it accepts. The mesh comes from memory: "cloth.obj", a small cloth; any other name is
// missing.

#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "io/json_scene_reader.h"

namespace {
constexpr const char* kCloth =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 0.2\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n";
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fosssim;
  InputFiles files = InputFiles::in_memory({{"cloth.obj", kCloth}}, fuzzing::fuzz_limits());
  try {
    Scene scene = load_json_scene_text(fuzzing::as_text(data, size), "fuzz.json", files);
    fuzzing::run_a_few_steps(scene);
  } catch (const SceneError&) {
  }
  return 0;
}
