// fosssim-web-run: runs one scene in the WebAssembly build and writes its trajectory file,
// byte for byte what `FOSSSim -s SCENE -d 0 -o OUT` writes natively (the regression manifest's
// digests are of that file). Node runs it with the real file system (-sNODERAWFS); the wasm
// tests of web/CMakeLists.txt compare its digests with the native manifest's.
//
//   node fosssim-web-run.js SCENE OUT     exit 0, 2 (scene error), 3 (step failed), 1 (other)

#include <iostream>
#include <optional>
#include <string>

#include "core/error.h"
#include "core/limits.h"
#include "core/step_error.h"
#include "io/input_files.h"
#include "io/scene_loader.h"
#include "scene_trajectory.h"

namespace fosssim {
namespace {

int run(const std::string& scene_path, const std::string& output) {
  InputFiles files;
  const Scene scene = load_scene_file(scene_path, files);
  check_step_count(scene.model, files.limits());
  for (const std::string& warning : scene.warnings) std::cerr << warning << "\n";
  const double end = write_scene_trajectory(scene, output);
  std::cout << "Simulation complete at time " << end << ". Exiting." << std::endl;
  return 0;
}

}  // namespace
}  // namespace fosssim

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: fosssim-web-run SCENE OUT\n";
    return 1;
  }
  try {
    return fosssim::run(argv[1], argv[2]);
  } catch (const fosssim::StepError& error) {
    std::cerr << "FOSSSim: error: " << argv[1] << ": " << error.what() << "\n";
    return 3;
  } catch (const fosssim::Error& error) {
    std::cerr << error.what() << "\n";
    return error.kind() == fosssim::ErrorKind::kBadInput ? 2 : 1;
  } catch (const std::exception& error) {
    std::cerr << "FOSSSim: error: " << error.what() << "\n";
    return 1;
  }
}
