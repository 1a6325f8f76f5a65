#include "app/options.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "cli/parse_command_line.h"
#include "core/collisions/contact_registry.h"
#include "core/error.h"
#include "core/integrators/integrator_registry.h"
#include "core/text.h"
#include "outputs/trajectory_output.h"

namespace fosssim {

namespace {

/// Declares the option of every output format of `group` (outputs/output_registry.h): its
/// destination, and the course's 0|1 switch (-g) of a format that has one.
void add_output_options(CLI::App& app, Options& options, std::string_view group) {
  for (const OutputFormat* format : output_formats()) {
    if (format->group != group) continue;
    // CLI11 hides the options of the group "": the main options keep its default group.
    const auto place = [group](CLI::Option* option) {
      if (!group.empty()) option->group(std::string(group));
    };
    if (!format->switch_flags.empty()) {
      place(app.add_option(std::string(format->switch_flags), options.outputs.switched(*format),
                           std::string(format->switch_help))
                ->check(CLI::IsMember({0, 1}))
                ->check(decimal_number()));
    }
    CLI::Option* option = app.add_option(std::string(format->flags),
                                         options.outputs.destination(*format),
                                         std::string(format->help))
                              ->type_name(std::string(format->value_name))
                              ->check(nonempty_name());
    place(option);
    if (!format->default_destination.empty()) option->capture_default_str();
  }
}

/// The --help group of the picture options, and of the output formats that name it.
constexpr std::string_view kPictureGroup = "Pictures (docs/viewing.md)";

void add_picture_options(CLI::App& app, Options& options) {
  const std::string group(kPictureGroup);
  add_output_options(app, options, group);
  app.add_option("--movie-stride", options.movie_stride,
                 "A movie frame every N steps (frames 0, N, 2N, ...); default: the stride that\n"
                 "plays the run at about real time at --fps")
      ->check(CLI::PositiveNumber)
      ->group(group);
  app.add_option("--fps", options.fps, "Movie frames per second")
      ->capture_default_str()
      ->group(group);
  app.add_option("--size", options.size,
                 "Width x height in pixels of the window, pictures and movie")
      ->capture_default_str()
      ->group(group);
  app.add_option("--view", options.view,
                 "3D scenes: look from YAW,PITCH degrees (0,0 looks along -z; the default is\n"
                 "30,20), optionally from DISTANCE to the target; overrides <camera3d>")
      ->group(group);
  app.add_flag("--orthographic", options.orthographic,
               "3D scenes: parallel projection instead of perspective")
      ->group(group);
  app.add_option("--frame", options.frame,
                 "Where the scene sets no viewport (or 3D camera target and distance), fit the\n"
                 "camera of pictures and movies to what the whole run covers (run: the scene is\n"
                 "simulated once more first) or to the initial state (first)")
      ->check(CLI::IsMember({"run", "first"}))
      ->capture_default_str()
      ->group(group);
  app.add_option("--color-by", options.color_by,
                 "Elastic bodies: colour their triangles and hinges (2D) and membranes (3D)\n"
                 "plain, by strain (blue compressed, grey at rest, red stretched) or by energy\n"
                 "density")
      ->check(CLI::IsMember({"plain", "strain", "energy"}))
      ->capture_default_str()
      ->group(group);
  app.add_option("--color-scale", options.color_scale,
                 "The strain (default 0.1) or energy density (default: each picture's largest)\n"
                 "drawn in full colour by --color-by")
      ->check(CLI::PositiveNumber)
      ->group(group);
  app.add_option("--window-screenshot", options.window_screenshot,
                 "Testing aid: run the window to --window-screenshot-step, save its framebuffer\n"
                 "as this PNG and close")
      ->group(group);
  app.add_option("--window-screenshot-step", options.window_screenshot_step,
                 "The step of --window-screenshot")
      ->check(CLI::NonNegativeNumber)
      ->group(group);
}

void add_limit_options(CLI::App& app, Options& options) {
  const char* group = "Limits (docs/limits-and-failures.md)";
  app.add_option("--max-steps", options.max_steps,
                 "Refuse a run (or a trajectory to grade) of more steps than this:\n"
                 "ceil(duration / dt)")
      ->check(CLI::Range(std::int64_t{1}, SceneModel::kMaxStepCount - 1))
      ->capture_default_str()
      ->group(group);
  app.add_option("--max-particles", options.max_particles,
                 "Refuse a scene of more particles than this, mesh vertices included; mesh\n"
                 "generators are refused before they generate more")
      ->check(CLI::Range(std::int64_t{1}, kMaxParticlesLimit))
      ->capture_default_str()
      ->group(group);
  app.add_option("--max-file-size", options.max_file_mib,
                 "Refuse a scene or mesh file larger than this many MiB")
      ->check(CLI::Range(std::int64_t{1}, std::int64_t{1} << 40))
      ->type_name("MIB")
      ->capture_default_str()
      ->group(group);
  app.add_option("--max-attributes", options.max_attributes,
                 "Refuse an XML element of more attributes than this")
      ->check(CLI::Range(std::int64_t{1}, std::int64_t{1} << 20))
      ->capture_default_str()
      ->group(group);
  app.add_option("--max-face-corners", options.max_face_corners,
                 "Refuse an OBJ face of more corners than this (a face of n corners makes\n"
                 "n (n - 1) / 2 springs)")
      ->check(CLI::Range(std::int64_t{3}, std::int64_t{1} << 16))
      ->capture_default_str()
      ->group(group);
  app.add_option("--max-polygon-corners", options.max_polygon_corners,
                 "Refuse an <elasticbody shape=\"polygon\"> of more corners than this,\n"
                 "outline and holes together (its triangulation takes time quadratic\n"
                 "in them)")
      ->check(CLI::Range(std::int64_t{3}, std::int64_t{1} << 24))
      ->capture_default_str()
      ->group(group);
  app.add_option("--max-hybrid-passes", options.max_hybrid_passes,
                 "Make at most this many impulse passes a step of hybrid collision handling;\n"
                 "a larger maxiters is read as this many, with a warning")
      ->check(CLI::Range(std::int64_t{1}, std::int64_t{2147483647}))
      ->capture_default_str()
      ->group(group);
}

/// Throws Error (kBadInput) with a message.
[[noreturn]] void fail(const std::string& problem) { throw Error(ErrorKind::kBadInput, problem); }

/// "-g, -m and --movie".
std::string join_names(const std::vector<std::string_view>& names) {
  std::string out;
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (k > 0) out += k + 1 == names.size() ? " and " : ", ";
    out += names[k];
  }
  return out;
}

/// Parses "WxH" into width and height (each 16..8192).
void parse_size(const std::string& text, int& width, int& height) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') ||
      w < 16 || h < 16 || w > 8192 || h > 8192) {
    fail(
        "--size must be WIDTHxHEIGHT with each between 16 and 8192 pixels (512x512, say), "
        "found '" +
        text + "'");
  }
  width = w;
  height = h;
}

/// Parses "YAW,PITCH[,DISTANCE]" (degrees, degrees, world units > 0) into `view`.
void parse_view(const std::string& text, OrbitViewSettings& view) {
  std::vector<double> values;
  bool numbers = true;
  for (std::size_t start = 0;;) {
    const std::size_t comma = text.find(',', start);
    const std::string item =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const bool number = is_decimal_number(item);
    const double value = number ? std::strtod(item.c_str(), nullptr) : 0.0;
    numbers = numbers && number;
    values.push_back(value);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (!numbers || values.size() < 2 || values.size() > 3 ||
      (values.size() == 3 && !(values[2] > 0.0))) {
    fail(
        "--view must be YAW,PITCH or YAW,PITCH,DISTANCE: angles in degrees and a distance "
        "> 0 (30,20 or 30,20,4, say), found '" +
        text + "'");
  }
  view.yaw = values[0];
  view.pitch = values[1];
  if (values.size() == 3) view.distance = values[2];
}

/// The --integrator-option values, NAME=VALUE each, as an OptionSource.
class CommandLineOptions final : public OptionSource {
 public:
  explicit CommandLineOptions(const std::vector<std::string>& assignments) {
    for (const std::string& assignment : assignments) {
      const auto equals = assignment.find('=');
      if (equals == std::string::npos || equals == 0) {
        throw Error(ErrorKind::kBadInput,
                    "--integrator-option must be NAME=VALUE, found '" + assignment + "'");
      }
      values_.emplace_back(assignment.substr(0, equals), assignment.substr(equals + 1));
    }
  }
  /// The names given, in order.
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& [name, value] : values_) out.push_back(name);
    return out;
  }

  bool has(std::string_view name) override { return find(name) != nullptr; }
  double number(std::string_view name) override {
    const std::string& text = *find(name);
    if (!is_decimal_number(text)) {
      fail(name, "must be a finite decimal number, found '" + text + "'");
    }
    return std::strtod(text.c_str(), nullptr);
  }
  std::string text(std::string_view name) override { return *find(name); }
  [[noreturn]] void fail(std::string_view name, const std::string& problem) override {
    throw Error(ErrorKind::kBadInput, "--integrator-option " + std::string(name) + ": " + problem);
  }

 private:
  /// The last value given for `name` (a later one overrides an earlier one), or nullptr.
  const std::string* find(std::string_view name) const {
    for (auto it = values_.rbegin(); it != values_.rend(); ++it) {
      if (it->first == name) return &it->second;
    }
    return nullptr;
  }

  std::vector<std::pair<std::string, std::string>> values_;
};

/// "newton-tolerance, newton-max-iterations", or "none".
std::string option_names(const IntegratorMethod& method) {
  std::string out;
  for (const OptionSpec& spec : method.options)
    out += (out.empty() ? "" : ", ") + std::string(spec.name);
  return out.empty() ? "none" : out;
}

/// Applies --integrator-option (and its shorthands) to the scene's integrator settings.
void apply_integrator_options(const std::vector<std::string>& assignments, Scene& scene) {
  if (assignments.empty()) return;
  IntegratorSettings& settings = scene.model.integrator;
  CommandLineOptions given(assignments);
  for (const std::string& name : given.names()) {
    if (settings.options.has(name)) continue;
    const std::string problem = "the scene's integrator " + std::string(settings.method->name) +
                                " has no option '" + name +
                                "' (its options: " + option_names(*settings.method) + ")";
    if (name.rfind("newton-", 0) != 0)
      throw Error(ErrorKind::kBadInput, "--integrator-option: " + problem);
    scene.warnings.push_back("FOSSSim: warning: --" + name + " ignored: " + problem);
  }
  settings.options.read(given);
}

/// The integrators and their options, for the end of --help.
std::string integrator_help() {
  std::string out =
      "Integrators (<integrator type=\"...\">) and their options (attributes of\n"
      "<integrator>, or --integrator-option NAME=VALUE; docs/integrators.md):\n";
  for (const IntegratorMethod* method : integrator_methods()) {
    out += "  " + std::string(method->name);
    for (std::string_view alias : method->aliases) out += ", " + std::string(alias);
    out += "\n      " + std::string(method->summary) + "\n";
    for (const OptionSpec& spec : method->options) {
      out += "      " + std::string(spec.name) + " = " + spec.describe_values() + " (default " +
             spec.default_text() + ")\n          " + std::string(spec.help) + "\n";
    }
  }
  return out;
}

/// The contact methods and their options, for the end of --help.
std::string contact_help() {
  std::string out =
      "Contact methods and their options: particle scenes name one with <collision\n"
      "type=\"...\"> (options are attributes of <collision>; docs/collisions.md), rigid-body\n"
      "scenes with <rigidbodycollisionhandling response=\"...\"> (docs/rigid-bodies.md):\n";
  for (const ContactMethod* method : contact_methods()) {
    out += "  " + std::string(method->name) + "\n      " + std::string(method->summary) + "\n";
    if (!method->scope.particles) out += "      (planar rigid bodies)\n";
    for (const OptionSpec& spec : method->options) {
      out += "      " + std::string(spec.name) + " = " + spec.describe_values() + " (default " +
             spec.default_text() + ")\n          " + std::string(spec.help) + "\n";
    }
  }
  return out;
}

}  // namespace

void check_picture_options(Options& options) {
  parse_size(options.size, options.width, options.height);
  const OutputSettings settings = output_settings(options);
  // The options of the outputs that cannot go with -i; the parser itself refuses -o with -i.
  std::vector<std::string_view> run_only;
  for (const OutputFormat* format : output_formats()) {
    if (!format->needs.with_grading && format != &kTrajectoryOutput) {
      run_only.push_back(format->request_name());
    }
  }
  for (const OutputRequest& request : output_requests(options)) {
    const OutputFormat& format = *request.format;
    if (!format.needs.with_grading && !options.input.empty()) {
      fail(join_names(run_only) + " describe a run; they cannot be combined with grading (-i)");
    }
  }
  for (const OutputRequest& request : output_requests(options)) {
    const OutputFormat& format = *request.format;
    if (format.check != nullptr) format.check(request.destination, settings);
    if (!format.needs.window) {
      if (options.display_given && options.display == 1) {
        fail(std::string(format.option_name()) + " " + std::string(format.headless_reason));
      }
      options.display = 0;
    }
  }
  if (!options.window_screenshot.empty() && options.display == 0) {
    fail("--window-screenshot needs the window (-d 1)");
  }
}

Limits limits_of(const Options& options) {
  Limits limits;
  limits.max_steps = options.max_steps;
  limits.max_particles = options.max_particles;
  limits.max_file_bytes = options.max_file_mib << 20;
  limits.max_face_corners = options.max_face_corners;
  limits.max_attributes = options.max_attributes;
  limits.max_hybrid_passes = options.max_hybrid_passes;
  limits.max_polygon_corners = options.max_polygon_corners;
  return limits;
}

OutputSettings output_settings(const Options& options) {
  OutputSettings settings;
  settings.movie = movie_settings(options);
  settings.movie_stride = options.movie_stride;
  return settings;
}

std::vector<OutputRequest> output_requests(const Options& options) {
  return options.outputs.requests();
}

bool asks_for_pictures(const Options& options) {
  for (const OutputRequest& request : output_requests(options)) {
    if (request.format->needs.pictures) return true;
  }
  return false;
}

ElementColors element_colors(const Options& options) {
  ElementColors colors;
  colors.by = options.color_by == "strain"   ? ElementColoring::kStrain
              : options.color_by == "energy" ? ElementColoring::kEnergy
                                             : ElementColoring::kPlain;
  colors.scale = options.color_scale;
  return colors;
}

MovieSettings movie_settings(const Options& options) {
  MovieSettings settings;
  settings.width = options.width;
  settings.height = options.height;
  settings.fps = options.fps;
  return settings;
}

void add_options(CLI::App& app, Options& options) {
  app.description(
      "FOSSSim: a physically based particle and mass-spring simulator.\n"
      "Runs a scene in the course's XML format, writes its trajectory (-o), or grades a\n"
      "trajectory against the scene's integrator with the course's criteria (-i).");
  app.add_option("-s,--scene", options.scene,
                 "Scene file: the course's XML, or the fast mass-springs JSON format")
      ->required();
  app.add_option("-d,--display", options.display,
                 "1: open the interactive window; 0: run headless to the scene's end")
      ->check(CLI::IsMember({0, 1}))
      ->capture_default_str();
  app.add_option("-p,--paused", options.paused, "1: start the window paused; 0: start running")
      ->check(CLI::IsMember({0, 1}))
      ->capture_default_str();
  add_output_options(app, options, "");
  auto* output = app.get_option("-o");
  auto* input = app.add_option(
      "-i,--input", options.input,
      "Grading mode: replay this trajectory step by step against the scene's integrator,\n"
      "print the course's report, write the residual file; exit 0 if it passes, 1 if not");
  output->excludes(input);
  input->excludes(output);
  app.add_option("--duration", options.duration, "Override the scene's duration (seconds, >= 0)");
  app.add_option("--dt", options.dt, "Override the scene's time step (seconds, > 0)");
  app.add_option("--integrator-option", options.integrator_options,
                 "Set an option of the scene's integrator, as an attribute of <integrator>\n"
                 "would (repeatable); the options of each method are listed below")
      ->type_name("NAME=VALUE");
  app.add_option_function<std::string>(
         "--newton-max-iterations",
         [&options](const std::string& n) {
           options.integrator_options.push_back("newton-max-iterations=" + n);
         },
         "Implicit Euler: give up on a step after this many Newton iterations (default 200)")
      ->type_name("N");
  app.add_option_function<std::string>(
         "--newton-tolerance",
         [&options](const std::string& tolerance) {
           options.integrator_options.push_back("newton-tolerance=" + tolerance);
         },
         "Implicit Euler: stop when the Newton correction's L2 norm is below this\n"
         "(default 1e-9, the course's value)")
      ->type_name("TOL");
  app.add_option("--residual-file", options.residual_file,
                 "Grading mode: where to write the per-criterion residuals")
      ->capture_default_str();
  app.add_flag("--check-derivatives", options.check_derivatives,
               "Check every force's gradient and Hessians against finite differences at the\n"
               "scene's initial state, print a table and exit (1 if any check fails)");
  app.add_option("--threads", options.threads,
                 "Threads of the BLAS behind the sparse solvers (MUMPS, CHOLMOD, UMFPACK) of\n"
                 "large implicit steps; everything else runs on one thread. 1 gives the same\n"
                 "bytes on every machine and is fastest on a shared one; N > 1 may change the\n"
                 "last bits of such runs and says so (docs/solvers.md). Overrides\n"
                 "OPENBLAS_NUM_THREADS and OMP_NUM_THREADS")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  app.add_flag("-q,--quiet", options.quiet, "No progress bar and no description");
  app.add_option("--progress", options.progress,
                 "How a run reports progress on standard error: a bar redrawn in place, a line\n"
                 "every 10 s (from the 10th second on: logs, nohup, batch jobs), or nothing;\n"
                 "auto is a bar at a terminal and lines otherwise")
      ->check(CLI::IsMember({"auto", "bar", "lines", "off"}))
      ->default_str("auto");
  app.add_option("--progress-every", options.progress_every,
                 "Seconds between two progress lines (--progress lines)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            // CLI::Range lets NaN through (every comparison with it is false).
            char* end = nullptr;
            const double seconds = std::strtod(text.c_str(), &end);
            if (end == text.c_str() || *end != '\0' || !(seconds >= 1e-3 && seconds <= 1e6)) {
              return "expected a number of seconds from 0.001 to 1e6, got '" + text + "'";
            }
            return {};
          },
          "SECONDS"))
      ->default_str("10");
  add_picture_options(app, options);
  // The outputs of groups of their own, each group once, in registry order.
  std::vector<std::string_view> groups = {"", kPictureGroup};
  for (const OutputFormat* format : output_formats()) {
    if (std::find(groups.begin(), groups.end(), format->group) != groups.end()) continue;
    groups.push_back(format->group);
    add_output_options(app, options, format->group);
  }
  add_limit_options(app, options);
  // Numbers read as the scene readers read them (no "0x10"), and no empty file names.
  for (const char* name :
       {"-d", "-p", "--threads", "--duration", "--dt", "--newton-max-iterations",
        "--newton-tolerance", "--movie-stride", "--fps", "--window-screenshot-step",
        "--max-steps", "--max-particles", "--max-file-size", "--max-face-corners",
        "--max-attributes", "--max-hybrid-passes", "--max-polygon-corners"}) {
    app.get_option(name)->check(decimal_number());
  }
  for (const char* name : {"-s", "-i", "--residual-file", "--window-screenshot"}) {
    app.get_option(name)->check(nonempty_name());
  }
  app.set_version_flag("--version", "FOSSSim 0.1.0");
  app.footer(integrator_help() + "\n" + contact_help() +
             "\nExit status: 0 success or passed; 1 grading failed; 2 bad command line, scene or\n"
             "trajectory file, a size over a limit, an output that would replace an input;\n"
             "3 a step failed (non-finite state, Newton did not converge); 4 an output file\n"
             "could not be written; 130 interrupted (docs/limits-and-failures.md).\n\n"
             "Examples:\n"
             "  FOSSSim -s assets/t1m1/springs_single.xml -d 0 -o out.bin\n"
             "  FOSSSim -s assets/t1m1/springs_single.xml -d 0 -i out.bin\n"
             "  FOSSSim -s scene.xml -d 0 --dt 0.001 --duration 2 -o fine.bin\n"
             "  FOSSSim -s scene.xml --check-derivatives\n"
             "  FOSSSim -s scene.xml                          (the window; see docs/viewing.md)\n"
             "  FOSSSim -s scene.xml --movie scene.mp4        (no display needed)\n"
             "  FOSSSim -s scene.xml -d 0 -g 1 --energy-plot energy.png");
}

void apply_overrides(const Options& options, Scene& scene) {
  SceneModel& model = scene.model;
  if (options.duration) {
    if (!std::isfinite(*options.duration) || *options.duration < 0.0)
      fail("--duration must be a finite number >= 0, found " + to_text(*options.duration));
    model.duration = *options.duration;
  }
  if (options.dt) {
    if (!std::isfinite(*options.dt) || *options.dt <= 0.0)
      fail("--dt must be a finite number > 0, found " + to_text(*options.dt));
    model.integrator.dt = *options.dt;
  }
  apply_integrator_options(options.integrator_options, scene);
  if (!options.view.empty() || options.orthographic) {
    if (model.dim != 3) fail("--view and --orthographic apply to 3D scenes (<scene dim=\"3\">)");
    if (!scene.appearance.camera3d) scene.appearance.camera3d.emplace();
    OrbitViewSettings& view = *scene.appearance.camera3d;
    if (!options.view.empty()) parse_view(options.view, view);
    if (options.orthographic) view.orthographic = true;
  }
}

}  // namespace fosssim
