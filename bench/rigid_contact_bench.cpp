// Rigid-body contact: the broad phase against all pairs on piles of 100 to 3,000 polygons, and
// the time of each inelastic response on the broad phase's contacts (docs/rigid-bodies.md,
// "Speed"). Timings are thread CPU milliseconds; the baseline is all pairs in the same run.
// Usage: bench_rigid_contact [--quick]   (--quick: piles of at most 300 polygons)

#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <random>

#include "bench_clock.h"
#include "core/rigid/rigid_contact_detection.h"
#include "core/rigid/rigid_contact_response.h"

namespace fosssim::bench {
namespace {

/// n polygons (3 to 6 vertices, radius about 0.5, body radius 0.1) on a jittered grid of
/// spacing `spacing`: at 1.1 each touches a neighbour or two (small groups of contacts), at
/// 0.95 nearly all touch (one group: a pile in resting contact).
void make_pile(int n, double spacing, RigidBodies& bodies, Vector& q, Vector& v) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int side = static_cast<int>(std::ceil(std::sqrt(n)));
  bodies.bodies.clear();
  q.resize(3 * n);
  v.resize(3 * n);
  for (int b = 0; b < n; ++b) {
    RigidBody body;
    const int vertices = 3 + static_cast<int>(u(rng) * 4);
    std::vector<Vec2> points;
    std::vector<double> masses(vertices, 1.0);
    for (int k = 0; k < vertices; ++k) {
      const double angle = -2 * std::numbers::pi * (k + 0.2 + 0.6 * u(rng)) / vertices;
      points.emplace_back(0.5 * std::cos(angle), 0.5 * std::sin(angle));
    }
    const MassProperties mp = compute_mass_properties(points, masses);
    for (const Vec2& p : points) body.body_points.push_back(p - mp.center);
    body.mass = mp.mass;
    body.inertia = mp.inertia;
    body.radius = 0.1;
    body.fixed = b < side;  // the bottom row holds the pile
    bodies.bodies.push_back(body);
    q.segment<3>(3 * b) << spacing * (b % side) + 0.1 * u(rng), spacing * (b / side) + 0.1 * u(rng),
        6 * u(rng);
    if (body.fixed) {
      v.segment<3>(3 * b).setZero();
    } else {
      v.segment<3>(3 * b) << u(rng) - 0.5, -1.0 - u(rng), u(rng) - 0.5;
    }
  }
}

template <typename F>
double best_of(int runs, F&& f) {
  double best = 1e300;
  for (int r = 0; r < runs; ++r) {
    const double start = thread_cpu_milliseconds();
    f();
    best = std::min(best, thread_cpu_milliseconds() - start);
  }
  return best;
}

}  // namespace
}  // namespace fosssim::bench

int main(int argc, char** argv) {
  using namespace fosssim;
  using namespace fosssim::bench;
  const bool quick = argc == 2 && std::strcmp(argv[1], "--quick") == 0;
  if (argc > 1 && !quick) {
    std::fputs(
        "Usage: bench_rigid_contact [--quick]\n"
        "  The broad phase against all pairs on piles of 30 to 3,000 polygons, and each\n"
        "  inelastic response on its contacts (thread CPU ms). --quick: at most 300 polygons.\n",
        std::strcmp(argv[1], "--help") == 0 ? stdout : stderr);
    return std::strcmp(argv[1], "--help") == 0 ? 0 : 2;
  }
  std::printf("rigid-body contact on piles (load %s)\n", load_average().c_str());
  std::printf("%8s %7s %9s %9s %8s %11s %11s %7s %9s %9s\n", "spacing", "bodies", "pairs", "tested",
              "records", "all-pairs", "broad", "ratio", "lcp", "vp");
  const std::pair<double, int> cases[] = {{1.1, 100}, {1.1, 300},  {1.1, 1000}, {1.1, 3000},
                                          {0.95, 30}, {0.95, 100}, {0.95, 300}};
  for (const auto& [spacing, n] : cases) {
    if (quick && n > 300) continue;
    RigidBodies bodies;
    Vector q, v;
    make_pile(n, spacing, bodies, q, v);
    std::vector<RigidContact> all, fast;
    const int runs = n <= 1000 ? 3 : 1;
    const double t_all = best_of(runs, [&] { all = detect_rigid_contacts_all_pairs(bodies, q); });
    const double t_fast = best_of(runs, [&] { fast = detect_rigid_contacts(bodies, q); });
    const std::size_t tested = rigid_candidate_pairs(bodies, q).size();
    bool same = all.size() == fast.size();
    for (std::size_t k = 0; same && k < all.size(); ++k) {
      same = all[k].i0 == fast[k].i0 && all[k].i1 == fast[k].i1 && all[k].arm0 == fast[k].arm0 &&
             all[k].arm1 == fast[k].arm1 && all[k].normal == fast[k].normal;
    }
    double t_solver[2];
    const ContactSolver solvers[2] = {ContactSolver::kLcp, ContactSolver::kVelocityProjection};
    for (int s = 0; s < 2; ++s) {
      t_solver[s] = best_of(1, [&] {
        Vector w = v;
        ContactReport report;
        apply_inelastic_response(solvers[s], bodies, q, fast, w, report);
      });
    }
    std::printf("%8.2f %7d %9lld %9zu %8zu %9.1fms %9.2fms %6.0fx %7.1fms %7.1fms%s\n", spacing, n,
                static_cast<long long>(n) * (n - 1) / 2, tested, fast.size(), t_all, t_fast,
                t_all / t_fast, t_solver[0], t_solver[1], same ? "" : "  RECORDS DIFFER");
  }
}
