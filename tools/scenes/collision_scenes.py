"""The scenes of the collision suites (assets/t2m1, t2m2, t2m3): the course's test categories of
Theme 2 for every collision type and integrator.

t2m1: types simple and penalty (restitution, fixed particles, half-planes, penalty,
particle-edge, particle-particle), once per integrator family. t2m2: continuous-time (fast
particles that discrete detection misses) and hybrid (impulse passes and rigid impact zones),
once per integrator family. t2m3: the contest timing class (balls and ribbons in a box, penalty
with thickness 0, forward-backward Euler) at sizes all-pairs grades quickly. Randomness comes
from random.Random(seed), whose sequence is the same on every Python 3.
"""

import math
import random

from scene_writer import FIXED_COLOR, GRAVITY, PALETTE, Scene

FAMILIES = ["explicit", "symplectic", "linearized", "implicit"]

FLOOR_COLOR = (0.35, 0.3, 0.25)


def stiff_dt(integ):
    """Explicit Euler gains energy on springs and penalty contact at a rate that grows with
    h·ω; scenes with them take ten times smaller steps under it."""
    return 0.001 if integ == "explicit" else 0.01


def penalty_dt(integ):
    """The course's implicit integrators leave the penalty force out of their matrix, so contact
    is as explicit under them as under explicit Euler: penalty scenes take ten times smaller
    steps with every integrator but symplectic Euler."""
    return 0.01 if integ == "symplectic" else 0.001
WALL_COLOR = (0.55, 0.6, 0.7)


def box(s, half_width, half_height, cy=0.0, colors=True):
    """Four half-planes bounding [-w, w] × [cy - h, cy + h]; normals unnormalised on purpose."""
    s.half_plane(0, cy - half_height, 0, 2, FLOOR_COLOR if colors else None)
    s.half_plane(0, cy + half_height, 0, -0.5, WALL_COLOR if colors else None)
    s.half_plane(-half_width, cy, 3, 0, WALL_COLOR if colors else None)
    s.half_plane(half_width, cy, -1, 0, WALL_COLOR if colors else None)


# --------------------------------------------------------------------------------------------
# t2m1: simple and penalty
# --------------------------------------------------------------------------------------------
def cor_particle_pair(integ):
    s = Scene(integ, dt=0.01, duration=1.5, viewport=(0, 0, 1.2))
    s.what = "two balls head-on with COR 0.5: they part at half their closing speed"
    s.particle(1, -0.8, 0, 1.2, 0, radius=0.15, color=PALETTE[0])
    s.particle(2, 0.8, 0.02, -0.6, 0, radius=0.2, color=PALETTE[1])
    s.collide("simple", COR=0.5)
    s.description = ("Coefficient of restitution: two balls (masses 1 and 2) meet head-on with "
                     "COR 0.5. Momentum is conserved; the relative normal speed after the impulse "
                     "is half what it was before.")
    return s


def cor_bouncing_ball(integ):
    s = Scene(integ, dt=0.01, duration=3.0, viewport=(0, 0.9, 1.2))
    s.what = "a ball bouncing on a floor with COR 0.8: each bounce lower"
    s.particle(1, 0, 1.5, 0.3, 0, radius=0.1, color=PALETTE[0])
    s.half_plane(0, 0, 0, 1, FLOOR_COLOR)
    s.gravity.append((0, -GRAVITY))
    s.collide("simple", COR=0.8)
    s.path(0)
    s.description = ("Restitution against a half-plane: a ball dropped from 1.5 m bounces with "
                     "COR 0.8, keeping 64% of its kinetic energy per bounce.")
    return s


def cor_particle_edge(integ):
    s = Scene(integ, dt=0.01, duration=1.0, viewport=(0, 0, 1.3))
    s.what = "ball on an edge with one fixed end, COR 0.5 (the course's worked example)"
    s.particle(2, 0.3, 0.35, 0, -1, radius=0.1, color=PALETTE[0])
    a = s.particle(1, -1, 0, fixed=True, radius=0.1)
    b = s.particle(3, 1, 0, radius=0.1, color=PALETTE[1])
    s.edge(a, b, radius=0.1)
    s.collide("simple", COR=0.5)
    s.description = ("Particle-edge impulse with COR 0.5: a ball of mass 2 falls on an edge "
                     "from a fixed particle to a free one of mass 3; the edge's free end takes "
                     "part of the impulse in proportion to where the ball hits (alpha = 0.65).")
    return s


def fixed_between_posts(integ):
    s = Scene(integ, dt=0.01, duration=3.0, viewport=(0, 0, 1.2))
    s.what = "a ball bouncing between two fixed posts: fixed particles have infinite mass"
    s.particle(1, -0.9, 0, fixed=True, radius=0.2)
    s.particle(1, 0.9, 0, fixed=True, radius=0.2)
    s.particle(1, 0, 0, 1.5, 0, radius=0.1, color=PALETTE[0])
    s.particle(1, 0, 0.5, 0, 0, fixed=True, radius=0.05)
    s.collide("simple")
    s.description = ("Fixed particles: a ball bounces elastically between two fixed posts, which "
                     "never move; its speed stays 1.5. A fixed particle at rest elsewhere touches "
                     "nothing.")
    return s


def fixed_edge_ends(integ):
    s = Scene(integ, dt=0.01, duration=2.0, viewport=(0, 0.3, 1.2))
    s.what = "balls falling on an edge between two fixed particles"
    a = s.particle(1, -1, 0, fixed=True, radius=0.05)
    b = s.particle(1, 1, 0, fixed=True, radius=0.05)
    s.edge(a, b, radius=0.05)
    for k, x in enumerate((-0.6, 0.0, 0.5)):
        s.particle(1 + k, x, 0.6 + 0.2 * k, 0.2, 0, radius=0.08, color=PALETTE[k])
    s.gravity.append((0, -GRAVITY))
    s.collide("simple", COR=0.7)
    s.description = ("Fixed particles as edge ends: three balls fall on an edge whose ends are "
                     "fixed, so the edge takes no impulse and the balls bounce with COR 0.7.")
    return s


def halfplane_box(integ):
    s = Scene(integ, dt=0.01, duration=3.0, viewport=(0, 0, 1.3))
    s.what = "balls in a box of four coloured half-planes with unnormalised normals"
    rng = random.Random(21)
    for k in range(6):
        s.particle(1, rng.uniform(-0.7, 0.7), rng.uniform(-0.7, 0.7), rng.uniform(-2, 2),
                   rng.uniform(-2, 2), radius=0.08, color=PALETTE[k])
    box(s, 1.0, 1.0)
    s.collide("simple")
    s.description = ("Half-planes: six balls bounce elastically inside a box of four "
                     "half-planes, whose normals have lengths 2, 0.5, 3 and 1 (the length never "
                     "matters). The balls also collide with each other.")
    return s


def halfplane_ramp(integ):
    s = Scene(integ, dt=0.01, duration=2.5, viewport=(0, 0.3, 1.4))
    s.what = "a ball bouncing down a tilted half-plane"
    s.particle(1, -1, 1.2, 0.5, 0, radius=0.1, color=PALETTE[0])
    s.half_plane(0, 0, 0.3, 1.0, FLOOR_COLOR)
    s.gravity.append((0, -GRAVITY))
    s.collide("simple", COR=0.9)
    s.path(0)
    s.description = ("A tilted half-plane: a ball bounces down a ramp with COR 0.9; each impulse "
                     "acts along the ramp's normal only.")
    return s


def penalty_floor_pile(integ):
    s = Scene(integ, dt=penalty_dt(integ), duration=2.0, viewport=(0, 0.4, 1.0))
    s.what = "balls settling on a floor and on each other by penalty forces"
    for k in range(5):
        s.particle(1, -0.4 + 0.2 * k, 0.2 + 0.25 * (k % 2), 0, 0, radius=0.1,
                   color=PALETTE[k])
    s.half_plane(0, 0, 0, 1, FLOOR_COLOR)
    s.gravity.append((0, -GRAVITY))
    s.drag.append(0.5)
    s.collide("penalty", k=1000, thickness=0.01)
    s.description = ("Penalty forces: five balls fall on a floor; springs of stiffness 1000 act "
                     "wherever objects come closer than their radii plus 0.01, so the balls sink "
                     "slightly into the floor and into each other and come to rest (drag).")
    return s


def penalty_chain_on_edge(integ):
    s = Scene(integ, dt=penalty_dt(integ), duration=2.0, viewport=(0, 0, 1.3))
    s.what = "a spring chain bouncing on a fixed edge, penalty contact"
    a = s.particle(1, -1.1, -0.5, fixed=True, radius=0.05)
    b = s.particle(1, 1.1, -0.5, fixed=True, radius=0.05)
    s.edge(a, b, radius=0.05)
    prev = None
    for k in range(6):
        p = s.particle(0.5, -0.5 + 0.2 * k, -0.1, radius=0.06, color=PALETTE[1])
        if prev is not None:
            s.spring(prev, p, 200, b=0.5)
        prev = p
    s.gravity.append((0, -GRAVITY))
    s.collide("penalty", k=2000)
    s.description = ("Penalty forces with edges: a chain of six particles on springs falls onto "
                     "a fixed edge and bounces on it, pushed by penalty forces (k = 2000, "
                     "default thickness 0.01) between its particles and the edge. The contact "
                     "is elastic: explicit Euler gains a little height per bounce, the implicit "
                     "integrators lose some.")
    return s


def particleedge_swinging_bar(integ):
    s = Scene(integ, dt=stiff_dt(integ), duration=2.0, viewport=(0, 0, 1.2))
    s.what = "balls hitting a free bar (an edge with a spring) from both sides"
    a = s.particle(1, -0.5, 0, radius=0.05, color=PALETTE[2])
    b = s.particle(1, 0.5, 0, radius=0.05, color=PALETTE[2])
    s.spring(a, b, 100, radius=0.06)
    s.particle(0.5, -0.2, 0.6, 0, -1.5, radius=0.1, color=PALETTE[0])
    s.particle(0.5, 0.3, -0.6, 0, 1.0, radius=0.1, color=PALETTE[1])
    s.collide("simple")
    s.description = ("Particle-edge collisions: two balls hit a free bar from above and below at "
                     "different points; the bar's ends share each impulse by where it hits, and "
                     "the bar spins.")
    return s


def particleparticle_cradle(integ):
    s = Scene(integ, dt=0.01, duration=1.5, viewport=(0, 0, 1.4))
    s.what = "Newton's cradle: a row of touching balls passes the momentum along"
    s.particle(1, -1.0, 0, 2, 0, radius=0.1, color=PALETTE[0])
    for k in range(4):
        s.particle(1, -0.3 + 0.2 * k, 0, radius=0.1, color=PALETTE[1])
    s.collide("simple")
    s.description = ("Particle-particle collisions in the course's order (Gauss-Seidel): a ball "
                     "hits a row of four touching balls; within one step the impulses pass "
                     "along the row and the last ball leaves at speed 2.")
    return s


def particleparticle_break(integ):
    s = Scene(integ, dt=0.005, duration=1.5, viewport=(0, 0, 1.6))
    s.what = "a break of billiard balls, COR 1: momentum and energy conserved"
    s.particle(1, -1.0, 0.01, 4, 0, radius=0.06, color=(0.8, 0.8, 0.8))
    k = 0
    for row in range(4):
        for j in range(row + 1):
            s.particle(1, 0.3 + row * 0.1040, (j - row / 2) * 0.1201, radius=0.06,
                       color=PALETTE[k % len(PALETTE)])
            k += 1
    box(s, 1.5, 0.8)
    s.collide("simple")
    s.description = ("A break: the cue ball hits a rack of ten balls in a box of half-planes. "
                     "Every collision is elastic, so momentum is conserved until the balls reach "
                     "the cushions and kinetic energy throughout.")
    return s


T2M1 = [
    ("cor", "particle_pair", cor_particle_pair),
    ("cor", "bouncing_ball", cor_bouncing_ball),
    ("cor", "particle_edge", cor_particle_edge),
    ("fixed", "between_posts", fixed_between_posts),
    ("fixed", "edge_ends", fixed_edge_ends),
    ("halfplane", "box", halfplane_box),
    ("halfplane", "ramp", halfplane_ramp),
    ("penalty", "floor_pile", penalty_floor_pile),
    ("penalty", "chain_on_edge", penalty_chain_on_edge),
    ("particleedge", "swinging_bar", particleedge_swinging_bar),
    ("particleparticle", "cradle", particleparticle_cradle),
    ("particleparticle", "break", particleparticle_break),
]


def penalty_stiff_exact_jacobian(integ):
    s = Scene(integ, dt=0.01, duration=2.0, viewport=(0, 0.3, 0.6))
    s.what = ("FOSSSim's own: stiff penalty contact (k = 1e5) that implicit Euler keeps stable "
              "with penalty-jacobian=\"exact\"")
    s.particle(0.1, 0, 0.3, 0, 0, radius=0.1, color=PALETTE[0])
    s.particle(0.1, 0.25, 0.5, 0, 0, radius=0.1, color=PALETTE[1])
    s.half_plane(0, 0, 0, 1, FLOOR_COLOR)
    s.gravity.append((0, -GRAVITY))
    s.collide("penalty", k=100000, thickness=0, **{"penalty-jacobian": "exact"})
    s.description = ("FOSSSim's own option: a penalty force of stiffness 1e5 on balls of mass "
                     "0.1 at h = 0.01 (h^2 k/m = 1000). With penalty-jacobian=\"exact\" the "
                     "contact enters implicit Euler's matrix and the balls settle; with the "
                     "course's semantics (no penalty Jacobian) they are shot off the floor.")
    return s


# --------------------------------------------------------------------------------------------
# t2m2: continuous-time and hybrid
# --------------------------------------------------------------------------------------------
def continuous_bullet(integ):
    s = Scene(integ, dt=0.01, duration=0.3, viewport=(0, 0, 1.5))
    s.what = "a fast ball that discrete detection lets through a thin wall; continuous-time stops it"
    a = s.particle(1, 0.2, -0.8, fixed=True, radius=0.02)
    b = s.particle(1, 0.2, 0.8, fixed=True, radius=0.02)
    s.edge(a, b, radius=0.02)
    s.particle(1, -1.2, 0.1, 60, 0, radius=0.05, color=PALETTE[0])
    s.collide("continuous-time")
    s.path(2)
    s.description = ("Continuous-time detection: a ball moving 0.6 per step meets a wall of "
                     "thickness 0.04. At the ends of steps it is never near the wall, so the "
                     "simple method would let it through; swept detection finds the contact "
                     "inside the step and bounces it back.")
    return s


def continuous_head_on(integ):
    s = Scene(integ, dt=0.01, duration=0.4, viewport=(0, 0, 1.5))
    s.what = "two fast balls crossing within one step, COR 0.8"
    s.particle(1, -1, 0.03, 40, 0, radius=0.05, color=PALETTE[0])
    s.particle(2, 1, -0.03, -40, 0, radius=0.05, color=PALETTE[1])
    s.collide("continuous-time", COR=0.8)
    s.description = ("Two balls approach at 80 per second and would pass through each other "
                     "within one step; continuous-time detection finds when they touch and "
                     "answers with COR 0.8.")
    return s


def continuous_halfplane_drop(integ):
    s = Scene(integ, dt=0.02, duration=1.5, viewport=(0, 1, 1.5))
    s.what = "a fast ball thrown at the floor bounces instead of tunnelling"
    s.particle(1, -0.5, 2, 2, -30, radius=0.05, color=PALETTE[0])
    s.half_plane(0, 0, 0, 1, FLOOR_COLOR)
    s.gravity.append((0, -GRAVITY))
    s.collide("continuous-time", COR=0.9)
    s.path(0)
    s.description = ("Continuous-time against a half-plane: a ball thrown down at 30 per second "
                     "moves 0.6 per step; every bounce is caught inside its step (COR 0.9).")
    return s


def continuous_edge_fixed(integ):
    s = Scene(integ, dt=stiff_dt(integ), duration=0.6, viewport=(0, 0, 1.2))
    s.what = "fast balls against a free edge and a fixed particle, COR 0.5"
    a = s.particle(1, -0.6, 0, radius=0.05, color=PALETTE[2])
    b = s.particle(2, 0.6, 0, radius=0.05, color=PALETTE[2])
    s.spring(a, b, 100, radius=0.03)
    s.particle(0.5, 0.1, 0.9, 0, -30, radius=0.05, color=PALETTE[0])
    s.particle(1, -0.8, -0.6, fixed=True, radius=0.1)
    s.particle(0.5, -0.8, 0.6, 0, -25, radius=0.05, color=PALETTE[1])
    s.collide("continuous-time", COR=0.5)
    s.description = ("Continuous-time with edges and fixed particles: one fast ball hits a free "
                     "bar, another a fixed particle (infinite mass), both with COR 0.5.")
    return s


def hybrid_resolved(integ):
    s = Scene(integ, dt=0.01, duration=1.0, viewport=(0, 0, 1.3))
    s.what = "hybrid: a few balls whose collisions the impulse passes resolve"
    rng = random.Random(5)
    for k in range(5):
        s.particle(1, -0.8 + 0.4 * k, rng.uniform(-0.3, 0.3), rng.uniform(-3, 3),
                   rng.uniform(-3, 3), radius=0.1, color=PALETTE[k])
    box(s, 1.2, 1.0)
    s.collide("hybrid", COR=0.9)
    s.description = ("Hybrid handling, impulse stage: penalty forces (k = 10, thickness 0.1), "
                     "then up to 10 Jacobi passes of swept impulses per step, which here resolve "
                     "every collision; the geometric stage is never needed.")
    return s


def hybrid_impact_zone(integ):
    s = Scene(integ, dt=0.01, duration=0.5, viewport=(0.2, 0, 1.0))
    s.what = "hybrid with one impulse pass: a row of balls merges into a rigid impact zone"
    s.particle(1, -0.45, 0, 1, 0, radius=0.25, color=PALETTE[0])
    s.particle(1, 0, 0, radius=0.25, color=PALETTE[1])
    s.particle(1, 0.45, 0, radius=0.25, color=PALETTE[2])
    s.collide("hybrid", maxiters=1, k=0)
    s.description = ("Rigid impact zones (the course's example): one impulse pass answers the "
                     "first contact only; the geometric stage then finds the second and moves "
                     "the touching balls together as one rigid body.")
    return s


def hybrid_geometric_pile(integ):
    s = Scene(integ, dt=0.01, duration=1.0, viewport=(0, 0.3, 1.0))
    s.what = "hybrid with maxiters 0: falling balls stop dead where they touch the floor"
    for k in range(4):
        s.particle(1, -0.45 + 0.3 * k, 0.3 + 0.15 * k, 0.5 - 0.3 * k, 0, radius=0.1,
                   color=PALETTE[k])
    s.half_plane(0, 0, 0, 1, FLOOR_COLOR)
    s.gravity.append((0, -GRAVITY))
    s.collide("hybrid", maxiters=0)
    s.description = ("The geometric stage alone (maxiters 0): balls fall on a floor; an impact "
                     "zone that touches a half-plane goes back to where it started the step and "
                     "stops, so the balls come to rest above the floor.")
    return s


def hybrid_ribbon(integ):
    s = Scene(integ, dt=stiff_dt(integ), duration=1.0, viewport=(0, 0, 1.3))
    s.what = "hybrid: a ribbon of springs and edges falls on a fixed bar"
    a = s.particle(1, -1, -0.5, fixed=True, radius=0.05)
    b = s.particle(1, 1, -0.5, fixed=True, radius=0.05)
    s.edge(a, b, radius=0.05)
    prev = None
    for k in range(6):
        p = s.particle(0.2, -0.5 + 0.2 * k, 0.3 + 0.05 * k, radius=0.05, color=PALETTE[3])
        if prev is not None:
            s.spring(prev, p, 300, b=0.2, radius=0.03)
        prev = p
    s.gravity.append((0, -GRAVITY))
    s.collide("hybrid", COR=0.5)
    s.description = ("Hybrid handling of a ribbon: a chain of particles joined by springs and "
                     "edges falls on a fixed bar; penalty forces, swept impulses and, when they "
                     "do not suffice, rigid impact zones keep it from passing through.")
    return s


T2M2 = [
    ("continuous", "bullet", continuous_bullet),
    ("continuous", "head_on", continuous_head_on),
    ("continuous", "halfplane_drop", continuous_halfplane_drop),
    ("continuous", "edge_and_fixed", continuous_edge_fixed),
    ("hybrid", "resolved", hybrid_resolved),
    ("hybrid", "impact_zone", hybrid_impact_zone),
    ("hybrid", "geometric_pile", hybrid_geometric_pile),
    ("hybrid", "ribbon", hybrid_ribbon),
]


# --------------------------------------------------------------------------------------------
# t2m3: the contest timing class
# --------------------------------------------------------------------------------------------
def contest_box(s, half):
    """Four fixed corner particles of radius 0.5 joined by four edges of radius 0.5."""
    corners = [s.particle(1, x, y, fixed=True, radius=0.5)
               for x, y in ((-half, -half), (half, -half), (half, half), (-half, half))]
    for k in range(4):
        s.edge(corners[k], corners[(k + 1) % 4], radius=0.5)


def timing_balls(count, detection, seed):
    def build(_):
        s = Scene("symplectic", dt=0.005, duration=0.1, viewport=(0, 0, 6.0),
                  integrator_type="forward-backward-euler")
        s.what = (f"{count} free balls of radius 0.02 in a box, penalty k 100, thickness 0, "
                  f"{detection} detection")
        rng = random.Random(seed)
        for _ in range(count):
            speed, angle = rng.uniform(0, 0.5), rng.uniform(0, 2 * math.pi)
            s.particle(1, rng.uniform(-5, 5), rng.uniform(-5, 5), round(speed * math.cos(angle), 6),
                       round(speed * math.sin(angle), 6), radius=0.02, color=PALETTE[1])
        contest_box(s, 5.5)
        s.collide("penalty", k=100, thickness=0)
        s.detection = detection
        s.description = (f"The contest's timing scene class at {count} balls: random positions in "
                         "[-5, 5]^2 and speeds up to 0.5 inside a box of four fixed corners and "
                         "edges of radius 0.5, penalty forces with thickness 0, forward-backward "
                         "Euler, h = 0.005, 20 steps. The course's scene has 15,000 balls.")
        return s
    return build


def add_ribbon(s, x0, y0, length, spacing, radius, edge_radius, color, velocity):
    """A horizontal chain of `length` particles of mass 0.1 from (x0, y0), `spacing` apart, joined
    by springs (k 100, b 0.1) on edges; velocity() gives each particle's (vx, vy) in turn."""
    prev = None
    for k in range(length):
        vx, vy = velocity()
        p = s.particle(0.1, x0 + spacing * k, y0, vx, vy, radius=radius, color=color)
        if prev is not None:
            s.spring(prev, p, 100, b=0.1, radius=edge_radius)
        prev = p


def timing_ribbons(_):
    s = Scene("symplectic", dt=0.005, duration=0.1, viewport=(0, 0, 6.0),
              integrator_type="forward-backward-euler")
    s.what = "a pile of ribbons (chains of springs and edges) in the box, contest detection"
    rng = random.Random(17)
    for r in range(12):
        x0, y0 = rng.uniform(-4, 3), rng.uniform(-4.5, 4.5)
        add_ribbon(s, x0, y0, 10, 0.1, 0.04, 0.02, PALETTE[r % len(PALETTE)],
                   lambda: (rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3)))
    contest_box(s, 5.5)
    s.gravity.append((0, -GRAVITY))
    s.collide("penalty", k=100, thickness=0)
    s.detection = "contest"
    s.description = ("The contest's ribbon pile: twelve ribbons of ten particles joined by springs "
                     "and edges fall in the box under gravity; penalty forces act between "
                     "particles, particles and edges, and the box.")
    return s


def timing_ribbon_pile(ribbons, length, seed):
    def build(_):
        s = Scene("symplectic", dt=0.005, duration=0.1, viewport=(0, 0, 6.0),
                  integrator_type="forward-backward-euler")
        s.what = (f"a pile of {ribbons} ribbons of {length} particles (springs and edges) in the "
                  "box, contest detection")
        rng = random.Random(seed)
        spacing = 0.06
        for r in range(ribbons):
            x0, y0 = rng.uniform(-4.9, 4.9 - spacing * (length - 1)), rng.uniform(-4.9, 4.9)
            vx, vy = rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3)
            add_ribbon(s, x0, y0, length, spacing, 0.02, 0.01, PALETTE[r % len(PALETTE)],
                       lambda: (vx, vy))
        contest_box(s, 5.5)
        s.gravity.append((0, -GRAVITY))
        s.collide("penalty", k=100, thickness=0)
        s.detection = "contest"
        s.description = (f"The contest's class with ribbons: {ribbons} ribbons of {length} "
                         "particles of radius 0.02, 0.06 apart, joined by springs and edges of "
                         "radius 0.01, lie across each other in the box (random places and "
                         "velocities) and fall under gravity; penalty forces with thickness 0 act "
                         "between particles, particles and edges, and the box; forward-backward "
                         "Euler, h = 0.005, 20 steps.")
        return s
    return build


def timing_simple(_):
    s = Scene("symplectic", dt=0.005, duration=0.5, viewport=(0, 0, 6.0),
              integrator_type="forward-backward-euler")
    s.what = "contest detection with simple impulses, which the course's program also runs"
    rng = random.Random(3)
    for _ in range(150):
        s.particle(1, rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-2, 2),
                   rng.uniform(-2, 2), radius=0.15, color=PALETTE[0])
    contest_box(s, 5.5)
    s.collide("simple")
    s.detection = "contest"
    s.description = ("Contest detection serves the simple method too: 150 balls of radius 0.15 "
                     "bounce elastically in the box.")
    return s


T2M3 = [
    ("timing", "balls_400_contest", timing_balls(400, "contest", 2)),
    ("timing", "balls_400_allpairs", timing_balls(400, "allpairs", 2)),
    ("timing", "balls_15000_contest", timing_balls(15000, "contest", 1)),
    ("timing", "ribbons_contest", timing_ribbons),
    ("timing", "ribbon_pile_15000_contest", timing_ribbon_pile(300, 50, 5)),
    ("timing", "simple_contest", timing_simple),
]


def collision_files():
    """(path relative to the repository, Scene, category) of every collision suite."""
    for category, what, build in T2M1:
        for family in FAMILIES:
            yield f"assets/t2m1/{family}_{category}_{what}.xml", build(family), category
    yield ("assets/t2m1/implicit_penalty_stiff_exact_jacobian.xml",
           penalty_stiff_exact_jacobian("implicit"), "penalty")
    for category, what, build in T2M2:
        for family in FAMILIES:
            yield f"assets/t2m2/{family}_{category}_{what}.xml", build(family), category
    for category, what, build in T2M3:
        yield f"assets/t2m3/{category}_{what}.xml", build(None), category
