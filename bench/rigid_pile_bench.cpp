// Rigid bodies at scale: the time per step of a pile of 10², 10³ and 10⁴ polygons falling into
// a box, a real simulation (gravity, symplectic Euler, the contact stage of each response
// method), with the broad phase and against all-pairs detection, and the scaling per 10× bodies
// (docs/rigid-bodies.md, "Speed"). Timings are thread CPU milliseconds per step.
//
//   bench_rigid_pile [--sizes 100,1000,10000] [--steps S] [--all-pairs-steps K] [--methods M]...
//
// (--methods NAME, repeatable, runs only those responses; "all-pairs" adds the all-pairs run,
// which continues lcp's.) The default S = 60 covers the pile landing, every body in contact,
// groups small; by S = 120 a pile of 1,000 forms one group of 745 bodies, and one of 10⁴ groups
// too large for the exact solvers' dense factors (docs/rigid-bodies.md, "Speed").
//
// Each size runs S steps per response method through the scene's own step pipeline (the
// contact stage the loader would make, with its broad phase); the time per step is the mean of
// the last S/2 steps, when the pile is in contact. All-pairs detection is timed in the same run:
// from the state the lcp run ended in, K steps with a stage that detects on all pairs and then
// responds as lcp does (same records, bit for bit, so the same response); at 10⁴ bodies K is
// small, all pairs costing seconds per step.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "bench_clock.h"
#include "core/forces/rigid_body_gravity_force.h"
#include "core/integrators/integrator_registry.h"
#include "core/rigid/rigid_contact_detection.h"
#include "core/collisions/contact_registry.h"
#include "core/rigid/rigid_contact_response.h"
#include "core/scene_model.h"
#include "core/state.h"
#include "core/step/step_pipeline.h"

namespace fosssim::bench {
namespace {

constexpr double kStep = 0.005;  // h of the t3m2 scenes
constexpr int kRows = 10;        // the pile's depth: its width grows with the number of bodies
constexpr double kSpacing = 1.12;

/// One body of a pile: a polygon (points about its centre), fixed or not.
void add_body(const std::vector<Vec2>& points, double radius, bool fixed, const Vec<3>& q,
              const Vec<3>& v, RigidBodies& bodies, std::vector<double>& mass, std::vector<Vec<3>>& qs,
              std::vector<Vec<3>>& vs) {
  const std::vector<double> masses(points.size(), 1.0);
  const MassProperties mp = compute_mass_properties(points, masses);
  RigidBody body;
  for (const Vec2& p : points) body.body_points.push_back(p - mp.center);
  body.mass = mp.mass;
  body.inertia = mp.inertia;
  body.initial_center = mp.center;
  body.radius = radius;
  body.fixed = fixed;
  bodies.bodies.push_back(body);
  mass.insert(mass.end(), {mp.mass, mp.mass, mp.inertia});
  qs.push_back(q + Vec<3>(mp.center.x(), mp.center.y(), 0.0));
  vs.push_back(fixed ? Vec<3>::Zero() : v);
}

/// n polygons (3 to 6 vertices, about 1 across, radius 0.06) on a jittered grid of kRows rows
/// and n / kRows columns, at random angles, falling at about 1 m/s into a box of three fixed
/// bodies (a floor just under the lowest row and two walls), in gravity (0, −10), stepped by
/// symplectic Euler with h = 0.005 and `method`'s contact response.
std::pair<SceneModel, State> make_pile(int n, const ContactMethod& method) {
  std::mt19937 rng(20260);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int columns = (n + kRows - 1) / kRows;
  auto bodies = std::make_shared<RigidBodies>();
  std::vector<double> mass;
  std::vector<Vec<3>> qs, vs;
  for (int b = 0; b < n; ++b) {
    const int vertices = 3 + static_cast<int>(u(rng) * 4);
    std::vector<Vec2> points;
    for (int k = 0; k < vertices; ++k) {
      const double angle = -2 * std::numbers::pi * (k + 0.2 + 0.6 * u(rng)) / vertices;
      points.emplace_back(0.5 * std::cos(angle), 0.5 * std::sin(angle));
    }
    const Vec<3> q(kSpacing * (b % columns) + 0.04 * u(rng), kSpacing * (b / columns) + 0.04 * u(rng),
                   6 * u(rng));
    const Vec<3> v(0.2 * (u(rng) - 0.5), -1.0 - 0.2 * u(rng), u(rng) - 0.5);
    add_body(points, 0.06, false, q, v, *bodies, mass, qs, vs);
  }
  const double width = kSpacing * columns, height = kSpacing * (kRows + 2);
  const auto box = [](double x0, double y0, double x1, double y1) {
    return std::vector<Vec2>{{x0, y1}, {x1, y1}, {x1, y0}, {x0, y0}};  // clockwise
  };
  add_body(box(-1.5, -1.5, width + 0.5, -0.7), 0.06, true, Vec<3>::Zero(), Vec<3>::Zero(),
           *bodies, mass, qs, vs);
  add_body(box(-1.5, -0.7, -0.7, height), 0.06, true, Vec<3>::Zero(), Vec<3>::Zero(), *bodies,
           mass, qs, vs);
  add_body(box(width - 0.3, -0.7, width + 0.5, height), 0.06, true, Vec<3>::Zero(),
           Vec<3>::Zero(), *bodies, mass, qs, vs);
  bodies->contact.max_group_contacts = 1 << 30;  // the bench measures, it does not refuse

  SceneModel model;
  State state;
  const int count = bodies->size();
  model.dim = kRigidBodyCoordinates;
  model.mass = Eigen::Map<const Vector>(mass.data(), 3 * count);
  state.q.resize(3 * count);
  state.v.resize(3 * count);
  for (int b = 0; b < count; ++b) {
    state.q.segment<3>(3 * b) = qs[b];
    state.v.segment<3>(3 * b) = vs[b];
    model.fixed.push_back(bodies->bodies[b].fixed);
    model.particle_radius.push_back(bodies->bodies[b].radius);
  }
  model.rigid_bodies = std::move(bodies);
  model.collisions.method = &method;
  model.forces.push_back(std::make_unique<RigidBodyGravityForce>(Vec2(0.0, -10.0)));
  model.integrator.use(integrator_method("symplectic-euler"));
  model.integrator.dt = kStep;
  model.duration = 1e6;
  return {std::move(model), std::move(state)};
}

/// The lcp response after detection on all pairs (the course's detection): the stage the
/// pipeline makes for lcp, with detect_rigid_contacts_all_pairs in place of the broad phase.
class AllPairsLcpStage final : public StepStage {
 public:
  explicit AllPairsLcpStage(const SceneModel& model) : model_(&model) {}
  void apply(const StepContext&, State& state) override {
    const RigidBodies& bodies = *model_->rigid_bodies;
    const std::vector<RigidContact> contacts = detect_rigid_contacts_all_pairs(bodies, state.q);
    ContactReport report;
    if (!contacts.empty()) {
      apply_inelastic_response(ContactSolver::kLcp, bodies, state.q, contacts, state.v, report,
                               bodies.contact.max_group_contacts);
    }
  }

 private:
  const SceneModel* model_;
};

/// What one run measured.
struct RunTimes {
  double per_step = 0.0;  ///< ms per step over the measured steps
  int contacts = 0;       ///< contacts at the last step
  int largest_group = 0;  ///< bodies of the largest group of contacts at the last step
  std::string failure;    ///< the step's error, if one failed
  State end;              ///< the last state
};

/// The free bodies of the largest group (bodies joined by contacts, fixed ones joining none).
int largest_group(const RigidBodies& bodies, const Vector& q) {
  std::vector<int> parent(bodies.size());
  for (int b = 0; b < bodies.size(); ++b) parent[b] = b;
  const auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const RigidContact& c : detect_rigid_contacts(bodies, q)) {
    if (!bodies.bodies[c.i0].fixed && !bodies.bodies[c.i1].fixed) parent[find(c.i0)] = find(c.i1);
  }
  std::vector<int> size(bodies.size(), 0);
  int largest = 0;
  for (int b = 0; b < bodies.size(); ++b) {
    if (!bodies.bodies[b].fixed) largest = std::max(largest, ++size[find(b)]);
  }
  return largest;
}

/// Steps `state` `steps` times through `pipeline`, timing the last `measured` of them.
RunTimes run(const SceneModel& model, StepPipeline& pipeline, State state, int steps, int measured) {
  RunTimes out;
  double total = 0.0;
  try {
    for (int s = 0; s < steps; ++s) {
      const double start = thread_cpu_milliseconds();
      pipeline.step(state);
      if (s >= steps - measured) total += thread_cpu_milliseconds() - start;
    }
  } catch (const std::exception& e) {
    out.failure = e.what();
  }
  out.per_step = total / measured;
  out.contacts = static_cast<int>(detect_rigid_contacts(*model.rigid_bodies, state.q).size());
  out.largest_group = largest_group(*model.rigid_bodies, state.q);
  out.end = std::move(state);
  return out;
}

/// FNV-1a of the bytes of the state's q and v: equal checksums before and after an
/// optimisation show that it left the trajectory unchanged, bit for bit.
unsigned long long checksum(const State& state) {
  unsigned long long h = 1469598103934665603ULL;
  for (const Vector* x : {&state.q, &state.v}) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(x->data());
    for (std::size_t k = 0; k < sizeof(double) * static_cast<std::size_t>(x->size()); ++k) {
      h = (h ^ bytes[k]) * 1099511628211ULL;
    }
  }
  return h;
}

std::vector<int> parse_sizes(const char* text) {
  std::vector<int> sizes;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) sizes.push_back(std::atoi(item.c_str()));
  return sizes;
}

}  // namespace
}  // namespace fosssim::bench

int main(int argc, char** argv) {
  using namespace fosssim;
  using namespace fosssim::bench;
  std::vector<int> sizes = {100, 1000, 10000};
  int steps = 60, all_pairs_steps = 0;  // 0: 20 steps below 10⁴ bodies, 2 from 10⁴
  std::vector<std::string> only;
  for (int a = 1; a < argc; a += 2) {
    const bool help = !std::strcmp(argv[a], "--help");
    if (help || a + 1 == argc) {
      std::fprintf(help ? stdout : stderr,
                   "usage: %s [--sizes 100,1000,10000] [--steps S] [--all-pairs-steps K] "
                   "[--methods NAME]...\n  (the smallest run: --sizes 100 --steps 4)\n",
                   argv[0]);
      return help ? 0 : 2;
    }
    if (!std::strcmp(argv[a], "--sizes")) sizes = parse_sizes(argv[a + 1]);
    else if (!std::strcmp(argv[a], "--steps")) steps = std::atoi(argv[a + 1]);
    else if (!std::strcmp(argv[a], "--all-pairs-steps")) all_pairs_steps = std::atoi(argv[a + 1]);
    else if (!std::strcmp(argv[a], "--methods")) only.push_back(argv[a + 1]);
    else {
      std::fprintf(stderr, "%s: unknown option %s (--help lists them)\n", argv[0], argv[a]);
      return 2;
    }
  }
  const int measured = std::max(1, steps / 2);
  std::printf("rigid-body pile falling into a box: %d steps of h = %g, ms per step (thread CPU) "
              "over the last %d (load %s)\n", steps, kStep, measured, load_average().c_str());
  std::printf("%7s  %-24s %10s %9s %8s %17s  %s\n", "bodies", "response (detection)", "ms/step",
              "contacts", "largest", "end state", "scaling per 10x bodies");
  std::vector<std::string> names;
  for (const ContactMethod* method : contact_methods()) {
    if (!method->scope.handles(BodyKind::kPlanarRigidBodies) || method->name == "none") continue;
    if (only.empty() || std::find(only.begin(), only.end(), method->name) != only.end()) {
      names.emplace_back(method->name);
    }
  }
  if (only.empty() || std::find(only.begin(), only.end(), "all-pairs") != only.end()) {
    names.push_back("lcp (all pairs)");  // needs lcp's run, which it continues
  }
  std::vector<std::vector<double>> times(names.size());
  for (const int n : sizes) {
    State lcp_end;
    bool have_lcp_end = false;
    for (std::size_t m = 0; m < names.size(); ++m) {
      RunTimes t;
      if (names[m] != "lcp (all pairs)") {
        auto [model, state] = make_pile(n, contact_method(names[m]));
        StepPipeline pipeline(model);
        t = run(model, pipeline, std::move(state), steps, measured);
        if (names[m] == "lcp" && t.failure.empty()) {
          lcp_end = t.end;
          have_lcp_end = true;
        }
      } else {
        if (!have_lcp_end) continue;
        auto [model, state] = make_pile(n, no_contact_method());  // no stage of its own
        StepPipeline pipeline(model);
        pipeline.add_stage(StagePhase::kResponse, std::make_unique<AllPairsLcpStage>(model));
        const int k = all_pairs_steps > 0 ? all_pairs_steps : (n < 10000 ? 20 : 2);
        t = run(model, pipeline, lcp_end, k, k);
      }
      times[m].push_back(t.per_step);
      std::string scaling;
      if (times[m].size() >= 2 && t.failure.empty()) {
        const double ratio = times[m].back() / times[m][times[m].size() - 2];
        const double factor = double(n) / sizes[times[m].size() - 2];
        char text[64];
        std::snprintf(text, sizeof text, "%.1fx for %.0fx bodies", ratio, factor);
        scaling = text;
      }
      std::printf("%7d  %-24s %10.2f %9d %8d %017llx  %s%s\n", n, names[m].c_str(), t.per_step,
                  t.contacts, t.largest_group, checksum(t.end), scaling.c_str(),
                  t.failure.empty() ? "" : ("  FAILED: " + t.failure.substr(0, 160)).c_str());
      std::fflush(stdout);
    }
  }
}
