// How far a few local/global iterations are from implicit Euler, from each start, on a flag:
// the table of docs/scenes-3d.md ("Where the iterations start"). Usage:
//   bench_iteration_start [--quick]   (--quick: a 40 × 20 flag)
//
// The flag is the JSON scene that this command writes (80 × 40 vertices, 2 m × 1 m, hanging
// in the xy plane and held along its left side, quads with both diagonals, k = 10⁵ N/m as in
// the assignment's flag, masses from Voronoi areas at 1 kg/m², h = 1/30 s, penalty pins,
// -9.8 N on every vertex):
//   FOSSSim-generate -o flag.obj --json flag.json --k 100000 --pins left-column
//       cloth --nx 80 --ny 40 --width 2 --height 1 --no-bend
// Implicit Euler's trajectory from each start is local/global iterated at every step until no
// coordinate moves more than 10⁻¹² m. (Newton's method, implicit-euler, agrees with it from rest
// to 2·10⁻¹² on the 40 × 20 flag, but needs more than 200 iterations for the first step of the
// 80 × 40 one; and since the step's energy is not convex, it and the two starts may end in
// different minima once the flag moves.) Three measures, for 10, 50 and 200 iterations from
// each start, all as the largest distance of a vertex relative to the diagonal of the flag's
// bounding box at rest: the first step, from rest; single steps from implicit Euler's states
// at every third step of the first second, where the flag moves; and the whole 10 s run.

#include <array>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/integrators/integrator.h"
#include "core/integrators/local_global.h"
#include "core/step/simulation.h"
#include "io/json_scene_reader.h"
#include "io/mesh_writer.h"
#include "mesh/generators.h"

namespace {

using namespace fosssim;

constexpr int kSteps = 300;  // 10 s
/// Implicit Euler's step: the iterations continued until no coordinate moves more than this, m.
constexpr double kTolerance = 1e-12;
/// The steps of implicit Euler's trajectory whose states single steps start from: at rest,
/// then in the first second, where the flag moves.
constexpr std::array<int, 10> kSamples = {0, 3, 6, 9, 12, 15, 18, 21, 24, 27};

/// Writes the flag's OBJ and JSON (nx × ny vertices) into `dir`; returns the JSON's path.
std::string write_flag(int nx, int ny, const std::filesystem::path& dir) {
  const GeneratedMesh cloth = generate_cloth(nx, ny, 2.0, 1.0, false, false);
  std::filesystem::create_directories(dir);
  write_obj_file((dir / "flag.obj").string(), cloth.mesh);
  std::string json = "{\"obj\": \"flag.obj\", \"k\": 100000, \"b\": [";
  const std::vector<int>& pole = *cloth.find_pins("left-column");
  for (std::size_t p = 0; p < pole.size(); ++p)
    json += (p > 0 ? ", " : "") + std::to_string(pole[p] + 1);
  json += "]}\n";
  const std::string path = (dir / "flag.json").string();
  std::ofstream(path) << json;
  return path;
}

double diagonal(const Vector& q) {
  const auto points = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
      q.data(), q.size() / 3, 3);
  return (points.colwise().maxCoeff() - points.colwise().minCoeff()).norm();
}

double largest_distance(const Vector& a, const Vector& b) {
  double largest = 0.0;
  for (Eigen::Index p = 0; p < a.size() / 3; ++p)
    largest = std::max(largest, (a.segment<3>(3 * p) - b.segment<3>(3 * p)).norm());
  return largest;
}

/// A local/global integrator bound to its own copy of the flag.
struct Stepper {
  Stepper(const std::string& json, int iterations, const char* start, double tolerance)
      : scene(load_json_scene_file(json)) {
    OptionValues& options = scene.model.integrator.options;
    options.set("iterations", iterations);
    options.set("start", start);
    options.set("tolerance", tolerance);
    integrator = make_integrator(scene.model);
  }
  Scene scene;
  std::unique_ptr<Integrator> integrator;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc == 2 && std::strcmp(argv[1], "--quick") == 0;
  if (argc > 1 && !quick) {
    const bool help = std::strcmp(argv[1], "--help") == 0;
    std::fputs(
        "Usage: bench_iteration_start [--quick]\n"
        "  How far 10, 50 and 200 local/global iterations from each start are from implicit\n"
        "  Euler on an 80 x 40 flag (docs/scenes-3d.md). --quick: a 40 x 20 flag.\n",
        help ? stdout : stderr);
    return help ? 0 : 2;
  }
  const int nx = quick ? 40 : 80, ny = quick ? 20 : 40;
  const auto dir = std::filesystem::temp_directory_path() / "fosssim-bench-iteration-start";
  const std::string json = write_flag(nx, ny, dir);

  const auto start = std::chrono::steady_clock::now();
  const std::array<const char*, 2> starts = {"current", "inertial"};

  // Implicit Euler's trajectories: local/global iterated at every step until no coordinate
  // moves more than kTolerance, from each start.
  std::array<std::vector<State>, 2> exact;
  long long converged_iterations = 0;
  double size = 0.0;
  for (int s = 0; s < 2; ++s) {
    Stepper stepper(json, 1000000, starts[s], kTolerance);
    size = diagonal(stepper.scene.initial.q);
    Simulation run(stepper.scene.model, stepper.scene.initial);
    exact[s].push_back(run.state());
    for (int step = 0; step < kSteps; ++step) {
      run.step();
      exact[s].push_back(run.state());
      converged_iterations +=
          static_cast<const LocalGlobal<3>&>(run.integrator()).last_iterations();
    }
  }
  double apart = 0.0;
  for (int step = 0; step < kSteps; ++step)
    apart = std::max(apart, largest_distance(exact[0][step + 1].q, exact[1][step + 1].q));
  // How far implicit Euler moves a vertex in the first step, and at most in the other samples.
  const double first_move = largest_distance(exact[1][0].q, exact[1][1].q);
  double moving_move = 0.0;
  for (int step : kSamples) {
    if (step > 0)
      moving_move = std::max(moving_move, largest_distance(exact[1][step].q, exact[1][step + 1].q));
  }

  std::printf(
      "Flag of %d x %d vertices (k = 1e5 N/m, h = 1/30 s): local/global with 10, 50 and 200 "
      "iterations against\nimplicit Euler, the same iterations continued until no coordinate "
      "moves more than %.0e m (%.0f per step\non average). Largest distance of a vertex, "
      "relative to the bounding-box diagonal (%.3f m); implicit Euler\nmoves a vertex by up to "
      "%.2e of it in the first step, %.2e in the other sampled steps.\n\n",
      nx, ny, kTolerance, static_cast<double>(converged_iterations) / (2.0 * kSteps), size,
      first_move / size, moving_move / size);
  std::printf("%-24s %-22s %10s %10s %10s\n", "start", "measure", "10 iter.", "50 iter.",
              "200 iter.");
  for (int s = 0; s < 2; ++s) {
    std::vector<double> from_rest, moving, whole_run;
    for (int iterations : {10, 50, 200}) {
      Stepper stepper(json, iterations, starts[s], 0.0);
      double largest = 0.0;
      for (int step : kSamples) {
        State state = exact[s][step];
        stepper.integrator->step(state);
        const double distance = largest_distance(state.q, exact[s][step + 1].q) / size;
        if (step == 0) {
          from_rest.push_back(distance);
        } else {
          largest = std::max(largest, distance);
        }
      }
      moving.push_back(largest);
      largest = 0.0;
      Simulation run(stepper.scene.model, stepper.scene.initial);
      for (int step = 1; step <= kSteps; ++step) {
        run.step();
        largest = std::max(largest, largest_distance(run.state().q, exact[s][step].q));
      }
      whole_run.push_back(largest / size);
    }
    const auto row = [](const char* name, const char* measure, const std::vector<double>& x) {
      std::printf("%-24s %-22s %10.2e %10.2e %10.2e\n", name, measure, x[0], x[1], x[2]);
    };
    row(s == 0 ? "current (p^n)" : "inertial (p^n + h v^n)", "one step from rest", from_rest);
    row("", "one step, moving", moving);
    row("", "whole run of 10 s", whole_run);
  }
  std::printf(
      "\nImplicit Euler's step is not unique (its energy is not convex): the converged "
      "trajectories from the two\nstarts are up to %.2e apart.\n\n(%.0f s in all)\n",
      apart / size, seconds_since(start));
  std::filesystem::remove_all(dir);
  return 0;
}
