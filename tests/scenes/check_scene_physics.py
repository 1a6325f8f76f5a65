#!/usr/bin/env python3
"""Checks the physics of the shipped scenes against math: runs each scene with FOSSSim, reads its
trajectory and compares it with closed-form motion, discrete update formulas, equilibria and
conservation laws, and with the numbers their descriptions quote.

Usage: check_scene_physics.py FOSSSIM
Prints one line per check and exits 1 if any check fails.
"""

import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools", "scenes"))
from trajectory import layout_of_scene, point, read_records  # noqa: E402 (the reader lives with the scene tools)

FOSSSIM = None
G_EARTH = 9.81


class Run:
    """A scene run into a temporary file, with its frames."""

    def __init__(self, scene, num_particles, workdir):
        self.scene = scene
        out = os.path.join(workdir, scene.replace("/", "_") + ".bin")
        path = os.path.join(ROOT, scene)
        subprocess.run([FOSSSIM, "-s", path, "-d", "0", "-q", "-o", out],
                       check=True, stdout=subprocess.DEVNULL)
        with open(path) as f:
            layout = layout_of_scene(f.read())
        records = read_records(out, num_particles, layout=layout)
        # Continuous-time and hybrid files hold a sync record before each end-of-step record.
        self.records = records[::2] if layout == "polynomials" else records
        self.frames = [(r["q"], r["v"]) for r in self.records]
        self.n = num_particles

    def x(self, k, i):
        return point(self.frames[k][0], i)

    def v(self, k, i):
        return point(self.frames[k][1], i)

    def last(self):
        return len(self.frames) - 1


results = []


def expect(scene, label, value, ok):
    results.append((scene, label, value, bool(ok)))


def close(a, b, tol):
    return abs(a - b) <= tol


def kinetic(run, k, masses):
    return sum(0.5 * m * (run.v(k, i)[0] ** 2 + run.v(k, i)[1] ** 2) for i, m in masses.items())


# ---------------------------------------------------------------------------------------------
def check_inertia(work):
    for scene in ("assets/t1m1/inertia_single.xml", "assets/t1m2/symplectic_inertia_single.xml",
                  "assets/t1m2/linearized_inertia_single.xml", "assets/t1m3/inertia_single.xml"):
        r = Run(scene, 1, work)
        x = r.x(r.last(), 0)
        expect(scene, "final position (2, 1)", x,
               close(x[0], 2.0, 1e-12) and close(x[1], 1.0, 1e-12))
    r = Run("assets/t1m3/inertia_several.xml", 5, work)
    rest, moving = r.x(r.last(), 3), r.x(r.last(), 4)
    expect(r.scene, "fixed particle at rest stays at (-0.5, -0.5)", rest,
           rest == (-0.5, -0.5))
    expect(r.scene, "fixed moving particle at (-0.5, 0.5) + 2 (0.5, 0.25) = (0.5, 1)", moving,
           close(moving[0], 0.5, 1e-12) and close(moving[1], 1.0, 1e-12))


def check_simple_gravity(work):
    # Discrete solutions under constant acceleration g from y0 = 0 with h = 0.01, N = 100:
    # explicit Euler y_N = v0 T - g h^2 N(N-1)/2; the others y_N = v0 T - g h^2 N(N+1)/2.
    h, n = 0.01, 100
    for scene, explicit in (("assets/t1m1/simplegravity_fixed_moving.xml", True),
                            ("assets/t1m2/symplectic_simplegravity_fixed_moving.xml", False),
                            ("assets/t1m2/linearized_simplegravity_fixed_moving.xml", False),
                            ("assets/t1m3/simplegravity_fixed_moving.xml", False)):
        r = Run(scene, 3, work)
        steps = n * (n - 1) if explicit else n * (n + 1)
        expected = 3.0 - G_EARTH * h * h * steps / 2.0
        free, fixed = r.x(r.last(), 0), r.x(r.last(), 1)
        expect(scene, f"free particle y(1) = {expected:.6f} (discrete formula)", free[1],
               close(free[1], expected, 1e-9))
        expect(scene, "fixed particle with velocity (2, 3) ends at (2, 3)", fixed,
               close(fixed[0], 2.0, 1e-12) and close(fixed[1], 3.0, 1e-12))
    r = Run("assets/t1m2/symplectic_simplegravity_masses.xml", 3, work)
    moves = [tuple(a - b for a, b in zip(r.x(r.last(), i), r.x(0, i))) for i in range(3)]
    expect(r.scene, "masses 0.1, 1, 10 move alike, about (1.5, -2)", moves[1],
           all(close(m[0], moves[0][0], 1e-12) and close(m[1], moves[0][1], 1e-12)
               for m in moves) and close(moves[0][0], 1.5, 0.02) and
           close(moves[0][1], -2.0, 0.03))


def amplitude(run, i, first, last):
    xs = [run.x(k, i)[0] for k in range(first, last + 1)]
    return max(xs)


def check_springs(work):
    # springs_single: period 2 pi sqrt(m/k) = 1.987 s; symplectic amplitude stays 0.5.
    r = Run("assets/t1m2/symplectic_springs_single.xml", 2, work)
    xs = [r.x(k, 1)[0] for k in range(len(r.frames))]
    crossings = [k * 0.01 for k in range(1, len(xs)) if xs[k - 1] < 1.0 <= xs[k]]
    period = crossings[1] - crossings[0]
    expect(r.scene, "period 2 pi sqrt(m/k) = 1.987 s", period, close(period, 1.987, 0.02))
    expect(r.scene, "amplitude stays within 1.5 +- 1%", max(xs), close(max(xs), 1.5, 0.015))
    late_explicit = Run("assets/t1m1/springs_single.xml", 2, work)
    top = amplitude(late_explicit, 1, 4000, 5000)
    expect(late_explicit.scene, "explicit Euler amplitude grows (max x in the last second)", top,
           1.5 < top < 1.53)
    late_implicit = Run("assets/t1m3/springs_single.xml", 2, work)
    top = amplitude(late_implicit, 1, 400, 500)
    expect(late_implicit.scene, "implicit Euler amplitude decays (max x in the last second)", top,
           1.35 < top < 1.45)
    # zero rest length: x = cos t, y = 0.5 sin t.
    r = Run("assets/t1m2/symplectic_springs_zero_rest_length.xml", 2, work)
    worst = max(math.dist(r.x(k, 1), (math.cos(0.01 * k), 0.5 * math.sin(0.01 * k)))
                for k in range(len(r.frames)))
    expect(r.scene, "follows the ellipse (cos t, 0.5 sin t)", worst, worst < 0.01)
    # two masses: the centre of mass stays at the origin.
    r = Run("assets/t1m1/springs_two_masses.xml", 2, work)
    com = max(abs(1.0 * r.x(k, 0)[0] + 3.0 * r.x(k, 1)[0]) / 4.0 for k in range(len(r.frames)))
    expect(r.scene, "centre of mass stays at the origin", com, com < 1e-12)
    # moving anchor: a fixed particle with velocity (1, 0) is at (t, 0).
    r = Run("assets/t1m3/springs_moving_anchor.xml", 2, work)
    a = r.x(r.last(), 0)
    expect(r.scene, "fixed anchor with velocity ends at (4, 0)", a,
           close(a[0], 4.0, 1e-12) and a[1] == 0.0)


def check_spring_damping(work):
    # Hanging chain: spring n from the top stretches by (7 - n) m g / k at rest.
    m, k, l0 = 0.1, 50.0, 0.3
    expected, y = [], 0.0
    for n in range(1, 7):
        y -= l0 + (7 - n) * m * G_EARTH / k
        expected.append(y)
    for scene in ("assets/t1m1/springdamping_hanging_chain.xml",
                  "assets/t1m2/symplectic_springdamping_hanging_chain.xml",
                  "assets/t1m3/springdamping_hanging_chain.xml"):
        r = Run(scene, 7, work)
        worst = max(abs(r.x(r.last(), n)[1] - expected[n - 1]) for n in range(1, 7))
        expect(scene, f"settles at the analytic equilibrium (bottom y = {expected[-1]:.4f})",
               worst, worst < 0.005)
    # Spinning dumbbell: spring damping keeps angular momentum, drag removes it like exp(-b t/m).
    def angular_momentum(run, k):
        return sum(run.x(k, i)[0] * run.v(k, i)[1] - run.x(k, i)[1] * run.v(k, i)[0]
                   for i in range(2))
    r = Run("assets/t1m2/symplectic_springdamping_spinning.xml", 2, work)
    ratio = angular_momentum(r, r.last()) / angular_momentum(r, 0)
    expect(r.scene, "spring damping conserves angular momentum", ratio, close(ratio, 1.0, 1e-9))
    r = Run("assets/t1m2/symplectic_drag_spinning.xml", 2, work)
    ratio = angular_momentum(r, r.last()) / angular_momentum(r, 0)
    expect(r.scene, "drag: angular momentum ratio (1 - h b / m)^N ~ exp(-1.5)", ratio,
           close(ratio, (1.0 - 0.01 * 0.3) ** 500, 1e-9) and close(ratio, math.exp(-1.5), 0.01))
    # Critical damping: the middle particle does not overshoot x = 1, the top one does.
    r = Run("assets/t1m3/springdamping_compare.xml", 6, work)
    under = min(r.x(k, 1)[0] for k in range(len(r.frames)))
    critical = min(r.x(k, 3)[0] for k in range(len(r.frames)))
    expect(r.scene, "under-damped overshoots below x = 1", under, under < 0.8)
    expect(r.scene, "critically damped does not overshoot", critical, critical >= 1.0)


def check_drag(work):
    b, g = 4.0, G_EARTH
    for scene in ("assets/t1m1/drag_terminal_velocity.xml",
                  "assets/t1m2/symplectic_drag_terminal_velocity.xml",
                  "assets/t1m3/drag_terminal_velocity.xml"):
        r = Run(scene, 3, work)
        for i, m in enumerate((0.5, 1.0, 2.0)):
            vt = m * g / b
            vy = r.v(r.last(), i)[1]
            expect(scene, f"mass {m}: speed at t = 3 near m g / b = {vt:.4f}", -vy,
                   close(-vy, vt, 0.005 * vt))
    # Coasting: v_N = v0 c^N with c = 1 - h b / m. Explicit Euler moves with the old velocity,
    # x_N = v0 (m/b) (1 - c^N); symplectic Euler with the new one, x_N = v0 (m/b) c (1 - c^N).
    # Both approach the exact v0 (m/b) (1 - exp(-b t/m)) to within h v0 = 0.02.
    for scene, explicit in (("assets/t1m1/drag_coasting.xml", True),
                            ("assets/t1m2/symplectic_drag_coasting.xml", False)):
        r = Run(scene, 3, work)
        for i, m in enumerate((0.5, 1.0, 2.0)):
            c = 1.0 - 0.01 / m
            discrete = 2.0 * m * (1.0 - c ** 500) * (1.0 if explicit else c)
            exact = 2.0 * m * (1.0 - math.exp(-5.0 / m))
            x = r.x(r.last(), i)[0]
            expect(scene, f"mass {m}: x(5) = discrete formula, exact {exact:.4f} +- h v0", x,
                   close(x, discrete, 1e-9) and close(x, exact, 0.02 + 1e-9))


def check_orbits(work):
    for scene, low, high in (("assets/t1m1/accuracy_orbit_fixed_sun.xml", 1.07, 1.085),
                             ("assets/t1m2/symplectic_accuracy_orbit_fixed_sun.xml", 0.998, 1.002),
                             ("assets/t1m3/accuracy_orbit_fixed_sun.xml", 0.91, 0.925),
                             ("assets/t1m2/symplectic_accuracy_orbit_free_sun.xml", 0.998, 1.002)):
        r = Run(scene, 2, work)
        radii = [math.dist(r.x(k, 0), r.x(k, 1)) for k in range(len(r.frames))]
        if "symplectic" in scene:
            value = (min(radii), max(radii))
            ok = low <= value[0] and value[1] <= high
        else:
            value = radii[-1]
            ok = low <= value <= high
        expect(scene, f"orbit radius within [{low}, {high}]", value, ok)
    r = Run("assets/t1m2/symplectic_accuracy_orbit_free_sun.xml", 2, work)
    com = max(math.hypot(*(10.0 * a + b for a, b in zip(r.x(k, 0), r.x(k, 1))))
              for k in range(len(r.frames))) / 11.0
    expect(r.scene, "centre of mass drifts by less than 1e-12 from (1/11, 0)",
           abs(com - 1.0 / 11.0), abs(com - 1.0 / 11.0) < 1e-12)
    # Spring with period exactly 1 s: symplectic Euler is back at x = 1.5 after 3 periods.
    r = Run("assets/t1m2/symplectic_accuracy_spring_period.xml", 2, work)
    x = r.x(3000, 1)[0]
    expect(r.scene, "x(3) = 1.5 after three 1 s periods", x, close(x, 1.5, 1e-3))
    # Figure eight: back to the start after one period.
    r = Run("extracreditassets/newtoniangravity_figure_eight_symplectic.xml", 3, work)
    worst = max(math.dist(r.x(0, i), r.x(r.last(), i)) for i in range(3))
    expect(r.scene, "bodies back at their start after one period", worst, worst < 0.01)
    # Moon stays bound to its planet.
    r = Run("extracreditassets/newtoniangravity_solar_system_colours.xml", 6, work)
    far = max(math.dist(r.x(k, 3), r.x(k, 4)) for k in range(len(r.frames)))
    expect(r.scene, "the moon stays within 0.07 of its planet", far, far < 0.07)


def check_systems(work):
    masses = {i: 1.0 for i in range(1, 6)}

    def energy(run, k):
        e = kinetic(run, k, masses)
        for i in range(1, 6):
            e += G_EARTH * run.x(k, i)[1]
            d = math.dist(run.x(k, i - 1), run.x(k, i))
            e += 0.5 * 1.0e4 * (d - 0.5) ** 2
        return e

    r = Run("assets/t1m3/system_multiple_pendulum.xml", 6, work)
    samples = [energy(r, k) for k in range(0, len(r.frames), 100)]
    decreasing = all(b < a for a, b in zip(samples, samples[1:]))
    expect(r.scene, "implicit Euler: energy decreases second by second", samples, decreasing)
    s = Run("assets/t1m2/symplectic_system_multiple_pendulum.xml", 6, work)
    expect(r.scene, "implicit Euler loses more energy than symplectic Euler",
           (samples[-1], energy(s, s.last())), samples[-1] < energy(s, s.last()) - 10.0)
    # Elastic pendulum: the bouncing turns into swinging.
    r = Run("assets/t1m2/symplectic_system_elastic_pendulum.xml", 2, work)
    first = max(abs(r.x(k, 1)[0]) for k in range(0, 100))
    later = max(abs(r.x(k, 1)[0]) for k in range(100, len(r.frames)))
    # All the stretch energy k 0.15^2 / 2 turned into swing: m g L (1 - cos theta) with the
    # hanging length L = 4/3, so the swing reaches x = L sin theta.
    k, hang = 3.0 * G_EARTH, 4.0 / 3.0
    theta = math.acos(1.0 - 0.5 * k * 0.15 ** 2 / (G_EARTH * hang))
    full = hang * math.sin(theta)
    expect(r.scene, f"swing grows from the 4 degree start to about {full:.3f} (full transfer)",
           (first, later), later > 2.5 * first and close(later, full, 0.1 * full))
    # Stiff chain at a large step: the implicit integrators keep the links nearly rigid.
    for scene in ("extracreditassets/springs_stiff_chain_large_step_implicit.xml",
                  "extracreditassets/springs_stiff_chain_large_step_linearized.xml"):
        r = Run(scene, 11, work)
        strain = max(abs(math.dist(r.x(k, i), r.x(k, i + 1)) - 0.1) / 0.1
                     for k in range(len(r.frames)) for i in range(10))
        expect(scene, "links stretch by less than 1%", strain, strain < 0.01)
    # Balloons: the particle whose weight the constant force carries stays put.
    r = Run("extracreditassets/constantforce_balloons_explicit.xml", 3, work)
    expect(r.scene, "mass 1 floats exactly", r.x(r.last(), 1), r.x(r.last(), 1) == (0.5, 0.0))
    # Vortex: particles end up moving at about kbs = 1.
    r = Run("extracreditassets/vortex_swirl_implicit.xml", 25, work)
    speeds = [math.hypot(*r.v(r.last(), i)) for i in range(1, 25)]
    expect(r.scene, "particles move at about kbs = 1", (min(speeds), max(speeds)),
           0.8 < min(speeds) and max(speeds) < 1.05)


FAMILIES = ("explicit", "symplectic", "linearized", "implicit")


def momentum(run, k, masses):
    return tuple(sum(m * run.v(k, i)[c] for i, m in enumerate(masses)) for c in range(2))


def check_collisions(work):
    for family in FAMILIES:
        # A break with COR 1 and no forces: kinetic energy is kept through every impulse, and
        # momentum until the first ball reaches a cushion (a half-plane).
        scene = f"assets/t2m1/{family}_particleparticle_break.xml"
        r = Run(scene, 11, work)
        masses = [1.0] * 11
        e0 = kinetic(r, 0, dict(enumerate(masses)))
        e_end = kinetic(r, r.last(), dict(enumerate(masses)))
        expect(scene, "kinetic energy kept (8)", (e0, e_end), close(e_end, e0, 1e-9))
        first_wall = next((k for k, rec in enumerate(r.records)
                           if any(c[0] == 2 for c in rec["collisions"])), r.last())
        p0, p = momentum(r, 0, masses), momentum(r, first_wall - 1, masses)
        hits = sum(len(rec["collisions"]) for rec in r.records[:first_wall])
        expect(scene, f"momentum kept through {hits} ball collisions before the cushions",
               (p0, p), close(p[0], p0[0], 1e-12) and close(p[1], p0[1], 1e-12) and hits > 5)
        # Newton's cradle: the last ball leaves at speed 2, the others stop.
        scene = f"assets/t2m1/{family}_particleparticle_cradle.xml"
        r = Run(scene, 5, work)
        speeds = [r.v(r.last(), i)[0] for i in range(5)]
        expect(scene, "last ball at 2, the others at rest", speeds,
               close(speeds[4], 2.0, 1e-12) and all(abs(s) < 1e-12 for s in speeds[:4]))
        # COR 0.5: the relative normal speed after the impulse is half of it before.
        scene = f"assets/t2m1/{family}_cor_particle_pair.xml"
        r = Run(scene, 2, work)
        k = next(k for k, rec in enumerate(r.records) if rec["collisions"])
        n = r.records[k]["collisions"][0][3]
        length = math.hypot(*n)
        rel = [sum((r.v(j, 1)[c] - r.v(j, 0)[c]) * n[c] / length for c in range(2))
               for j in (0, k)]
        expect(scene, "relative normal speed after = -0.5 x before", rel,
               close(rel[1], -0.5 * rel[0], 1e-12))
        # Continuous-time stops a ball that simple detection lets through a thin wall, and logs
        # N(N-1) + 4 (particle-edge pairs) = 6 + 4 polynomials per step.
        scene = f"assets/t2m2/{family}_continuous_bullet.xml"
        r = Run(scene, 3, work)
        x = r.x(r.last(), 2)[0]
        counts = {len(rec["polynomials"]) for rec in r.records[1:]}
        expect(scene, "ball bounced back off the wall at x = 0.2; 10 polynomials a step",
               (x, counts), x < 0.1 and counts == {10})


def main(argv):
    global FOSSSIM
    if len(argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    FOSSSIM = os.path.abspath(argv[1])
    with tempfile.TemporaryDirectory(prefix="fosssim-physics.") as work:
        for check in (check_inertia, check_simple_gravity, check_springs, check_spring_damping,
                      check_drag, check_orbits, check_systems, check_collisions):
            check(work)
    failed = 0
    for scene, label, value, ok in results:
        failed += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {scene}: {label}: {value}")
    print(f"{len(results) - failed} of {len(results)} physics checks passed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
