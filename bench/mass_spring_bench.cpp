// Times the 3D mass-spring integrators on flat cloths held at two corners and prints tables:
// milliseconds per step of the local/global solver (10 iterations) and of linearly implicit
// Euler, beside a baseline that assembles the implicit step matrix and factors it from
// scratch with Eigen's SimplicialLDLT every step; then the cost of spring forces as one
// SpringSetForce versus one SpringForce per spring, and of the local/global global solve with
// our sweeps versus Eigen's and CHOLMOD's. Ratios are against baselines run in the same
// process. Usage: bench_mass_springs [--quick | --smoke]   (--quick skips the 10^5-vertex cloth;
// --smoke runs the 32 x 32 cloth alone, to show that the program runs)

#include <Eigen/SparseCholesky>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <string>

#include "bench_clock.h"
#include "core/force_evaluation.h"
#include "core/forces/simple_gravity_force.h"
#include "core/forces/spring_force.h"
#include "core/forces/spring_set_force.h"
#include "core/integrators/linearly_implicit_euler.h"
#include "core/integrators/local_global.h"
#include "core/solvers/spd_solver.h"
#include "core/systems/local_global_system.h"
#include "core/systems/step_matrix.h"
#include "mesh/generators.h"
#include "mesh/mesh_scene.h"

#ifdef FOSSSIM_BENCH_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

namespace {

using namespace fosssim;
using bench::Clock;
using bench::load_average;
using bench::milliseconds_since;

constexpr double kTimeStep = 1.0 / 30.0;

/// The paper's setting at any resolution: a flat 1 m cloth of nx × nx vertices, 1 kg, springs
/// of 1000 N/m (structural, shear, bend), held at two corners, gravity, h = 1/30 s.
Scene make_cloth(int nx, const char* integrator) {
  Scene scene;
  scene.model.dim = 3;
  scene.model.integrator.use(integrator_method(integrator));
  scene.model.integrator.dt = kTimeStep;
  if (scene.model.integrator.options.has("iterations")) {
    scene.model.integrator.options.set("iterations", 10);
  }
  GeneratedMesh cloth = generate_cloth(nx, nx, 1.0, 1.0, true, true);
  MeshMaterial material;
  material.k = 1000.0;
  material.mass = {MassRule::kTotal, 1.0};
  scene.model.forces.push_back(
      append_mesh(scene, cloth.mesh, material, *cloth.find_pins("corners"), "cloth"));
  scene.model.forces.push_back(std::make_unique<SimpleGravityForce<3>>(Vec<3>(0.0, -9.8, 0.0)));
  return scene;
}

/// The baseline: linearly implicit Euler with the course's identity rows for fixed particles
/// (StepMatrix) and a SimplicialLDLT analysed and factored from scratch every step.
class LdltEveryStep final : public Integrator {
 protected:
  void prepare() override { matrix_.emplace(forces(), FixedParticleRule::kIdentityRows); }
  void advance(State& state) override {
    const double h = model().integrator.dt;
    Vector rhs = h * compute_force(forces(), state.q, state.v);
    const SparseMatrix& A = matrix_->assemble(state.q, state.v, h, &state.v, &rhs);
    Eigen::SimplicialLDLT<SparseMatrix> ldlt(A);
    matrix_->add_solution(ldlt.solve(matrix_->restrict(rhs)), state.v);
    state.q += h * state.v;
  }

 private:
  std::optional<StepMatrix> matrix_;
};

/// The springs of a cloth made by make_cloth (its first force).
std::vector<SpringTerm> cloth_springs(const Scene& scene) {
  return dynamic_cast<const SpringSetForce<3>&>(*scene.model.forces[0]).springs();
}

struct StepTiming {
  double first_ms = 0.0;  ///< precompute and the first step
  double step_ms = 0.0;   ///< mean of the following steps
};

/// Binds `integrator` to the scene's model and times its steps.
StepTiming time_steps(Integrator& integrator, const Scene& scene, int steps) {
  State state = scene.initial;
  StepTiming timing;
  auto start = Clock::now();
  integrator.precompute(scene.model);
  integrator.step(state);
  timing.first_ms = milliseconds_since(start);
  start = Clock::now();
  for (int k = 0; k < steps; ++k) integrator.step(state);
  timing.step_ms = milliseconds_since(start) / steps;
  if (!state.q.allFinite()) std::printf("  (warning: the state became non-finite)\n");
  return timing;
}

void integrator_table(const std::vector<int>& sizes) {
  std::printf(
      "\nMilliseconds per step (mean over the steps after the first; the first step, with all\n"
      "precomputation, in parentheses). LG-10: local/global, 10 iterations, sparse, pins\n"
      "eliminated. LIE: linearly implicit Euler (free DOFs only, LDL^T reusing its analysis).\n"
      "Baseline: compat-eliminated step matrix, SimplicialLDLT analysed and factored every "
      "step.\n\n");
  std::printf("%9s %9s %20s %20s %20s %11s %11s\n", "vertices", "springs", "LG-10", "LIE",
              "LDLT baseline", "base/LG-10", "base/LIE");
  for (int nx : sizes) {
    const Scene lg_scene = make_cloth(nx, "local-global");
    const Scene lie_scene = make_cloth(nx, "linearly-implicit-euler");
    const int n = lg_scene.model.num_particles();
    const int steps = n <= 2000 ? 30 : (n <= 20000 ? 10 : 2);
    LocalGlobal<3> lg(local_global_settings(lg_scene.model.integrator.options));
    LinearlyImplicitEuler lie(/*project_hessian=*/false);
    LdltEveryStep baseline;
    const StepTiming t_lg = time_steps(lg, lg_scene, n <= 20000 ? 3 * steps : 5);
    const StepTiming t_lie = time_steps(lie, lie_scene, steps);
    const StepTiming t_base = time_steps(baseline, lie_scene, steps);
    char lg_text[32], lie_text[32], base_text[32];
    std::snprintf(lg_text, sizeof lg_text, "%.2f (%.0f)", t_lg.step_ms, t_lg.first_ms);
    std::snprintf(lie_text, sizeof lie_text, "%.1f (%.0f)", t_lie.step_ms, t_lie.first_ms);
    std::snprintf(base_text, sizeof base_text, "%.1f (%.0f)", t_base.step_ms, t_base.first_ms);
    std::printf("%9d %9zu %20s %20s %20s %11.1f %11.2f\n", n, lg_scene.model.edges.size(), lg_text,
                lie_text, base_text, t_base.step_ms / t_lg.step_ms, t_base.step_ms / t_lie.step_ms);
    std::fflush(stdout);
  }
}

void spring_force_table(const std::vector<int>& sizes) {
  std::printf(
      "\nSpring forces: one SpringSetForce against one SpringForce object per spring (same\n"
      "math), milliseconds per gradient and per hessX (adding the triplets; building the sparse\n"
      "matrix from them costs the same for both).\n\n");
  std::printf("%9s %9s %12s %12s %8s %12s %12s %8s\n", "vertices", "springs", "grad set",
              "grad each", "ratio", "hessX set", "hessX each", "ratio");
  for (int nx : sizes) {
    const Scene scene = make_cloth(nx, "implicit-euler");
    const std::vector<SpringTerm> springs = cloth_springs(scene);
    const SpringSetForce<3> set(springs, "set");
    std::vector<std::unique_ptr<Force>> each;
    for (const SpringTerm& s : springs)
      each.push_back(std::make_unique<SpringForce<3>>(s.i, s.j, s.k, s.l0, s.b));
    const int n = scene.model.num_dofs();
    Vector q = scene.initial.q + 0.01 * Vector::Random(n);
    const Vector v = Vector::Zero(n);
    const ForceInput in{q, v, scene.model.mass};
    const int repeats = std::max(3, 3000000 / static_cast<int>(springs.size()));
    const auto time = [&](auto&& work) {
      work();  // warm-up: allocations and caches
      auto start = Clock::now();
      for (int r = 0; r < repeats; ++r) work();
      return milliseconds_since(start) / repeats;
    };
    Vector gradient(n);
    const double grad_set = time([&] {
      gradient.setZero();
      set.add_gradient(in, gradient);
    });
    const double grad_each = time([&] {
      gradient.setZero();
      for (const auto& f : each) f->add_gradient(in, gradient);
    });
    HessianBuilder builder;
    const int hessian_repeats = std::max(3, repeats / 5);
    const auto time_hessian = [&](auto&& add) {
      builder.clear();
      add();  // warm-up: the triplet list's capacity
      auto start = Clock::now();
      for (int r = 0; r < hessian_repeats; ++r) {
        builder.clear();
        add();
      }
      return milliseconds_since(start) / hessian_repeats;
    };
    const double hess_set = time_hessian([&] { set.add_hessian_x(in, builder); });
    const double hess_each = time_hessian([&] {
      for (const auto& f : each) f->add_hessian_x(in, builder);
    });
    std::printf("%9d %9zu %12.3f %12.3f %8.2f %12.1f %12.1f %8.2f\n", n / 3, springs.size(),
                grad_set, grad_each, grad_each / grad_set, hess_set, hess_each,
                hess_each / hess_set);
    std::fflush(stdout);
  }
}

/// Q = M/h² + Aᵀ K A over the free particles of a cloth, as the local/global solver builds it.
SparseMatrix local_global_matrix(const Scene& scene) {
  const SceneModel& model = scene.model;
  return assemble_local_global_matrix(model.mass, FreeDofs(model.fixed, 3), cloth_springs(scene),
                                      {}, model.integrator.dt);
}

template <typename Solve>
double time_solves(int repeats, Solve solve) {
  auto start = Clock::now();
  for (int r = 0; r < repeats; ++r) solve();
  return milliseconds_since(start) / repeats;
}

void global_solve_table(const std::vector<int>& sizes) {
  std::printf(
      "\nThe local/global global step: factor Q once, then solve for the x, y, z columns.\n"
      "Milliseconds to factor (analysis + numeric) and per 3-column solve; ratio: Eigen's\n"
      "SimplicialLLT solve over our sweeps of its factor.\n\n");
  std::printf("%9s %12s %12s %12s %12s %8s", "vertices", "nnz(L)", "factor", "ours", "Eigen",
              "ratio");
#ifdef FOSSSIM_BENCH_CHOLMOD
  std::printf(" %14s %14s %14s", "CHOLMOD simpl.", "CHOLMOD super.", "super. factor");
#endif
  std::printf("\n");
  for (int nx : sizes) {
    const SparseMatrix Q = local_global_matrix(make_cloth(nx, "local-global"));
    const int n = static_cast<int>(Q.rows());
    const Points<3> B = Points<3>::Random(n, 3);
    const int repeats = std::max(3, 20000000 / n / 20);
    SpdSolver ours;
    auto start = Clock::now();
    ours.factor(Q, SpdSolver::Method::kSparse);
    const double factor_ms = milliseconds_since(start);
    Points<3> X = B;
    const double ours_ms = time_solves(repeats, [&] {
      X = B;
      ours.solve_in_place<3>(X);
    });
    Eigen::SimplicialLLT<SparseMatrix> eigen(Q);
    Eigen::MatrixX3d Y;
    const Eigen::MatrixX3d Bc = B;
    const double eigen_ms = time_solves(repeats, [&] { Y = eigen.solve(Bc); });
    std::printf("%9d %12ld %12.1f %12.3f %12.3f %8.2f", n, ours.factor_nonzeros(), factor_ms,
                ours_ms, eigen_ms, eigen_ms / ours_ms);
#ifdef FOSSSIM_BENCH_CHOLMOD
    Eigen::CholmodSimplicialLLT<SparseMatrix> simplicial(Q);
    const double simplicial_ms = time_solves(repeats, [&] { Y = simplicial.solve(Bc); });
    start = Clock::now();
    Eigen::CholmodSupernodalLLT<SparseMatrix> supernodal(Q);
    const double supernodal_factor_ms = milliseconds_since(start);
    const double supernodal_ms = time_solves(repeats, [&] { Y = supernodal.solve(Bc); });
    std::printf(" %14.3f %14.3f %14.1f", simplicial_ms, supernodal_ms, supernodal_factor_ms);
#endif
    std::printf("\n");
    std::fflush(stdout);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc == 2 && std::strcmp(argv[1], "--quick") == 0;
  const bool smoke = argc == 2 && std::strcmp(argv[1], "--smoke") == 0;
  if (argc > 1 && !quick && !smoke) {
    const bool help = std::strcmp(argv[1], "--help") == 0;
    std::fputs(
        "Usage: bench_mass_springs [--quick | --smoke]\n"
        "  The 3D mass-spring integrators, spring forces and global solves on cloths of 32^2,\n"
        "  81^2, 100^2 and 316^2 vertices. --quick: without the 316^2 cloth. --smoke: the 32^2\n"
        "  cloth alone (to see that it runs).\n",
        help ? stdout : stderr);
    return help ? 0 : 2;
  }
  std::vector<int> sizes = {32, 81, 100};  // 1,024, 6,561 (the paper's cloth), 10,000 vertices
  if (!quick && !smoke) sizes.push_back(316);  // 99,856 vertices
  if (smoke) sizes = {32};
  std::printf(
      "FOSSSim mass-spring benchmark: flat 1 m cloths of nx x nx vertices held at two\n"
      "corners, 1 kg, structural + shear + bend springs of 1000 N/m, gravity, h = 1/30 s.\n"
      "Load average at start: %s\n",
      load_average().c_str());
  integrator_table(sizes);
  spring_force_table(sizes);
  global_solve_table(sizes);
  std::printf("\nLoad average at end: %s\n", load_average().c_str());
  return 0;
}
