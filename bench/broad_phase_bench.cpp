// Times FOSSSim's broad phase (core/collisions/grid_pairs.h) against all pairs on the contest's
// scene class and prints two tables: the two contest-size scenes of assets/t2m3 stepped with the
// grid and with all pairs (CPU milliseconds per step, the ratio, and the largest difference of the
// states, which is 0 when the trajectories are the same bit for bit); and the balls scene from
// 10^3 to 10^6 balls at the contest's density (time per step and per particle and step, which
// stay about constant when the cost grows linearly), with all pairs beside it where it takes
// seconds. Every baseline runs in this process; times are this thread's CPU time, steadier than
// wall time on a shared machine.
// Usage: bench_broad_phase [--quick | --smoke | --balls N] [--stats-json DIR]
//   --quick stops the scaling at 10^5 balls; --smoke runs its first size only, without the
//   contest scenes (it only shows that the program runs); --balls N times only the grid on N
//   balls (to profile);
//   --stats-json DIR writes the run summary of each contest scene's grid run (docs/command-line.md,
//   'Run summaries') as DIR/<scene>.stats.json

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "bench_clock.h"
#include "core/collisions/candidate_pairs.h"
#include "core/scene.h"
#include "core/step/step_pipeline.h"
#include "io/output_file.h"
#include "io/scene_loader.h"
#include "outputs/run_summary.h"

namespace {

using namespace fosssim;
using bench::load_average;
using bench::thread_cpu_milliseconds;

void add_particle(Scene& scene, double x, double y, double vx, double vy, bool fixed,
                  double radius) {
  const Eigen::Index n = scene.initial.q.size();
  scene.initial.q.conservativeResize(n + 2);
  scene.initial.v.conservativeResize(n + 2);
  scene.model.mass.conservativeResize(n + 2);
  scene.initial.q.tail(2) << x, y;
  scene.initial.v.tail(2) << vx, vy;
  scene.model.mass.tail(2).setConstant(1.0);
  scene.model.fixed.push_back(fixed);
  scene.model.particle_radius.push_back(radius);
}

/// The contest's scene class at `count` balls: radius 0.02, speeds up to 0.5, at the density
/// of 15,000 balls in [-5, 5]² (the square grows with the count), in a box of four fixed
/// corners of radius 0.5 half a unit outside the square joined by edges of radius 0.5;
/// symplectic Euler, h = 0.005, penalty k = 100, thickness 0.
Scene contest_balls(int count, unsigned seed) {
  Scene scene;
  scene.model.integrator.use(integrator_method("symplectic-euler"));
  scene.model.integrator.dt = 0.005;
  const double half = 5.0 * std::sqrt(count / 15000.0);
  scene.initial.q.resize(0);
  scene.initial.v.resize(0);
  scene.model.mass.resize(0);
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> place(-half, half), speed(0.0, 0.5),
      angle(0.0, 2.0 * M_PI);
  for (int k = 0; k < count; ++k) {
    const double x = place(random), y = place(random), s = speed(random), a = angle(random);
    add_particle(scene, x, y, s * std::cos(a), s * std::sin(a), false, 0.02);
  }
  const double corner = half + 0.5;
  const int first = count;
  for (const auto& [x, y] : {std::pair{-corner, -corner}, std::pair{corner, -corner},
                             std::pair{corner, corner}, std::pair{-corner, corner}}) {
    add_particle(scene, x, y, 0.0, 0.0, true, 0.5);
  }
  for (int k = 0; k < 4; ++k) {
    scene.model.edges.push_back({first + k, first + (k + 1) % 4});
    scene.model.edge_radius.push_back(0.5);
  }
  scene.model.collisions.method = &contact_method("penalty");
  scene.model.collisions.stiffness = 100.0;
  scene.model.collisions.thickness = 0.0;
  return scene;
}

struct Run {
  double ms_per_step = 0.0;
  State end;
};

/// `steps` steps of `scene` with pairs found as `detection` says, fed to `summary` if given
/// (outside the time measured: a summary computes every state's energy).
Run run(Scene& scene, PairDetection detection, int steps, RunSummary* summary = nullptr) {
  scene.model.collisions.detection = detection;
  StepPipeline pipeline(scene.model);
  State state = scene.initial;
  if (summary == nullptr) {
    const double start = thread_cpu_milliseconds();
    for (int k = 0; k < steps; ++k) pipeline.step(state);
    return {(thread_cpu_milliseconds() - start) / steps, std::move(state)};
  }
  summary->add(state, nullptr, &pipeline.integrator());
  double milliseconds = 0.0;
  for (int k = 0; k < steps; ++k) {
    const double start = thread_cpu_milliseconds();
    pipeline.step(state);
    milliseconds += thread_cpu_milliseconds() - start;
    summary->add(state, &pipeline.last_record(), &pipeline.integrator());
  }
  return {milliseconds / steps, std::move(state)};
}

double largest_difference(const State& a, const State& b) {
  return std::max((a.q - b.q).cwiseAbs().maxCoeff(), (a.v - b.v).cwiseAbs().maxCoeff());
}

/// Candidate pairs the grid finds for the initial positions, per particle.
double candidates_per_particle(Scene& scene) {
  scene.model.collisions.detection = PairDetection::kContest;
  const std::unique_ptr<CandidatePairs> pairs = make_candidate_pairs(scene.model);
  long count = 0;
  const Vector& q = scene.initial.q;
  pairs->for_each(PairQuery{q, q, scene.model.collisions.thickness},
                  [&count](const CandidatePair&) { ++count; });
  return static_cast<double>(count) / scene.model.num_particles();
}

void contest_scenes(const std::string& stats_folder) {
  std::printf(
      "Contest-size scenes of assets/t2m3: the grid against all pairs (all pairs takes 2 "
      "steps)\n\n");
  std::printf(
      "| scene | particles | edges | candidates per particle | grid ms/step | all pairs ms/step "
      "| ratio | largest difference after 2 steps |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const char* name : {"timing_balls_15000_contest", "timing_ribbon_pile_15000_contest"}) {
    Scene scene =
        load_scene_file(std::string(FOSSSIM_SOURCE_DIR) + "/assets/t2m3/" + name + ".xml");
    std::optional<RunSummary> summary;
    if (!stats_folder.empty()) summary.emplace(scene);
    const Run grid = run(scene, PairDetection::kContest, 20, summary ? &*summary : nullptr);
    if (summary) write_output_file(stats_folder + "/" + name + ".stats.json", summary->json());
    const Run grid_two = run(scene, PairDetection::kContest, 2);
    const Run all = run(scene, PairDetection::kAllPairs, 2);
    std::printf("| %s | %d | %zu | %.2f | %.2f | %.0f | %.0f | %.1e |\n", name,
                scene.model.num_particles(), scene.model.edges.size(),
                candidates_per_particle(scene), grid.ms_per_step, all.ms_per_step,
                all.ms_per_step / grid.ms_per_step, largest_difference(grid_two.end, all.end));
    std::fflush(stdout);
  }
}

void scaling(bool quick, bool smoke) {
  std::printf(
      "\nScaling: the balls scene at the contest's density (20 steps; all pairs 2 steps, up to "
      "3e4 balls)\n\n");
  std::printf(
      "| balls | candidates per ball | grid ms/step | grid ns per ball and step | all "
      "pairs ms/step | ratio | largest difference after 2 steps |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const int count : {1000, 3000, 10000, 30000, 100000, 300000, 1000000}) {
    if ((quick && count > 100000) || (smoke && count > 1000)) break;
    Scene scene = contest_balls(count, 7);
    const Run grid = run(scene, PairDetection::kContest, 20);
    const double per_ball = grid.ms_per_step * 1e6 / count;
    std::printf("| %d | %.2f | %.2f | %.0f |", count, candidates_per_particle(scene),
                grid.ms_per_step, per_ball);
    if (count <= 30000) {
      const Run grid_two = run(scene, PairDetection::kContest, 2);
      const Run all = run(scene, PairDetection::kAllPairs, 2);
      std::printf(" %.1f | %.0f | %.1e |\n", all.ms_per_step, all.ms_per_step / grid.ms_per_step,
                  largest_difference(grid_two.end, all.end));
    } else {
      std::printf(" | | |\n");
    }
    std::fflush(stdout);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "--help") == 0) {
    std::puts(
        "Usage: bench_broad_phase [--quick | --smoke | --balls N] [--stats-json DIR]\n"
        "  The grid broad phase against all pairs on the contest's two scenes, then the balls\n"
        "  scene from 10^3 to 10^6 balls. --quick: up to 10^5 balls. --smoke: 10^3 balls only,\n"
        "  no contest scene (to see that it runs). --balls N: the grid alone on N balls (to\n"
        "  profile). --stats-json DIR: the contest scenes' run summaries there.");
    return 0;
  }
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const bool smoke = argc > 1 && std::strcmp(argv[1], "--smoke") == 0;
  std::string stats_folder;
  for (int k = 1; k + 1 < argc; ++k) {
    if (std::strcmp(argv[k], "--stats-json") == 0) stats_folder = argv[k + 1];
  }
  if (argc > 2 && std::strcmp(argv[1], "--balls") == 0) {  // one size, grid only, to profile
    Scene scene = contest_balls(std::atoi(argv[2]), 7);
    std::printf("%.2f ms/step\n", run(scene, PairDetection::kContest, 20).ms_per_step);
    return 0;
  }
  std::printf("Broad phase benchmark (load average %s)\n\n", load_average().c_str());
  if (!smoke) contest_scenes(stats_folder);
  scaling(quick, smoke);
  return 0;
}
