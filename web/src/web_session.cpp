// The page's view of FOSSSim (Embind, module FOSSSimModule): one scene loaded from the text the
// student picked, pasted or edited, stepped on request and drawn with the same Drawing the
// native window and pictures paint (render/scene_view.h), flattened into numbers for the
// page's canvas (web/page/fosssim-page.js paints them).

#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "core/analysis/energy.h"
#include "core/error.h"
#include "core/limits.h"
#include "core/step/simulation.h"
#include "grading/grader.h"
#include "grading/rigid_grader.h"
#include "grading/step_grader.h"
#include "io/input_files.h"
#include "io/json_scene_reader.h"
#include "io/scene_loader.h"
#include "io/trajectory_file.h"
#include "render/drawing.h"
#include "render/scene_view.h"
#include "scene_trajectory.h"
#include "scripting/step_hooks.h"
#include "viewer/particle_grab.h"

namespace fosssim {
namespace {

/// Drawing commands, one after another: a code, then its numbers (pixels, colours in [0, 1]).
enum Command : int {
  kBackground = 0,  // r g b
  kRegion = 1,      // n, n × (x y), r g b
  kPolyline = 2,    // n, width, n × (x y), r g b
  kTriangle = 3,    // x0 y0 x1 y1 x2 y2, r g b, outline width, r g b
  kCapsule = 4,     // ax ay bx by radius, r g b
  kDisc = 5,        // cx cy radius, r g b
  kRing = 6,        // cx cy radius width, r g b
};

class Commands {
 public:
  void color(const Color& c) { values_.insert(values_.end(), {c.r, c.g, c.b}); }
  void add(const Region& r) {
    begin(kRegion, static_cast<double>(r.corners.size()));
    for (const Point2& p : r.corners) point(p);
    color(r.color);
  }
  void add(const Polyline& l) {
    begin(kPolyline, static_cast<double>(l.points.size()));
    values_.push_back(l.width);
    for (const Point2& p : l.points) point(p);
    color(l.color);
  }
  void add(const Triangle& t) {
    values_.push_back(kTriangle);
    for (const Point2& p : t.corners) point(p);
    color(t.color);
    values_.push_back(t.outline_width);
    color(t.outline_color);
  }
  void add(const Capsule& c) {
    values_.push_back(kCapsule);
    point(c.a);
    point(c.b);
    values_.push_back(c.radius);
    color(c.color);
  }
  void add(const Disc& d) {
    values_.push_back(kDisc);
    point(d.center);
    values_.push_back(d.radius);
    color(d.color);
  }
  void add(const Ring& r) {
    values_.push_back(kRing);
    point(r.center);
    values_.insert(values_.end(), {r.radius, r.width});
    color(r.color);
  }
  void begin(Command code, double count) { values_.insert(values_.end(), {double(code), count}); }
  void background(const Color& c) {
    values_.push_back(kBackground);
    color(c);
  }
  std::vector<double> take() { return std::move(values_); }

 private:
  void point(const Point2& p) { values_.insert(values_.end(), {p.x, p.y}); }
  std::vector<double> values_;
};

}  // namespace

/// Bytes of a file of Emscripten's in-memory file system, which the page's trajectories pass
/// through: FOSSSim's writers and readers work on files, as natively.
std::string read_memory_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// The result of grading an uploaded trajectory: what `FOSSSim -s SCENE -i FILE` prints on its
/// standard output (the report) and standard error (the failure's description or the error),
/// and whether it passed (exit status 0).
struct GradeOutcome {
  std::string report;
  std::string problem;
  bool passed = false;
};

/// One loaded scene and its run. load() returns the error text (file:line: error: ...) or "".
class WebSession {
 public:
  ///
  /// `name` is the scene's path (a suite's "assets3d/scenes/x.xml", a student's "x.xml"); the
  /// files it names (meshes), relative to its folder as natively, are served from the files
  /// added with add_file and nothing else. A name ending in ".json" is read as a JSON scene, as
  /// `FOSSSim -s` does. When a named file is not among them, missing_file() says which path the
  /// loader asked for: the page fetches it or takes it from the student's files, adds it and
  /// loads again.
  std::string load(const std::string& text, const std::string& name, int width, int height) {
    view_.reset();
    simulation_.reset();
    grab_.reset();
    scene_.reset();
    missing_.clear();
    InputFiles files = InputFiles::in_memory(added_);
    try {
      Scene scene = std::filesystem::path(name).extension() == ".json"
                        ? load_json_scene_text(text, name, files)
                        : load_scene_text(text, name, files);
      check_step_count(scene.model, Limits{});
      scene_ = std::make_unique<Scene>(std::move(scene));
      width_ = width;
      height_ = height;
      reset();
    } catch (const std::exception& error) {
      scene_.reset();
      for (const std::string& path : files.paths()) {
        if (added_.count(path) == 0) {
          missing_ = path;
          break;
        }
      }
      return error.what();
    }
    return "";
  }

  /// The first file the last load() tried to read and did not find, or "".
  std::string missing_file() const { return missing_; }

  /// Adds the file `path` (the path the loader asked for, missing_file()) with content `bytes`
  /// for the scenes loaded next: a mesh fetched from the served suites or opened by the
  /// student. At most Limits::max_file_bytes each (the loader's limit). Returns "" or the problem.
  std::string add_file(const std::string& path, const std::string& bytes) {
    if (static_cast<std::int64_t>(bytes.size()) > Limits{}.max_file_bytes) {
      return path + ": larger than the limit of " + std::to_string(Limits{}.max_file_bytes) +
             " bytes";
    }
    added_[path] = bytes;
    return "";
  }
  /// Forgets the added files: a scene of another origin must not find them.
  void clear_files() { added_.clear(); }

  /// The positions of the current state, `dim` numbers per particle (2D: x y), metres.
  std::vector<double> positions() const {
    if (!simulation_) return {};
    const Vector& q = simulation_->state().q;
    return std::vector<double>(q.data(), q.data() + q.size());
  }

  void reset() {
    if (!scene_) return;
    view_.reset();
    simulation_.reset();
    grab_ = std::make_unique<ParticleGrab>(*scene_);
    StepAdditions additions = scripted_additions(*scene_);
    additions.interaction_forces.push_back(&grab_->interaction_force());
    simulation_ =
        std::make_unique<Simulation>(scene_->model, scene_->initial, std::move(additions));
    view_ = std::make_unique<SceneView>(*scene_, simulation_->state(), width_, height_);
  }

  /// Takes up to `count` steps; returns "" or the error that stopped the run.
  std::string step(int count) {
    if (!simulation_) return "no scene is loaded";
    try {
      for (int k = 0; k < count && !simulation_->finished(); ++k) {
        simulation_->step();
        view_->record(simulation_->state());
      }
    } catch (const std::exception& error) {
      return scene_->source + ": " + error.what();
    }
    return "";
  }

  bool finished() const { return !simulation_ || simulation_->finished(); }
  double time() const { return simulation_ ? simulation_->state().time : 0.0; }
  double steps() const { return simulation_ ? double(simulation_->state().step) : 0.0; }
  std::string warnings() const {
    std::string all;
    if (scene_) {
      for (const std::string& w : scene_->warnings) all += w + "\n";
    }
    return all;
  }

  /// Kinetic, potential and total energy of the current state (core/analysis/energy.h), as the
  /// native energy plot computes them; empty without a scene.
  std::vector<double> energy() const {
    if (!simulation_) return {};
    const EnergyReport e = compute_energies(scene_->model, simulation_->state());
    return {e.kinetic, e.potential, e.total()};
  }

  /// Mouse dragging, as the native window's: press grabs the free particle under pixel (x, y)
  /// (returns false when there is none), move pulls it toward the cursor, release lets go.
  bool press(double x, double y) {
    return view_ && grab_->press(*view_, simulation_->state(), x, y);
  }
  void move(double x, double y) {
    if (view_ && grab_->active()) grab_->move(*view_, x, y);
  }
  void release() {
    if (grab_) grab_->release();
  }

  /// The loaded scene's whole run from its initial state as the bytes of its trajectory file
  /// (a Uint8Array), exactly what `FOSSSim -s SCENE -d 0 -o OUT` writes (scene_trajectory.h),
  /// or null with the error in last_error(). The interactive run is not touched.
  emscripten::val trajectory() {
    const std::string bytes = trajectory_bytes();
    if (!error_.empty()) return emscripten::val::null();
    // A copy: the view into the wasm memory is gone when `bytes` is.
    return emscripten::val::global("Uint8Array")
        .new_(emscripten::typed_memory_view(bytes.size(),
                                            reinterpret_cast<const unsigned char*>(bytes.data())));
  }
  std::string trajectory_bytes() {
    error_.clear();
    if (!scene_) {
      error_ = "no scene is loaded";
      return {};
    }
    const std::string path = "/tmp/fosssim-trajectory.bin";
    try {
      write_scene_trajectory(*scene_, path);
    } catch (const std::exception& error) {
      error_ = scene_->source + ": " + error.what();
      return {};
    }
    std::string bytes = read_memory_file(path);
    std::remove(path.c_str());
    return bytes;
  }
  std::string last_error() const { return error_; }

  /// Grades the trajectory `bytes` (an uploaded file called `name`) against the loaded scene
  /// with the course's criteria, through the code `FOSSSim -s SCENE -i FILE` runs
  /// (app/run_grading.cpp): the same report, failure description and verdict.
  GradeOutcome grade(const std::string& bytes, const std::string& name) {
    GradeOutcome out;
    if (!scene_) {
      out.problem = "no scene is loaded";
      return out;
    }
    const std::string path = "/tmp/fosssim-upload.bin";
    {
      std::ofstream file(path, std::ios::binary | std::ios::trunc);
      file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    }
    std::ostringstream report;
    try {
      if (scene_->model.rigid_bodies) {
        const RigidGradeReport rigid = grade_rigid_trajectory(*scene_, path);
        print_rigid_grade_report(report, rigid);
        out.passed = rigid.passed();
      } else {
        TrajectoryReader file = open_trajectory(path, scene_->model);
        StepGrader grader = StepGrader::open(*scene_, file, std::nullopt, Cancellation());
        while (grader.grade_next_step()) {
        }
        const GradeReport& result = grader.report();
        print_grade_report(report, result);
        out.passed = result.passed();
        if (!out.passed) out.problem = describe_failure(result, scene_->model.dim);
      }
    } catch (const std::exception& error) {
      out.problem = name + ": " + error.what();
    }
    std::remove(path.c_str());
    out.report = report.str();
    return out;
  }

  /// The drawing of the current state, as commands (see Command).
  std::vector<double> draw() const {
    Commands commands;
    if (!view_) return commands.take();
    Overlay overlay;
    overlay.drag = grab_->guide();
    const Drawing d = view_->compose(simulation_->state(), overlay);
    commands.background(d.background);
    for (const Region& r : d.regions) commands.add(r);
    for (const Polyline& p : d.paths) commands.add(p);
    for (const Shape& s : d.shapes) std::visit([&](const auto& x) { commands.add(x); }, s);
    for (const Capsule& e : d.edges) commands.add(e);
    for (const Disc& p : d.particles) commands.add(p);
    for (const Ring& m : d.marks) commands.add(m);
    for (const Polyline& g : d.guides) commands.add(g);
    return commands.take();
  }

 private:
  std::unique_ptr<Scene> scene_;
  std::unique_ptr<ParticleGrab> grab_;  // before the simulation, which holds its spring
  std::unique_ptr<Simulation> simulation_;
  std::unique_ptr<SceneView> view_;
  std::string error_;
  std::string missing_;
  std::map<std::string, std::string> added_;  ///< path -> content, served to the loader
  int width_ = 640, height_ = 480;
};

EMSCRIPTEN_BINDINGS(fosssim) {
  emscripten::register_vector<double>("VectorDouble");
  emscripten::value_object<GradeOutcome>("GradeOutcome")
      .field("report", &GradeOutcome::report)
      .field("problem", &GradeOutcome::problem)
      .field("passed", &GradeOutcome::passed);
  emscripten::class_<WebSession>("WebSession")
      .constructor<>()
      .function("load", &WebSession::load)
      .function("missingFile", &WebSession::missing_file)
      .function("addFile", &WebSession::add_file)
      .function("clearFiles", &WebSession::clear_files)
      .function("positions", &WebSession::positions)
      .function("reset", &WebSession::reset)
      .function("step", &WebSession::step)
      .function("finished", &WebSession::finished)
      .function("time", &WebSession::time)
      .function("steps", &WebSession::steps)
      .function("warnings", &WebSession::warnings)
      .function("energy", &WebSession::energy)
      .function("press", &WebSession::press)
      .function("move", &WebSession::move)
      .function("release", &WebSession::release)
      .function("trajectory", &WebSession::trajectory)
      .function("lastError", &WebSession::last_error)
      .function("grade", &WebSession::grade)
      .function("draw", &WebSession::draw);
}

}  // namespace fosssim
