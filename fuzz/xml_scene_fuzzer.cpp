// Fuzz target: the XML scene reader (io/scene_loader.h), then a few steps of every scene it
// accepts. Mesh files named by the scene come from memory: a small cloth "cloth.obj" and a tet
// "tet.mesh"; any other name is missing.

#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "io/scene_loader.h"

namespace {

constexpr const char* kCloth =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 0.2\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n";
constexpr const char* kTet =
    "MeshVersionFormatted 1\nDimension 3\nVertices 5\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
    "1 1 1 0\nTetrahedra 2\n1 2 3 4 0\n2 3 4 5 0\nEnd\n";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fosssim;
  InputFiles files =
      InputFiles::in_memory({{"cloth.obj", kCloth}, {"tet.mesh", kTet}}, fuzzing::fuzz_limits());
  try {
    Scene scene = load_scene_text(fuzzing::as_text(data, size), "fuzz.xml", files);
    fuzzing::run_a_few_steps(scene);
  } catch (const SceneError&) {
  }
  return 0;
}
