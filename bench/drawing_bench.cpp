// Times the pictures of a 3D scene: composing the drawing of a state (projection, shading,
// depth sort) and painting it with Cairo at the window's size, for the 81 × 81 cloth of Liu et
// al. 2013 (assets3d/scenes/cloth_81.xml) after it has fallen for a while. Beside it, the
// baselines measured in the same process: one simulation step of the scene, and the flat
// drawing 3D scenes had before (every spring as a capsule and every particle as a disc, seen
// along -z). The same picture coloured by strain (--color-by strain) times the elements that
// forces show (3D membranes: Creative/membrane_drape.xml).
// Usage: bench_drawing [SCENE.xml [STEPS]]   (defaults: the 81 × 81 cloth, 45 steps)

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bench_clock.h"
#include "core/step/simulation.h"
#include "io/scene_loader.h"
#include "pictures/cairo_painter.h"
#include "render/scene_view.h"

namespace {

using namespace fosssim;
using bench::Clock;
using bench::load_average;

/// The median of `repeats` timings of `work`, milliseconds.
double median_ms(int repeats, const std::function<void()>& work) {
  std::vector<double> times;
  for (int r = 0; r < repeats; ++r) {
    const auto start = Clock::now();
    work();
    times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--help") {
    std::puts(
        "Usage: bench_drawing [SCENE.xml [STEPS]]\n"
        "  Times composing and painting the picture of SCENE (default: the 81 x 81 cloth,\n"
        "  assets3d/scenes/cloth_81.xml) after STEPS steps (default 45), against one step.");
    return 0;
  }
  const std::string path =
      argc > 1 ? argv[1] : std::string(FOSSSIM_SOURCE_DIR) + "/assets3d/scenes/cloth_81.xml";
  const int steps = argc > 2 ? std::stoi(argv[2]) : 45;
  std::optional<Scene> loaded;
  try {
    loaded.emplace(load_scene_file(path));
  } catch (const Error& error) {
    std::fprintf(stderr, "%s\n", error.what());
    return 2;
  }
  const Scene& scene = *loaded;
  Simulation simulation(scene.model, scene.initial);
  for (int k = 0; k < steps; ++k) simulation.step();
  const State& state = simulation.state();
  const double step_ms = median_ms(5, [&] { simulation.step(); });

  constexpr int kRepeats = 15;
  const SceneView view(scene, state, 512, 512);
  Drawing drawing;
  const double compose_ms = median_ms(kRepeats, [&] { drawing = view.compose(state); });
  const double paint_ms = median_ms(kRepeats, [&] { render_image(drawing); });
  const std::size_t shapes = drawing.shapes.size();
  // Membranes (elastic triangles in 3D) coloured by strain: the forces' elements with their
  // strains and energies are computed for every picture.
  SceneView strain_view(scene, state, 512, 512);
  strain_view.set_element_colors({ElementColoring::kStrain, 0.0});
  Drawing strain_drawing;
  const double strain_compose_ms =
      median_ms(kRepeats, [&] { strain_drawing = strain_view.compose(state); });
  const double strain_paint_ms = median_ms(kRepeats, [&] { render_image(strain_drawing); });
  std::vector<ForceElement> elements;
  for (const auto& force : scene.model.forces) force->append_elements(state.q, elements);

  Overlay overlay;
  const Camera flat_camera = fit_camera(state.q, 3, 512, 512);
  Drawing flat;
  const double flat_compose_ms = median_ms(kRepeats, [&] {
    flat = compose_drawing(scene, state, PathHistory(scene), flat_camera, 512, 512, overlay);
  });
  const double flat_paint_ms = median_ms(kRepeats, [&] { render_image(flat); });

  std::printf("scene %s after %d steps: %d particles, %zu edges, %zu triangles, %zu elements\n",
              path.c_str(), steps, scene.model.num_particles(), scene.model.edges.size(),
              scene.appearance.triangles.size(), elements.size());
  std::printf("load average %s; medians of %d runs, 512 x 512 pixels\n\n", load_average().c_str(),
              kRepeats);
  std::printf("%-44s %10s %10s\n", "", "ms", "ratio");
  std::printf("%-44s %10.2f %10.2f\n", "one simulation step (baseline)", step_ms, 1.0);
  std::printf("%-44s %10.2f %10.2f\n", "3D: compose (project, shade, sort)", compose_ms,
              compose_ms / step_ms);
  std::printf("%-44s %10.2f %10.2f\n", "3D: paint with Cairo", paint_ms, paint_ms / step_ms);
  std::printf("%-44s %10.2f %10.2f\n", "3D: picture total", compose_ms + paint_ms,
              (compose_ms + paint_ms) / step_ms);
  std::printf("%-44s %10.2f %10.2f\n", "3D by strain: compose", strain_compose_ms,
              strain_compose_ms / step_ms);
  std::printf("%-44s %10.2f %10.2f\n", "3D by strain: picture total",
              strain_compose_ms + strain_paint_ms, (strain_compose_ms + strain_paint_ms) / step_ms);
  std::printf("%-44s %10.2f %10.2f\n", "flat along -z, every spring: compose", flat_compose_ms,
              flat_compose_ms / step_ms);
  std::printf("%-44s %10.2f %10.2f\n", "flat along -z, every spring: paint", flat_paint_ms,
              flat_paint_ms / step_ms);
  std::printf("\n3D picture: %zu shapes; %.1f pictures per second\n", shapes,
              1000.0 / (compose_ms + paint_ms));
  return 0;
}
