// Elastic sheets and 2D cloth under implicit Euler at 10² to 10⁵ elements: time per step of
// FOSSSim's solver paths against a dense baseline (the course's way), and the growth per 10×
// elements (issue 19, "Speed"; docs/solvers.md, "Elastic sheets"). Not a test: a table of
// ratios measured in one process. Times are this thread's CPU time (bench_clock.h): steadier
// than wall time on the shared 2-core machine, and every solver runs on this thread (BLAS and
// OpenMP are set to one thread).
//
// Usage: bench_elastic [--quick] [--profile-amg] [--steps N] [--dense-max-unknowns N] [--solvers a,b,...]
//                      [--cloths N,N,...] [--cloth-only]
//   --quick                sheets of 10² to 10⁴ triangles, no cloth
//   --cloths LIST          the cloths' sizes, N×N particles each (100,316)
//   --cloth-only           the cloths only, no sheets
//   --profile-amg          only BoomerAMG's setup, V-cycle and CG times on the sheets
//   --steps N              steps timed after the first (5)
//   --dense-max-unknowns N the largest system the dense baseline factors (12000: 1.2 GB)
//   --solvers LIST         the `solver` option values compared (auto,amg)

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "bench_clock.h"
#include "bench_scenes.h"
#include "core/force_set.h"
#include "core/integrators/implicit_euler.h"
#include "core/solvers/amg_solver.h"
#include "core/integrators/integrator.h"
#include "core/integrators/linearized_implicit_euler.h"
#include "core/solvers/memory_policy.h"
#include "core/systems/backward_euler.h"
#include "core/systems/step_matrix.h"
#include "io/scene_loader.h"

// OpenBLAS and libgomp come in through MUMPS and SuiteSparse (as in app/solver_threads.cpp).
extern "C" {
void openblas_set_num_threads(int count) __attribute__((weak));
void omp_set_num_threads(int count) __attribute__((weak));
}

namespace fosssim::bench {
namespace {

/// The sheet: a cantilever of 2 ny × ny cells (4 ny² triangles, alternating diagonals), 1 m ×
/// 0.5 m, E = 2·10⁴ N/m, ν = 0.3, 1 kg, its left side fixed, in gravity, implicit Euler at
/// h = 0.01 s. It bends down under its weight; Newton takes 2 to 4 iterations a step.
std::string sheet_scene(int ny, const std::string& solver) {
  std::ostringstream out;
  out << "<scene>\n"
      << "  <duration time=\"1\"/>\n"
      << "  <integrator type=\"implicit-euler\" dt=\"0.01\" solver=\"" << solver << "\"/>\n"
      << "  <simplegravity fx=\"0\" fy=\"-9.81\"/>\n"
      << "  <elasticbody shape=\"sheet\" nx=\"" << 2 * ny << "\" ny=\"" << ny
      << "\" width=\"1\" height=\"0.5\" youngsmodulus=\"2e4\" poissonratio=\"0.3\""
      << " totalmass=\"1\" fix=\"left\"/>\n"
      << "</scene>\n";
  return out.str();
}

/// Implicit Euler as the course's program solves it: Newton to 1e-9 on the same residual,
/// every iteration a dense step matrix and a dense LU (partial pivoting here, which costs less
/// than the course's full pivoting: the baseline is generous).
class DenseNewton final : public Integrator {
 public:
  int iterations() const { return iterations_; }

 protected:
  void prepare() override { matrix_.emplace(forces(), FixedParticleRule::kIdentityRows); }
  void advance(State& state) override {
    const double h = model().integrator.dt;
    const BackwardEulerStep problem{forces(), state, h};
    Vector dv = Vector::Zero(state.v.size());
    Vector rhs = problem.residual(dv);
    for (int iteration = 0; iteration < 100; ++iteration) {
      const Vector v = state.v + dv;
      const Eigen::MatrixXd A(matrix_->assemble_from_triplets(state.q + h * v, v, h));
      const Vector delta = A.partialPivLu().solve(rhs);
      ++iterations_;
      dv += delta;
      if (delta.norm() < 1e-9) break;
      rhs = problem.residual(dv);
    }
    state.q += h * (state.v + dv);
    state.v += dv;
  }

 private:
  std::optional<StepMatrix> matrix_;
  int iterations_ = 0;
};

struct Timing {
  double first_ms = 0.0;     // precompute and the first step
  double step_ms = 0.0;      // mean of the timed steps
  double iterations = 0.0;   // Newton iterations per timed step (0: not Newton)
  double krylov = 0.0;       // Krylov iterations per timed step
  std::int64_t fallbacks = 0;
  std::string path;          // what solved the last system
  Vector q;                  // the final positions
};

const StepSolver* solver_of(const Integrator& integrator) {
  if (const auto* i = dynamic_cast<const ImplicitEuler*>(&integrator)) return &i->solver();
  if (const auto* i = dynamic_cast<const LinearizedImplicitEuler*>(&integrator)) {
    return &i->solver();
  }
  return nullptr;
}

const char* path_name(Factorization f) {
  switch (f) {
    case Factorization::kLDLT: return "Eigen LDLT";
    case Factorization::kLU: return "Eigen LU";
    case Factorization::kCholesky: return "GMRES+CHOLMOD";
    case Factorization::kUmfpack: return "GMRES+UMFPACK";
    case Factorization::kMumps: return "GMRES+MUMPS";
    case Factorization::kAmgCg: return "CG+BoomerAMG";
    case Factorization::kAmgGmres: return "GMRES+BoomerAMG";
  }
  return "?";
}

/// Precompute and one step, then `steps` timed steps.
Timing time_steps(const Scene& scene, Integrator& integrator, int steps) {
  Timing t;
  State state = scene.initial;
  double start = thread_cpu_milliseconds();
  integrator.precompute(scene.model);
  integrator.step(state);
  t.first_ms = thread_cpu_milliseconds() - start;
  const StepSolver* solver = solver_of(integrator);
  const SolveStatistics before = solver ? solver->statistics() : SolveStatistics{};
  const auto* implicit = dynamic_cast<const ImplicitEuler*>(&integrator);
  const auto* dense = dynamic_cast<const DenseNewton*>(&integrator);
  const int dense_before = dense ? dense->iterations() : 0;
  int newton = 0;
  start = thread_cpu_milliseconds();
  for (int k = 0; k < steps; ++k) {
    integrator.step(state);
    if (implicit) newton += implicit->last_iterations();
  }
  t.step_ms = (thread_cpu_milliseconds() - start) / steps;
  if (dense) newton = dense->iterations() - dense_before;
  t.iterations = static_cast<double>(newton) / steps;
  if (solver) {
    t.krylov = static_cast<double>(solver->statistics().krylov_iterations - before.krylov_iterations) /
               steps;
    t.fallbacks = solver->statistics().direct_fallbacks + solver->statistics().amg_failures;
    t.path = path_name(solver->last_factorization());
  } else {
    t.path = "dense LU";
  }
  t.q = state.q;
  return t;
}

Timing run_fosssim(const Scene& scene, int steps) {
  auto integrator =
      scene.model.integrator.method->create(scene.model.integrator.options, scene.model.dim);
  return time_steps(scene, *integrator, steps);
}

/// One dense Newton iteration's cost (assembly, LU, solve) at this scene's first state.
double dense_iteration_ms(const Scene& scene) {
  const ForceSet forces(scene.model);
  StepMatrix matrix(forces, FixedParticleRule::kIdentityRows);
  const double h = scene.model.integrator.dt;
  const State& s = scene.initial;
  const Vector b = Vector::Ones(s.v.size());
  const double start = thread_cpu_milliseconds();
  const Eigen::MatrixXd A(matrix.assemble_from_triplets(s.q + h * s.v, s.v, h));
  const Vector x = A.partialPivLu().solve(b);
  const double ms = thread_cpu_milliseconds() - start;
  if (!x.allFinite()) std::printf("  (dense LU: non-finite answer)\n");
  return ms;
}

struct Options {
  bool quick = false;
  bool profile = false;  // --profile-amg: only where multigrid's time goes
  int steps = 5;
  long dense_max_unknowns = 12000;
  long dense_full_max_unknowns = 3000;  // above: one iteration timed, times FOSSSim's count
  std::vector<std::string> solvers = {"auto", "amg"};
  std::vector<int> cloth_sizes = {100, 316};
  bool cloth_only = false;
};

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> parts;
  std::stringstream in(list);
  for (std::string part; std::getline(in, part, ',');) parts.push_back(part);
  return parts;
}

double growth_per_10x(double t0, double t1, double n0, double n1) {
  return std::pow(t1 / t0, 1.0 / std::log10(n1 / n0));
}

void sheets(const Options& options) {
  std::vector<int> rows = {5, 16, 50, 158};  // 100, 1024, 10000, 99856 triangles
  if (options.quick) rows.pop_back();
  std::printf("\nCST sheet (cantilever, E = 2e4, nu = 0.3, h = 0.01), implicit-euler, ms per step "
              "(thread CPU), mean of %d steps after the first\n\n",
              options.steps);
  std::printf("| triangles | unknowns | solver | path | Newton it/step | Krylov it/step | first "
              "step ms | ms/step | dense ms/step | dense / this |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<std::vector<double>> times(options.solvers.size());
  std::vector<double> triangles;
  for (const int ny : rows) {
    const int tri = 4 * ny * ny;
    triangles.push_back(tri);
    std::optional<double> dense_ms;
    std::string dense_note;
    Vector reference;
    for (std::size_t s = 0; s < options.solvers.size(); ++s) {
      const Scene scene = load_scene_text(sheet_scene(ny, options.solvers[s]), "sheet");
      const long unknowns = scene.model.num_dofs();
      const Timing t = run_fosssim(scene, options.steps);
      times[s].push_back(t.step_ms);
      if (s == 0) {
        reference = t.q;
        if (unknowns <= std::min(options.dense_full_max_unknowns, options.dense_max_unknowns)) {
          DenseNewton dense;
          const Timing d = time_steps(scene, dense, options.steps);
          dense_ms = d.step_ms;
          dense_note = "";
          const double gap = (d.q - t.q).norm() / t.q.norm();
          if (gap > 1e-8) std::printf("  (dense and FOSSSim differ by %.1e relative)\n", gap);
        } else if (unknowns <= options.dense_max_unknowns) {
          dense_ms = dense_iteration_ms(scene) * std::max(1.0, t.iterations);
          dense_note = " (one LU timed × Newton it.)";
        }
      }
      const double gap = reference.size() == t.q.size() && s > 0
                             ? (t.q - reference).norm() / reference.norm()
                             : 0.0;
      std::printf("| %d | %ld | %s | %s | %.1f | %.1f | %.1f | %.2f | %s%s | %s |\n", tri,
                  unknowns, options.solvers[s].c_str(), t.path.c_str(), t.iterations, t.krylov,
                  t.first_ms, t.step_ms,
                  dense_ms ? std::to_string(static_cast<long>(std::lround(*dense_ms))).c_str()
                  : 8.0 * static_cast<double>(unknowns) * static_cast<double>(unknowns) > 16e9
                      ? "does not fit (over 16 GB)"
                      : "not run (--dense-max-unknowns)",
                  dense_ms ? dense_note.c_str() : "",
                  dense_ms ? (std::to_string(std::lround(*dense_ms / t.step_ms)) + "×").c_str()
                           : "");
      if (s > 0) std::printf("  (positions vs %s: %.1e relative)\n", options.solvers[0].c_str(), gap);
      if (t.fallbacks > 0) std::printf("  (%lld fallbacks)\n", static_cast<long long>(t.fallbacks));
      std::fflush(stdout);
    }
  }
  std::printf("\nGrowth of the time per step for 10× the triangles:\n\n| solver |");
  for (std::size_t k = 1; k < triangles.size(); ++k)
    std::printf(" %.0f → %.0f |", triangles[k - 1], triangles[k]);
  std::printf("\n|---|");
  for (std::size_t k = 1; k < triangles.size(); ++k) std::printf("---|");
  std::printf("\n");
  for (std::size_t s = 0; s < options.solvers.size(); ++s) {
    std::printf("| %s |", options.solvers[s].c_str());
    for (std::size_t k = 1; k < triangles.size(); ++k) {
      std::printf(" %.1f× |",
                  growth_per_10x(times[s][k - 1], times[s][k], triangles[k - 1], triangles[k]));
    }
    std::printf("\n");
  }
}

/// Where multigrid's time goes on the sheets' first step matrices: one BoomerAMG setup, one
/// V-cycle, one CG solve to 1e-12, each timed (thread CPU), in V-cycles.
void amg_profile(const Options& options) {
  std::printf("\nBoomerAMG on the sheet's first step matrix (thread CPU ms)\n\n"
              "| triangles | unknowns | setup | V-cycle | setup / V-cycle | CG iterations | CG "
              "solve |\n|---|---|---|---|---|---|---|\n");
  for (const int ny : {16, 50, 158}) {
    if (options.quick && ny > 50) break;
    const Scene scene = load_scene_text(sheet_scene(ny, "amg"), "sheet");
    const ForceSet forces(scene.model);
    StepMatrix matrix(forces, FixedParticleRule::kIdentityRows);
    const double h = scene.model.integrator.dt;
    const State& s = scene.initial;
    const SparseMatrix& A = matrix.assemble(s.q + h * s.v, s.v, h);
    const Vector b = A * Vector::Ones(A.rows());
    AmgSolver amg;
    double start = thread_cpu_milliseconds();
    if (!amg.setup(A, 2)) {
      std::printf("(no hypre)\n");
      return;
    }
    const double setup = thread_cpu_milliseconds() - start;
    Vector z(b.size());
    start = thread_cpu_milliseconds();
    for (int k = 0; k < 10; ++k) amg.apply(b.data(), z.data());
    const double cycle = (thread_cpu_milliseconds() - start) / 10;
    Vector x = Vector::Zero(b.size());
    start = thread_cpu_milliseconds();
    const KrylovResult r = amg.conjugate_gradients(b, x, 1e-12, 200);
    const double cg = thread_cpu_milliseconds() - start;
    std::printf("| %d | %ld | %.1f | %.2f | %.1f | %d | %.1f |\n", 4 * ny * ny,
                static_cast<long>(A.rows()), setup, cycle, setup / cycle, r.iterations, cg);
    std::fflush(stdout);
  }
}

void cloths(const Options& options) {
  std::printf("\n2D damped cloth (bench_implicit's), linearized-implicit-euler, ms per step "
              "(thread CPU), mean of %d steps after the first\n\n",
              options.steps);
  std::printf("| cloth | unknowns | solver | path | Krylov it/step | ms/step |\n|---|---|---|---|---|---|\n");
  std::vector<std::vector<double>> times(options.solvers.size());
  const std::vector<int>& sizes = options.cloth_sizes;
  for (const int nx : sizes) {
    for (std::size_t s = 0; s < options.solvers.size(); ++s) {
      Scene scene = damped_cloth_2d(nx, "linearized-implicit-euler");
      set_option(scene, "solver", options.solvers[s]);
      const Timing t = run_fosssim(scene, options.steps);
      times[s].push_back(t.step_ms);
      std::printf("| %d×%d | %d | %s | %s | %.1f | %.2f |\n", nx, nx, scene.model.num_dofs(),
                  options.solvers[s].c_str(), t.path.c_str(), t.krylov, t.step_ms);
      std::fflush(stdout);
    }
  }
  if (sizes.size() < 2) return;
  // Growth per 10× the particles between successive sizes and from the first to the last.
  std::printf("\n| solver |");
  for (std::size_t k = 1; k < sizes.size(); ++k) std::printf(" %d² → %d² |", sizes[k - 1], sizes[k]);
  std::printf(" %d² → %d² |\n|---|", sizes.front(), sizes.back());
  for (std::size_t k = 0; k < sizes.size(); ++k) std::printf("---|");
  std::printf("\n");
  const auto particles = [](int nx) { return static_cast<double>(nx) * nx; };
  for (std::size_t s = 0; s < options.solvers.size(); ++s) {
    std::printf("| %s per 10× particles |", options.solvers[s].c_str());
    for (std::size_t k = 1; k < sizes.size(); ++k)
      std::printf(" %.1f× |", growth_per_10x(times[s][k - 1], times[s][k], particles(sizes[k - 1]),
                                               particles(sizes[k])));
    std::printf(" %.1f× |\n", growth_per_10x(times[s].front(), times[s].back(),
                                              particles(sizes.front()), particles(sizes.back())));
  }
}

}  // namespace
}  // namespace fosssim::bench

int main(int argc, char** argv) {
  using namespace fosssim::bench;
  fosssim::return_large_blocks_to_system();
  if (openblas_set_num_threads != nullptr) openblas_set_num_threads(1);
  if (omp_set_num_threads != nullptr) omp_set_num_threads(1);
  Eigen::setNbThreads(1);
  Options options;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--quick") {
      options.quick = true;
    } else if (arg == "--profile-amg") {
      options.profile = true;
    } else if (arg == "--steps" && k + 1 < argc) {
      options.steps = std::max(1, std::atoi(argv[++k]));
    } else if (arg == "--dense-max-unknowns" && k + 1 < argc) {
      options.dense_max_unknowns = std::atol(argv[++k]);
    } else if (arg == "--solvers" && k + 1 < argc) {
      options.solvers = split(argv[++k]);
    } else if (arg == "--cloths" && k + 1 < argc) {
      options.cloth_sizes.clear();
      for (const std::string& size : split(argv[++k]))
        options.cloth_sizes.push_back(std::clamp(std::atoi(size.c_str()), 2, 2000));
    } else if (arg == "--cloth-only") {
      options.cloth_only = true;
    } else {
      const bool help = arg == "--help";
      std::fputs(
          "usage: bench_elastic [--quick] [--profile-amg] [--steps N] [--dense-max-unknowns N]\n"
          "                     [--solvers auto,amg,...] [--cloths N,N,...] [--cloth-only]\n"
          "  (the quickest run: --quick --steps 1 --dense-max-unknowns 1200)\n",
          help ? stdout : stderr);
      return help ? 0 : 2;
    }
  }
  std::printf("bench_elastic: load average %s; one thread (BLAS, OpenMP, Eigen)\n",
              load_average().c_str());
  try {
    if (options.profile) {
      amg_profile(options);
      return 0;
    }
    if (!options.cloth_only) sheets(options);
    if (!options.quick || options.cloth_only) cloths(options);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "bench_elastic: %s\n", error.what());
    return 1;
  }
  return 0;
}
