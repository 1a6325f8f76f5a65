// The page's view of FOSSSim (Embind, module FOSSSimModule): one scene loaded from the text the
// student picked, pasted or edited, stepped on request and drawn with the same Drawing the
// native window and pictures paint (render/scene_view.h), flattened into numbers for the
// page's canvas (web/page/fosssim-page.js paints them).

#include <emscripten/bind.h>

#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/error.h"
#include "core/limits.h"
#include "core/step/simulation.h"
#include "io/scene_loader.h"
#include "render/drawing.h"
#include "render/scene_view.h"
#include "scripting/step_hooks.h"

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

/// One loaded scene and its run. load() returns the error text (file:line: error: ...) or "".
class WebSession {
 public:
  std::string load(const std::string& text, const std::string& name, int width, int height) {
    simulation_.reset();
    view_.reset();
    scene_.reset();
    try {
      Scene scene = load_scene_text(text, name);
      check_step_count(scene.model, Limits{});
      scene_ = std::make_unique<Scene>(std::move(scene));
      width_ = width;
      height_ = height;
      reset();
    } catch (const std::exception& error) {
      scene_.reset();
      return error.what();
    }
    return "";
  }

  void reset() {
    if (!scene_) return;
    simulation_ = std::make_unique<Simulation>(scene_->model, scene_->initial,
                                               scripted_additions(*scene_));
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

  /// The drawing of the current state, as commands (see Command).
  std::vector<double> draw() const {
    Commands commands;
    if (!view_) return commands.take();
    const Drawing d = view_->compose(simulation_->state());
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
  std::unique_ptr<Simulation> simulation_;
  std::unique_ptr<SceneView> view_;
  int width_ = 640, height_ = 480;
};

EMSCRIPTEN_BINDINGS(fosssim) {
  emscripten::register_vector<double>("VectorDouble");
  emscripten::class_<WebSession>("WebSession")
      .constructor<>()
      .function("load", &WebSession::load)
      .function("reset", &WebSession::reset)
      .function("step", &WebSession::step)
      .function("finished", &WebSession::finished)
      .function("time", &WebSession::time)
      .function("steps", &WebSession::steps)
      .function("warnings", &WebSession::warnings)
      .function("draw", &WebSession::draw);
}

}  // namespace fosssim
