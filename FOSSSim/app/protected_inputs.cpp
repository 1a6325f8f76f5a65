// No output of a run may replace one of its inputs: every output the options name is compared
// with the scene file, its mesh files and the trajectory to grade by file identity (device and
// inode, so that another name for the same file is caught too) before anything is written.

#include <filesystem>
#include <string_view>
#include <vector>

#include "app/options.h"
#include "core/error.h"
#include "io/file_identity.h"

namespace fosssim {

namespace {

namespace fs = std::filesystem;

struct Input {
  std::string what;  ///< "the scene file s.xml"
  FileIdentity identity;
};

std::vector<Input> inputs_of(const Options& options, const Scene& scene) {
  std::vector<Input> inputs;
  const auto add = [&inputs](const std::string& what, const std::string& path) {
    if (const auto identity = file_identity(path)) inputs.push_back({what + " " + path, *identity});
  };
  for (std::size_t k = 0; k < scene.files.size(); ++k)
    add(k == 0 ? "the scene file" : "the mesh file", scene.files[k]);
  if (!options.input.empty()) add("the trajectory to grade (-i)", options.input);
  return inputs;
}

[[noreturn]] void refuse(const std::string& option, const std::string& output,
                         const std::string& written_as, const Input& input) {
  throw Error(ErrorKind::kBadInput,
              option + " " + output +
                  (written_as == output ? "" : " (written as " + written_as + ")") + " is " +
                  input.what +
                  ": an output must never replace an input; write it "
                  "under another name");
}

/// The input that the file `name` is, if any.
const Input* input_at(const std::string& name, const std::vector<Input>& inputs) {
  const auto identity = file_identity(name);
  if (!identity) return nullptr;
  for (const Input& input : inputs) {
    if (input.identity == *identity) return &input;
  }
  return nullptr;
}

/// Refuses an output file whose name, or any name it is written under on the way (the
/// temporary "<name>.partial", "<name>.incomplete" of a stopped run, and the same beside the
/// file a symbolic link names; io/output_file.h), is an input.
void check_file(const std::string& option, const std::string& path,
                const std::vector<Input>& inputs) {
  if (path.empty()) return;
  std::vector<std::string> bases = {path};
  std::error_code error;
  if (fs::is_symlink(fs::symlink_status(path, error))) {
    const fs::path target = fs::weakly_canonical(path, error);
    if (!error) bases.push_back(target.string());
  }
  for (const std::string& base : bases) {
    for (const char* suffix : {"", ".partial", ".incomplete", ".incomplete.partial"}) {
      const std::string name = base + suffix;
      if (const Input* input = input_at(name, inputs)) refuse(option, path, name, *input);
    }
  }
}

/// Refuses a picture folder holding an input under a name the pictures are written to:
/// frame_<digits>.<extension>, with or without ".partial".
void check_folder(const std::string& option, const std::string& folder, std::string_view extension,
                  const std::vector<Input>& inputs) {
  std::error_code error;
  fs::directory_iterator entries(folder, error);
  if (error) return;  // not there yet: it will hold nothing but pictures
  for (const fs::directory_entry& entry : entries) {
    std::string name = entry.path().filename().string();
    if (name.size() > 8 && name.ends_with(".partial")) name.resize(name.size() - 8);
    const std::size_t dot = name.rfind('.');
    if (!name.starts_with("frame_") || dot == std::string::npos ||
        std::string_view(name).substr(dot + 1) != extension ||
        name.find_first_not_of("0123456789", 6) != dot) {
      continue;
    }
    if (const Input* input = input_at(entry.path().string(), inputs))
      refuse(option, folder, entry.path().string(), *input);
  }
}

/// The names under which `path` is compared with the other outputs: as written, and made
/// absolute with every link of its existing part resolved.
std::vector<std::string> comparable_names(const std::string& path) {
  std::vector<std::string> names = {fs::absolute(path).lexically_normal().string()};
  std::error_code error;
  const fs::path canonical = fs::weakly_canonical(path, error);
  if (!error) names.push_back(canonical.lexically_normal().string());
  return names;
}

bool is_character_device(const std::string& path) {
  std::error_code error;
  return fs::is_character_file(fs::status(path, error));
}

}  // namespace

void check_outputs_distinct(const Options& options) {
  struct Output {
    std::string option, path;
  };
  std::vector<Output> outputs;
  const auto add = [&outputs](std::string_view option, const std::string& path) {
    if (!path.empty()) outputs.push_back({std::string(option), path});
  };
  const std::vector<OutputRequest> requests = output_requests(options);
  for (const OutputRequest& request : requests) {
    if (request.format->target == OutputTarget::kFile)
      add(request.format->option_name(), request.destination);
  }
  if (!options.input.empty()) add("--residual-file", options.residual_file);
  if (options.display == 1) add("--window-screenshot", options.window_screenshot);
  const std::size_t files = outputs.size();
  for (const OutputRequest& request : requests) {
    if (request.format->target == OutputTarget::kFolder)
      add(request.format->option_name(), request.destination);
  }
  for (std::size_t a = 0; a < files; ++a) {
    // Writing twice to /dev/null (or a terminal) loses nothing.
    if (is_character_device(outputs[a].path)) continue;
    const std::vector<std::string> names_a = comparable_names(outputs[a].path);
    const auto identity_a = file_identity(outputs[a].path);
    for (std::size_t b = a + 1; b < outputs.size(); ++b) {
      const std::vector<std::string> names_b = comparable_names(outputs[b].path);
      bool same = identity_a && identity_a == file_identity(outputs[b].path);
      for (const std::string& x : names_a)
        for (const std::string& y : names_b) same = same || x == y;
      if (!same) continue;
      throw Error(ErrorKind::kBadInput,
                  outputs[a].option + " " + outputs[a].path + " and " + outputs[b].option + " " +
                      outputs[b].path +
                      " name the same file: one output would replace the other; give each "
                      "output its own name");
    }
  }
}

void check_outputs_spare_inputs(const Options& options, const Scene& scene) {
  const std::vector<Input> inputs = inputs_of(options, scene);
  if (inputs.empty()) return;
  for (const OutputRequest& request : output_requests(options)) {
    const OutputFormat& format = *request.format;
    const std::string option(format.request_name());
    if (format.target == OutputTarget::kFile) {
      check_file(option, request.destination, inputs);
    } else {
      check_folder(option, request.destination, format.picture_extension, inputs);
    }
  }
  if (!options.input.empty()) check_file("--residual-file", options.residual_file, inputs);
  check_file("--window-screenshot", options.window_screenshot, inputs);
}

}  // namespace fosssim
