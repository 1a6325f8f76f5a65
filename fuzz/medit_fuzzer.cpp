// Fuzz target: the MEDIT reader (io/medit_reader.h), the input being the <tetmesh> of an XML
// scene, which is then stepped a few times with linearly implicit Euler, masses from volumes.

#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "io/scene_loader.h"

namespace {
constexpr const char* kScene = R"(<scene dim="3">
  <duration time="0.1"/>
  <integrator type="linearly-implicit-euler" dt="0.01"/>
  <tetmesh file="mesh.mesh" k="100" mass="volume" density="1000">
    <pin axis="y" side="lowest" within="0.01"/>
  </tetmesh>
  <simplegravity fx="0" fy="-9.81" fz="0"/>
</scene>)";
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fosssim;
  InputFiles files = InputFiles::in_memory(
      {{"mesh.mesh", std::string(fuzzing::as_text(data, size))}}, fuzzing::fuzz_limits());
  try {
    Scene scene = load_scene_text(kScene, "fuzz.xml", files);
    fuzzing::run_a_few_steps(scene);
  } catch (const SceneError&) {
  }
  return 0;
}
