// Fuzz target: the OBJ reader (io/obj_reader.h), the input being the "obj" of a JSON scene of
// the fast mass-springs format, which is then stepped a few times with the local/global
// integrator: the mesh's springs, masses from areas and pins all see what the reader accepts.

#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "io/json_scene_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fosssim;
  InputFiles files = InputFiles::in_memory(
      {{"mesh.obj", std::string(fuzzing::as_text(data, size))}}, fuzzing::fuzz_limits());
  try {
    Scene scene = load_json_scene_text(
        R"({"obj": "mesh.obj", "k": 100, "b": [1], "iterations": 3, "duration": 0.1})", "fuzz.json",
        files);
    fuzzing::run_a_few_steps(scene);
  } catch (const SceneError&) {
  }
  return 0;
}
