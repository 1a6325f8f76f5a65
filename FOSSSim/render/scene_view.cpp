#include "render/scene_view.h"

namespace fosssim {

SceneView::SceneView(const Scene& scene, const State& initial, int width, int height)
    : scene_(scene),
      width_(width),
      height_(height),
      camera_(initial_camera(scene, initial, width, height)),
      paths_(scene) {
  paths_.record(initial.q, scene.model.dim);
}

void SceneView::record(const State& state) { paths_.record(state.q, scene_.model.dim); }

Drawing SceneView::compose(const State& state, const Overlay& overlay) const {
  return compose_drawing(scene_, state, paths_, camera_, width_, height_, overlay);
}

void SceneView::recenter(const State& state) {
  camera_ = fit_camera(state.q, scene_.model.dim, width_, height_);
}

void SceneView::restart_trails(const State& state) {
  paths_.clear();
  paths_.record(state.q, scene_.model.dim);
}

void SceneView::resize(int width, int height) {
  width_ = width;
  height_ = height;
}

}  // namespace fosssim
