// Fuzz target: FOSSSim's command line (app/options.h) up to the point where a run would start:
// parsing, the checks of picture options, the overrides applied to a scene, the step limit and
// the check that no output replaces an input, the check that no two outputs name one file, and
// the opening of each output file (io/output_file.h: empty names, folders, links, FIFOs), whose
// temporary file is then discarded. The input is the arguments, separated by NUL bytes. Nothing
// is run and nothing is kept: the target works in a folder of its own that holds the scene's
// files (scene.xml, cloth.obj, run.bin and pngs/frame_00000.png, which the outputs must spare),
// and only names inside it are opened.

#include <sys/stat.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/options.h"
#include "fuzz_support.h"
#include "io/output_file.h"
#include "io/scene_loader.h"

namespace {

constexpr const char* kScene = R"(<scene>
  <duration time="1"/>
  <integrator type="implicit-euler" dt="0.01"/>
  <particle m="1" px="0" py="0" vx="0" vy="0" fixed="1"/>
  <particle m="1" px="1" py="0" vx="0" vy="0" fixed="0"/>
  <edge i="0" j="1"/>
  <springforce edge="0" k="10" l0="1"/>
</scene>)";

/// The files the run reads, as Scene::files and -i name them, relative to the target's folder.
const std::vector<std::string> kInputs = {"scene.xml", "cloth.obj", "pngs/frame_00000.png"};

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  static char folder[] = "/tmp/fosssim-command-line-fuzzer-XXXXXX";
  if (::mkdtemp(folder) == nullptr || ::chdir(folder) != 0) return 0;
  std::atexit([] { std::filesystem::remove_all(folder); });
  ::mkdir("pngs", 0700);
  for (const std::string& name : kInputs) std::ofstream(name) << kScene;
  std::ofstream("run.bin") << std::string(64, '\0');
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fosssim;
  std::vector<std::string> arguments{"FOSSSim"};
  std::string current;
  for (std::size_t k = 0; k < size && arguments.size() < 40; ++k) {
    if (data[k] == 0) {
      arguments.push_back(current);
      current.clear();
    } else {
      current += static_cast<char>(data[k]);
    }
  }
  if (!current.empty()) arguments.push_back(current);
  std::vector<char*> argv;
  for (std::string& argument : arguments) argv.push_back(argument.data());

  Options options;
  CLI::App app{"FOSSSim", "FOSSSim"};
  add_options(app, options);
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::ParseError&) {
    return 0;  // usage errors, --help and --version end here
  }
  try {
    options.display_given = app.count("--display") > 0;
    check_picture_options(options);
    Scene scene = load_scene_text(kScene, "scene.xml");
    scene.files = kInputs;
    apply_overrides(options, scene);
    check_step_count(scene.model, limits_of(options));
    check_outputs_spare_inputs(options, scene);
    check_outputs_distinct(options);
    std::vector<std::string> names = {options.residual_file};
    for (const OutputRequest& request : output_requests(options)) {
      if (request.format->target == OutputTarget::kFile) names.push_back(request.destination);
    }
    for (const std::string* name = names.data(); name != names.data() + names.size(); ++name) {
      const std::filesystem::path path(*name);
      bool inside = path.is_relative();
      for (const auto& part : path) inside = inside && part != "..";
      if (!inside || name->empty()) continue;
      try {
        OutputFile output(*name);
        output.discard();
      } catch (const Error&) {
      }
    }
  } catch (const Error&) {
  }
  return 0;
}
