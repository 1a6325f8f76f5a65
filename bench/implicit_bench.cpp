// Times FOSSSim's implicit integrators against straightforward solutions in the same run and
// prints the tables of docs/integrators.md ("Speed"): per-step times and peak memory from 10³
// to 10⁶ unknowns, the goals of the solver work as ratios, and accuracy against time on the
// 81×81 cloth. Every measurement runs in a process of its own (this program, started again
// with --case), so that each peak memory is its own. Not a test: run it on a quiet machine.
//
// Usage: bench_implicit [--quick | --smoke] [--bunny FILE.mesh] [--table scaling|goals|accuracy]...
//   --quick   sizes up to 10⁴ unknowns only, fewer steps
//   --smoke   the scaling table alone at 10³ unknowns, 2 steps each (only shows that it runs)

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "accuracy.h"
#include "baselines.h"
#include "bench_scenes.h"
#include "core/integrators/implicit_euler.h"
#include "core/integrators/integrator_registry.h"
#include "core/integrators/linearized_implicit_euler.h"
#include "core/integrators/linearly_implicit_euler.h"
#include "core/integrators/newton.h"
#include "core/solvers/memory_policy.h"
#include "io/medit_reader.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace fosssim::bench {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string one, five, fifteen;
  in >> one >> five >> fifteen;
  return one + " " + five + " " + fifteen;
}

// ---------------------------------------------------------------------------------------------
// One case, in the child process.

/// The method-name suffix that runs a baseline with keep_freed_memory().
constexpr std::string_view kKeptHeapSuffix = "+kept-heap";

/// The allocator setting most favourable to a baseline that allocates its triplets and sparse
/// matrices afresh every step: glibc maps no block below 32 MiB (the most it allows) on its own
/// and never trims the heap's top, so what one step frees the next reuses, warm, instead of
/// faulting it in again. On this project's virtual machines a page fault is dear: under glibc's
/// defaults the student a2 baseline spends about three quarters of its CPU time faulting pages
/// in (docs/solvers.md, "The CSC417 bunny").
void keep_freed_memory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max());
#endif
}

/// The step solver of an integrator that has one, or nullptr.
const StepSolver* step_solver(const Integrator& integrator) {
  if (const auto* i = dynamic_cast<const LinearlyImplicitEuler*>(&integrator)) return &i->solver();
  if (const auto* i = dynamic_cast<const LinearizedImplicitEuler*>(&integrator)) {
    return &i->solver();
  }
  if (const auto* i = dynamic_cast<const ImplicitEuler*>(&integrator)) return &i->solver();
  if (const auto* i = dynamic_cast<const Newton*>(&integrator)) return &i->solver();
  return nullptr;
}

/// The scene of a case: its family, size parameter and integrator (for baselines, the
/// registry method whose options they read).
Scene make_scene(const std::string& family, int size, const std::string& integrator) {
  if (family == "cloth3d") return cloth_3d(size, integrator);
  if (family == "cloth2d") return damped_cloth_2d(size, integrator);
  if (family == "ball") return tet_ball(size, integrator);
  if (family == "bunny") return bunny_stand_in(integrator);
  if (family == "flag") return flag(size, size / 2, integrator);
  // "medit:PATH": a MEDIT tet mesh read from PATH, in the assignment's settings (the CSC417
  // bunny: pins within 3 units of the lowest y; `size` is unused).
  if (family.rfind("medit:", 0) == 0) {
    return assignment_tet_scene(read_medit_file(family.substr(6)), 3.0, integrator);
  }
  throw std::runtime_error("unknown scene family " + family);
}

/// Runs `method` on a scene: precompute and one step, then steps until `max_steps` or
/// `budget` seconds. Prints "result FIRST_MS STEP_MS STEPS"; with `save`, writes the final
/// positions there (raw doubles).
int run_case(const std::string& family, int size, const std::string& method, int max_steps,
             double budget, const std::string& save,
             const std::vector<std::pair<std::string, std::string>>& options) {
  const bool kept_heap = method.size() > kKeptHeapSuffix.size() &&
                         method.compare(method.size() - kKeptHeapSuffix.size(),
                                        kKeptHeapSuffix.size(), kKeptHeapSuffix) == 0;
  std::unique_ptr<Integrator> baseline =
      make_baseline(kept_heap ? method.substr(0, method.size() - kKeptHeapSuffix.size()) : method);
  if (kept_heap && !baseline) throw std::runtime_error(method + ": not a baseline");
  if (kept_heap) keep_freed_memory();
  // FOSSSim's cases run under the allocator policy the FOSSSim program sets first thing; the
  // baselines under glibc's defaults, as a student's program would (the policy maps every
  // block of 1 MiB or more on its own, and a baseline that allocates its triplets afresh every
  // step would then fault them in every step).
  if (!baseline) return_large_blocks_to_system();
  const std::string integrator =
      baseline ? (family == "flag" ? "local-global" : "linearly-implicit-euler") : method;
  Scene scene = make_scene(family, size, integrator);
  for (const auto& [name, value] : options) {
    char* end = nullptr;
    const double number = std::strtod(value.c_str(), &end);
    if (*end == '\0') {
      set_option(scene, name, number);
    } else {
      set_option(scene, name, value);
    }
  }
  std::unique_ptr<Integrator> integrator_object =
      baseline
          ? std::move(baseline)
          : scene.model.integrator.method->create(scene.model.integrator.options, scene.model.dim);
  State state = scene.initial;
  auto start = Clock::now();
  timespec cpu_start{}, cpu_end{};
  integrator_object->precompute(scene.model);
  integrator_object->step(state);
  const double first = seconds_since(start);
  start = Clock::now();
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &cpu_start);
  int steps = 0;
  while (steps < max_steps && (steps == 0 || seconds_since(start) < budget)) {
    integrator_object->step(state);
    ++steps;
  }
  const double per_step = steps > 0 ? seconds_since(start) / steps : 0.0;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &cpu_end);
  const double cpu_seconds = static_cast<double>(cpu_end.tv_sec - cpu_start.tv_sec) +
                             1e-9 * static_cast<double>(cpu_end.tv_nsec - cpu_start.tv_nsec);
  const double cpu_per_step = steps > 0 ? cpu_seconds / steps : 0.0;
  if (!state.q.allFinite()) {
    std::printf("failed non-finite\n");
    return 1;
  }
  if (!save.empty()) {
    std::ofstream out(save, std::ios::binary);
    out.write(reinterpret_cast<const char*>(state.q.data()),
              static_cast<std::streamsize>(sizeof(double) * state.q.size()));
  }
  if (const StepSolver* solver = step_solver(*integrator_object)) {
    const SolveStatistics& s = solver->statistics();
    std::printf("solver solves %lld factorizations %lld krylov %lld lu %lld direct %lld\n",
                static_cast<long long>(s.solves), static_cast<long long>(s.factorizations),
                static_cast<long long>(s.krylov_iterations),
                static_cast<long long>(s.lu_factorizations),
                static_cast<long long>(s.direct_fallbacks));
  }
  std::printf("result %.6f %.6f %d %.6f\n", 1e3 * first, 1e3 * per_step, steps,
              1e3 * cpu_per_step);
  return 0;
}

// ---------------------------------------------------------------------------------------------
// The parent: starts cases and prints tables.

struct Measured {
  bool ok = false;
  double first_ms = 0.0;
  double step_ms = 0.0;
  int steps = 0;
  double cpu_step_ms = 0.0;  ///< the process's CPU time per step: on a loaded machine, closer
                             ///< to a quiet machine's wall time than the wall time is
  double peak_mb = 0.0;
  std::string output;  ///< everything the case printed
};

std::string self_path;

/// Runs this program with `args` and collects its result line and peak memory.
Measured measure(const std::vector<std::string>& args) {
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) return {};
  const pid_t child = fork();
  if (child == 0) {
    dup2(pipe_fds[1], STDOUT_FILENO);
    close(pipe_fds[0]);
    close(pipe_fds[1]);
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(self_path.c_str()));
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(self_path.c_str(), argv.data());
    _exit(127);
  }
  close(pipe_fds[1]);
  std::string output;
  char buffer[4096];
  for (ssize_t got; (got = read(pipe_fds[0], buffer, sizeof buffer)) > 0;)
    output.append(buffer, got);
  close(pipe_fds[0]);
  int status = 0;
  rusage usage{};
  wait4(child, &status, 0, &usage);
  Measured m;
  m.output = output;
  m.peak_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;
  const auto at = output.find("result ");
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && at != std::string::npos) {
    std::istringstream in(output.substr(at + 7));
    in >> m.first_ms >> m.step_ms >> m.steps >> m.cpu_step_ms;
    m.ok = true;
  }
  return m;
}

Measured measure_steps(const std::string& family, int size, const std::string& method,
                       int max_steps, double budget, const std::string& save = "",
                       const std::vector<std::string>& options = {}) {
  std::vector<std::string> args = {"--case",
                                   family,
                                   std::to_string(size),
                                   method,
                                   std::to_string(max_steps),
                                   std::to_string(budget),
                                   save.empty() ? "-" : save};
  for (const std::string& o : options) args.push_back(o);
  return measure(args);
}

std::vector<double> read_doubles(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<double> values;
  double x;
  while (in.read(reinterpret_cast<char*>(&x), sizeof x)) values.push_back(x);
  return values;
}

/// The largest difference between the doubles of two files written by cases.
double largest_difference(const std::string& path_a, const std::string& path_b) {
  const std::vector<double> a = read_doubles(path_a), b = read_doubles(path_b);
  double difference = 0.0;
  for (std::size_t k = 0; k < a.size() && k < b.size(); ++k) {
    difference = std::max(difference, std::abs(a[k] - b[k]));
  }
  return difference;
}

std::string cell(const Measured& m) {
  char text[64];
  if (!m.ok) return "-";
  if (m.step_ms >= 100.0) {
    std::snprintf(text, sizeof text, "%.0f ms, %.0f MB", m.step_ms, m.peak_mb);
  } else {
    std::snprintf(text, sizeof text, "%.2f ms, %.0f MB", m.step_ms, m.peak_mb);
  }
  return text;
}

// ---------------------------------------------------------------------------------------------
// Tables.

struct Family {
  const char* title;
  const char* family;
  int dim;
  std::vector<std::pair<std::string, std::string>> methods;  ///< (label, method)
};

/// Per-step times and peak memory from 10³ to 10⁶ unknowns.
void scaling_table(bool quick, bool smoke) {
  const std::vector<Family> families = {
      {"3D cloth (Liu et al. 2013's, flat, two corners held), 3 n unknowns",
       "cloth3d",
       3,
       {{"linearly implicit Euler", "linearly-implicit-euler"},
        {"Newton (newton)", "newton"},
        {"quasi-Newton (quasi-newton)", "quasi-newton"},
        {"local/global, 10 iterations", "local-global"},
        {"Anderson local/global, 10 iterations", "accelerated-local-global"},
        {"old path: LIE, triplets + Eigen LDLT", "old-lie"},
        {"Levin's recipe: SimplicialLDLT every step", "levin"},
        {"Eigen SparseLU every step", "sparselu"}}},
      {"2D damped cloth (non-symmetric), 2 n unknowns",
       "cloth2d",
       2,
       {{"linearized implicit Euler", "linearized-implicit-euler"},
        {"implicit Euler (Newton, 1e-9)", "implicit-euler"},
        {"old path: linearized, triplets + Eigen LU", "old-linearized"},
        {"old path: implicit Euler", "old-implicit"},
        {"Eigen SparseLU every step (LIE form)", "sparselu"}}},
  };
  std::vector<double> unknowns = {1e3, 1e4};
  if (smoke) unknowns.pop_back();
  if (!quick && !smoke) {
    unknowns.push_back(1e5);
    unknowns.push_back(1e6);
  }
  for (const Family& family : families) {
    std::printf("\n%s. Milliseconds per step (mean after the first) and peak memory (MB):\n\n",
                family.title);
    std::vector<int> sizes;
    std::printf("%-44s", "method \\ unknowns");
    for (double u : unknowns) {
      const int nx = static_cast<int>(std::lround(std::sqrt(u / family.dim)));
      sizes.push_back(nx);
      char head[32];
      std::snprintf(head, sizeof head, "%d (%dx%d)", family.dim * nx * nx, nx, nx);
      std::printf(" %22s", head);
    }
    std::printf("\n");
    for (const auto& [label, method] : family.methods) {
      std::printf("%-44s", label.c_str());
      std::fflush(stdout);
      double previous_ms = 0.0;
      for (std::size_t k = 0; k < sizes.size(); ++k) {
        // Skip sizes a method cannot finish in a few minutes (the previous size times 40).
        if (k > 0 && previous_ms * 40.0 > 240e3) {
          std::printf(" %22s", "(too slow)");
          previous_ms = 1e12;
          continue;
        }
        const Measured m =
            measure_steps(family.family, sizes[k], method, smoke ? 2 : quick ? 5 : 20,
                          quick || smoke ? 5.0 : 20.0);
        previous_ms = m.ok ? m.step_ms : 1e12;
        std::printf(" %22s", cell(m).c_str());
        std::fflush(stdout);
      }
      std::printf("\n");
    }
  }
}

double ratio(const Measured& baseline, const Measured& ours) {
  return baseline.ok && ours.ok && ours.step_ms > 0.0 ? baseline.step_ms / ours.step_ms : 0.0;
}

/// The goals of the solver work, as ratios in this run.
void goals_table(bool quick, const std::string& bunny_file) {
  std::printf("\nGoals (ratios of per-step times measured in this run):\n\n");
  std::printf("%-58s %14s %14s %8s  %s\n", "work", "FOSSSim", "baseline", "ratio", "notes");
  const auto row = [](const char* work, const Measured& ours, const Measured& base,
                      const std::string& notes) {
    std::printf("%-58s %11.2f ms %11.2f ms %7.1fx  %s\n", work, ours.step_ms, base.step_ms,
                ratio(base, ours), notes.c_str());
    std::fflush(stdout);
  };
  const int bunny_steps = quick ? 100 : 1000;
  // The CSC417 a2 bunny case: linearly implicit Euler against a complete student solution
  // (student-lie), on the stand-in and, with --bunny FILE, on the real mesh.
  std::vector<std::pair<std::string, std::string>> bunnies = {
      {"bunny", "bunny stand-in (672 v., 5-tet box), LIE vs student a2"}};
  if (!bunny_file.empty()) {
    bunnies.emplace_back("medit:" + bunny_file, "the CSC417 coarse bunny (--bunny), LIE vs student a2");
  }
  for (const auto& [family, title] : bunnies) {
    const std::string ours_file = "/tmp/fosssim-bench-bunny-ours.bin";
    const std::string base_file = "/tmp/fosssim-bench-bunny-student.bin";
    const Measured ours =
        measure_steps(family, 0, "linearly-implicit-euler", bunny_steps, 1e9, ours_file);
    // The baseline twice: under glibc's allocator defaults, as a student's program runs, and
    // with freed memory kept, its best case (keep_freed_memory).
    for (const bool kept : {false, true}) {
      const std::string method = kept ? "student-lie" + std::string(kKeptHeapSuffix) : "student-lie";
      const Measured base = measure_steps(family, 0, method, bunny_steps, 1e9, base_file);
      const double deviation = largest_difference(ours_file, base_file);
      char notes[200];
      std::snprintf(notes, sizeof notes,
                    "%d steps; CPU time %.2f against %.2f ms (%.1fx); positions agree to %.1e units",
                    bunny_steps, ours.cpu_step_ms, base.cpu_step_ms,
                    ours.cpu_step_ms > 0.0 ? base.cpu_step_ms / ours.cpu_step_ms : 0.0, deviation);
      const std::string work = kept ? "  the same, the student's freed memory kept" : title;
      row(work.c_str(), ours, base, notes);
    }
  }
  {
    const Measured ours = measure_steps("cloth3d", 81, "linearly-implicit-euler", 30, 30.0);
    const Measured base = measure_steps("cloth3d", 81, "levin", quick ? 3 : 10, 30.0);
    row("81x81 cloth, linearly implicit Euler vs Levin's recipe", ours, base, "");
  }
  {
    const std::string ours_file = "/tmp/fosssim-bench-flag-ours.bin";
    const std::string base_file = "/tmp/fosssim-bench-flag-student.bin";
    const int steps = quick ? 20 : 100;
    const Measured ours = measure_steps("flag", 80, "local-global", steps, 1e9, ours_file);
    const Measured base = measure_steps("flag", 80, "student-lg", steps, 1e9, base_file);
    const double deviation = largest_difference(ours_file, base_file);
    char notes[160];
    std::snprintf(notes, sizeof notes, "%d steps; positions agree to %.1e m", steps + 1, deviation);
    row("flag 80x40, 50 local/global iterations vs SimplicialLLT", ours, base, notes);
  }
  {
    const Measured ours = measure_steps("cloth2d", 30, "linearized-implicit-euler", 200, 10.0);
    const Measured base = measure_steps("cloth2d", 30, "dense-lu", 3, 30.0);
    row("2D damped cloth 30x30, linearized vs dense LU (course's way)", ours, base,
        "the course's program itself: 3.0 s/step (issue 11)");
  }
  if (!quick) {
    const Measured small = measure_steps("cloth2d", 100, "linearized-implicit-euler", 50, 20.0);
    const Measured large = measure_steps("cloth2d", 316, "linearized-implicit-euler", 20, 60.0);
    char notes[160];
    std::snprintf(notes, sizeof notes, "316x316 peak memory %.0f MB (100x100: %.0f MB)",
                  large.peak_mb, small.peak_mb);
    std::printf("%-58s %11.2f ms %11.2f ms %7.1fx  %s\n",
                "2D damped cloth 316x316 over 100x100 (10x particles)", large.step_ms,
                small.step_ms, large.step_ms / small.step_ms, notes);
  }
}

}  // namespace
}  // namespace fosssim::bench

int main(int argc, char** argv) {
  using namespace fosssim::bench;
  self_path = "/proc/self/exe";
  char resolved[4096];
  const ssize_t length = readlink("/proc/self/exe", resolved, sizeof resolved - 1);
  if (length > 0) self_path.assign(resolved, static_cast<std::size_t>(length));
  if (argc >= 2 && std::strcmp(argv[1], "--accuracy-case") == 0) {
    fosssim::return_large_blocks_to_system();  // as the FOSSSim program does
    return run_accuracy_case();
  }
  if (argc >= 2 && std::strcmp(argv[1], "--case") == 0) {
    if (argc < 8) {
      std::fprintf(stderr, "bench_implicit --case: too few arguments\n");
      return 2;
    }
    std::vector<std::pair<std::string, std::string>> options;
    for (int k = 8; k < argc; ++k) {
      const std::string option = argv[k];
      const auto equals = option.find('=');
      options.emplace_back(option.substr(0, equals), option.substr(equals + 1));
    }
    return run_case(argv[2], std::atoi(argv[3]), argv[4], std::atoi(argv[5]), std::atof(argv[6]),
                    std::strcmp(argv[7], "-") == 0 ? "" : argv[7], options);
  }
  if (std::getenv("FOSSSIM_BENCH_CHILD") != nullptr) {
    std::fprintf(stderr, "bench_implicit: a measured child must be started with --case\n");
    return 2;
  }
  setenv("FOSSSIM_BENCH_CHILD", "1", 1);  // the children inherit it
  bool quick = false, smoke = false;
  std::string bunny_file;
  std::vector<std::string> tables;
  const char* usage =
      "Usage: bench_implicit [--quick | --smoke] [--bunny FILE.mesh]\n"
      "                      [--table goals|accuracy|scaling]...\n"
      "  Prints the tables of docs/solvers.md: the goal ratios, error against time on the\n"
      "  81x81 cloth, and per-step time and peak memory from 10^3 to 10^6 unknowns (all three\n"
      "  by default; about an hour on 2 cores). --quick: small sizes and fewer steps only.\n"
      "  --smoke: the scaling table alone at 10^3 unknowns, 2 steps each (to see that it runs).\n"
      "  --bunny: also measure the goals' bunny case on this MEDIT mesh (the CSC417 coarse\n"
      "  bunny, which the repository does not hold). Run it on a quiet machine: every\n"
      "  measurement is a process of its own, with one BLAS thread (FOSSSim's default,\n"
      "  --threads 1), set before OpenBLAS starts whatever the environment says.\n";
  for (int k = 1; k < argc; ++k) {
    const std::string argument = argv[k];
    if (argument == "--help" || argument == "-h") {
      std::fputs(usage, stdout);
      return 0;
    }
    if (argument == "--quick") {
      quick = true;
    } else if (argument == "--smoke") {
      smoke = true;
    } else if (argument == "--bunny" && k + 1 < argc) {
      bunny_file = argv[++k];
    } else if (argument == "--table" && k + 1 < argc &&
               (std::strcmp(argv[k + 1], "goals") == 0 ||
                std::strcmp(argv[k + 1], "accuracy") == 0 ||
                std::strcmp(argv[k + 1], "scaling") == 0)) {
      tables.emplace_back(argv[++k]);
    } else {
      std::fprintf(stderr, "bench_implicit: unknown argument '%s'\n%s", argv[k], usage);
      return 2;
    }
  }
  if (tables.empty()) tables = smoke ? std::vector<std::string>{"scaling"}
                                     : std::vector<std::string>{"goals", "accuracy", "scaling"};
  std::printf("FOSSSim implicit-solver benchmark. Load average at start: %s\n",
              load_average().c_str());
  for (const std::string& table : tables) {
    if (table == "scaling") scaling_table(quick, smoke);
    if (table == "goals") goals_table(quick, bunny_file);
    if (table == "accuracy") std::fputs(measure({"--accuracy-case"}).output.c_str(), stdout);
  }
  std::printf("\nLoad average at end: %s\n", load_average().c_str());
  return 0;
}
