"""The extra-credit scenes (extracreditassets/): vortices for every integrator, the integrator
aliases, constant forces, paths and colours, a stiff scene for the implicit integrators, a 2D
net and the figure-eight three-body orbit."""

import math

from milestone_scenes import NAMES, fmt
from scene_writer import DARK_BACKGROUND, GRAVITY, PALETTE, Scene, direction

VORTEX_LOOK = {
    "explicit": "Explicit Euler is stable here because the drag term's rate h kvc / (m l^2) stays "
                "well below 1 for every particle.",
    "symplectic": "Symplectic Euler treats the vortex like explicit Euler (the force depends on "
                  "velocity), stable at this step.",
    "linearized": "Linearized implicit Euler uses the vortex force's exact Jacobians (its "
                  "position Jacobian is not symmetric, so the step uses a general sparse solver).",
    "implicit": "Implicit Euler runs Newton's method on the vortex force with its exact "
                "Jacobians (the position Jacobian is not symmetric, so the step uses a general "
                "sparse solver).",
}


# --------------------------------------------------------------------------------------------
# vortex
# --------------------------------------------------------------------------------------------
def vortex_swirl(integ):
    kbs, kvc, m = 1.0, 10.0, 1.0
    s = Scene(integ, dt=0.01, duration=5.0, viewport=(0.0, 0.0, 2.2),
              background=DARK_BACKGROUND)
    s.what = "one vortex: rings of particles swirl, inner ones faster"
    centre = s.particle(1.0e6, 0.0, 0.0, fixed=True, radius=0.1, color=(0.9, 0.9, 0.9))
    for ring, r in enumerate((0.6, 1.0, 1.4)):
        for n in range(8):
            c, sn = direction(45.0 * (n + 0.5 * ring))
            p = s.particle(m, r * c, r * sn, radius=0.04,
                           color=PALETTE[(n + ring) % 6])
            s.vortex.append((centre, p, kbs, kvc))
            s.path(p, duration=1.0)
    s.description = (f"A vortex (kbs = {fmt(kbs)}, kvc = {fmt(kvc)}) around a fixed centre "
                     "drives 24 particles, starting at rest on three rings, towards the "
                     "counter-clockwise velocity kbs R(n): all reach speed about kbs, so the inner "
                     "ring turns faster (angular speed kbs / r) and the rings shear into a swirl "
                     "while drifting slowly outwards (the force has no centripetal part). "
                     + VORTEX_LOOK[integ])
    return s


def vortex_pair(integ):
    kbs, kvc, m = 1.0, 10.0, 1.0
    s = Scene(integ, dt=0.01, duration=4.0, viewport=(0.0, 1.0, 2.8),
              background=DARK_BACKGROUND)
    s.what = "two counter-rotating vortices push a jet of particles between them"
    left = s.particle(1.0e6, -1.0, 0.0, fixed=True, radius=0.1, color=(0.9, 0.9, 0.9))
    right = s.particle(1.0e6, 1.0, 0.0, fixed=True, radius=0.1, color=(0.9, 0.9, 0.9))
    for column in range(5):
        x = -0.4 + 0.2 * column
        color = PALETTE[1] if x < 0 else (PALETTE[0] if x > 0 else PALETTE[4])
        for row in range(5):
            y = -0.8 + 0.4 * row
            p = s.particle(m, x, y, radius=0.035, color=color)
            s.vortex.append((left, p, kbs, kvc))
            s.vortex.append((right, p, -kbs, kvc))
            s.path(p, duration=0.5)
    s.description = ("Two vortices, the left one counter-clockwise (kbs = 1) and the right one "
                     "clockwise (kbs = -1), both kvc = 10, act on 25 particles between them. On the "
                     "line between the centres both push upwards, so the particles shoot up as a "
                     "jet and curl back around each vortex, blue to the left and orange to the "
                     "right, like the cross-section of a smoke ring. " + VORTEX_LOOK[integ])
    return s


# --------------------------------------------------------------------------------------------
# aliases
# --------------------------------------------------------------------------------------------
def springs_alias_forward_backward_euler(integ):
    k, m, side = 200.0, 1.0, 0.5
    s = Scene("symplectic", dt=0.002, duration=3.0, viewport=(1.2, 0.0, 1.8),
              integrator_type="forward-backward-euler")
    s.what = "alias forward-backward-euler (= symplectic Euler): a tumbling braced square"
    corners = []
    spin, drift = 2.0, (0.8, 0.0)
    for n, (x, y) in enumerate(((-1, -1), (1, -1), (1, 1), (-1, 1))):
        x, y = 0.5 * side * x, 0.5 * side * y
        corners.append(s.particle(m, x, y, drift[0] - spin * y, drift[1] + spin * x,
                                  radius=0.05, color=PALETTE[n]))
    for n in range(4):
        s.spring(corners[n], corners[(n + 1) % 4], k)
    s.spring(corners[0], corners[2], k)
    s.spring(corners[1], corners[3], k)
    s.path(corners[0], duration=1.0)
    s.description = ("The integrator type forward-backward-euler is another name for symplectic "
                     "Euler. A square of four particles braced by springs on its sides and both "
                     f"diagonals (k = {fmt(k)}) drifts to the right at 0.8 while spinning at "
                     f"{fmt(spin)} rad/s: it tumbles like a nearly rigid body, its centre moving "
                     "in a straight line, its corners stretching the springs slightly outwards.")
    return s


def simplegravity_alias_semi_implicit_euler(integ):
    s = Scene("symplectic", dt=0.01, duration=1.2, viewport=(-0.3, -0.45, 3.2),
              integrator_type="semi-implicit-euler")
    s.what = "alias semi-implicit-euler (= symplectic Euler): a fountain of coloured particles"
    s.gravity.append((0.0, -GRAVITY))
    for n in range(12):
        c, sn = direction(60.0 + 60.0 * n / 11.0)
        speed = 4.5 + 0.5 * (n % 3)
        p = s.particle(1.0, 0.0, 0.0, speed * c, speed * sn,
                       radius=0.04, color=PALETTE[n % 6])
        s.path(p, duration=0.4)
    s.description = ("The integrator type semi-implicit-euler is another name for symplectic "
                     "Euler. Twelve particles shoot up from the origin at angles from 60 to 120 "
                     "degrees and speeds 4.5 to 5.5 under gravity, like a fountain; each follows "
                     "its own parabola and all are back below the start by t = 1.2.")
    return s


def springdamping_alias_linearized_implicit(integ):
    links, length, m, k, b = 6, 0.25, 0.2, 500.0, 2.0
    s = Scene("linearized", dt=0.01, duration=4.0, viewport=(0.0, -0.8, 1.7),
              integrator_type="linearized-implicit")
    s.what = "alias linearized-implicit: a damped rope swinging down"
    s.gravity.append((0.0, -GRAVITY))
    chain = [s.particle(1.0, 0.0, 0.0, fixed=True, radius=0.05)]
    for n in range(1, links + 1):
        chain.append(s.particle(m, length * n, 0.0, radius=0.045, color=PALETTE[2]))
    for a, c in zip(chain, chain[1:]):
        s.spring(a, c, k, length, b)
    s.path(chain[-1], duration=1.0)
    s.description = ("The integrator type linearized-implicit is another name for linearized "
                     f"implicit Euler. A rope of {links} particles on damped springs (k = "
                     f"{fmt(k)}, b = {fmt(b)}) is released horizontally from a fixed end and "
                     "swings down and back like a rope; spring damping and the integrator's "
                     "numerical damping take energy out, so each swing is lower than the last.")
    return s


def system_alias_implicit(integ):
    length, m, k, b = 0.6, 1.0, 1.0e4, 10.0
    s = Scene("implicit", dt=0.005, duration=5.0, viewport=(0.0, -0.6, 1.4),
              integrator_type="implicit")
    s.what = "alias implicit (= implicit Euler): a double pendulum"
    s.gravity.append((0.0, -GRAVITY))
    top = s.particle(1.0, 0.0, 0.0, fixed=True, radius=0.05)
    a = s.particle(m, length, 0.0, radius=0.07, color=PALETTE[0])
    c = s.particle(m, length, -length, radius=0.07, color=PALETTE[1])
    s.spring(top, a, k, length, b, radius=0.02)
    s.spring(a, c, k, length, b, radius=0.02)
    s.path(c, duration=1.5)
    s.description = ("The integrator type implicit is another name for implicit Euler (Newton). "
                     "A double pendulum of stiff damped springs (k = 1e4), first link horizontal "
                     "and second hanging down, released under gravity: its motion is chaotic and "
                     "implicit Euler's numerical damping slowly calms it.")
    return s


# --------------------------------------------------------------------------------------------
# constant force
# --------------------------------------------------------------------------------------------
def constantforce_wind(integ):
    wind = (2.0, 0.0)
    s = Scene(integ, dt=0.01, duration=1.2, viewport=(1.45, -3.55, 3.8))
    s.what = "constant force plus gravity: light particles are blown farther"
    s.gravity.append((0.0, -GRAVITY))
    s.constant.append(wind)
    for n, m in enumerate((0.5, 1.0, 2.0)):
        p = s.particle(m, 0.0, 0.0, radius=0.05 + 0.03 * m, color=PALETTE[n])
        s.path(p)
    s.description = ("A constant force (2, 0), the same for every particle, plus gravity, on "
                     "particles of mass 0.5, 1 and 2 dropped from the origin: they fall together "
                     "but the wind accelerates them by f / m = 4, 2 and 1, so each falls on its "
                     "own straight line and the lightest is blown farthest (2.88, 1.44 and 0.72 "
                     "at t = 1.2). " + NAMES[integ][0].upper() + NAMES[integ][1:] + ".")
    return s


def constantforce_balloons(integ):
    s = Scene(integ, dt=0.01, duration=1.0, viewport=(0.5, 1.25, 4.0))
    s.what = "constant upward force equal to one particle's weight: rise, float, sink"
    s.gravity.append((0.0, -GRAVITY))
    s.constant.append((0.0, GRAVITY))
    for n, m in enumerate((0.5, 1.0, 2.0)):
        p = s.particle(m, 0.5 * n, 0.0, radius=0.05 + 0.03 * m, color=PALETTE[n])
        s.path(p)
    s.description = (f"Balloons: a constant upward force of {GRAVITY} on every particle, with "
                     "gravity. It exactly carries the particle of mass 1, which floats in place; "
                     "the one of mass 0.5 rises with acceleration g and the one of mass 2 sinks "
                     "with g / 2 (at t = 1: +4.905, 0 and -2.45). " + NAMES[integ][0].upper()
                     + NAMES[integ][1:] + ".")
    return s


def constantforce_pendulum_in_wind(integ):
    m, length, k, b = 1.0, 1.0, 1000.0, 5.0
    wind = (5.0, 0.0)
    angle = math.degrees(math.atan2(wind[0], m * GRAVITY))
    s = Scene(integ, dt=0.01, duration=5.0, viewport=(0.3, -0.6, 0.9))
    s.what = "a pendulum in a steady wind settles at atan(f / m g)"
    s.gravity.append((0.0, -GRAVITY))
    s.constant.append(wind)
    anchor = s.particle(1.0, 0.0, 0.0, fixed=True, radius=0.05)
    p = s.particle(m, 0.0, -length, radius=0.08, color=PALETTE[0])
    s.spring(anchor, p, k, length, b, radius=0.02)
    s.path(p, duration=2.0)
    s.description = (f"A pendulum (mass {fmt(m)}, stiff spring of length {fmt(length)}) hangs "
                     f"straight down when a constant sideways force {fmt(wind[0])} starts to "
                     "blow: it swings about the tilted rest angle atan(f / m g) = "
                     f"{fmt(angle, 3)} degrees, between 0 and about twice that, and "
                     + NAMES[integ] + "'s numerical damping slowly narrows the swing around the "
                     "tilted angle (the constant force also pulls on the fixed anchor, which "
                     "ignores it).")
    return s


# --------------------------------------------------------------------------------------------
# Newtonian gravity
# --------------------------------------------------------------------------------------------
FIGURE_EIGHT_PERIOD = 6.3259


def newtoniangravity_figure_eight(integ):
    # Initial conditions of the figure-eight choreography (Chenciner and Montgomery 2000, in
    # the form published by Simo), G = 1 and unit masses.
    x1 = (0.97000436, -0.24308753)
    v3 = (-0.93240737, -0.86473146)
    s = Scene(integ, dt=0.001, duration=FIGURE_EIGHT_PERIOD, viewport=(0.0, 0.0, 1.2),
              background=DARK_BACKGROUND)
    s.what = "three equal bodies chasing each other on a figure eight"
    bodies = [
        s.particle(1.0, x1[0], x1[1], -0.5 * v3[0], -0.5 * v3[1], radius=0.05, color=PALETTE[0]),
        s.particle(1.0, -x1[0], -x1[1], -0.5 * v3[0], -0.5 * v3[1], radius=0.05,
                   color=PALETTE[5]),
        s.particle(1.0, 0.0, 0.0, v3[0], v3[1], radius=0.05, color=PALETTE[4]),
    ]
    for n, i in enumerate(bodies):
        for j in bodies[n + 1:]:
            s.newtonian.append((i, j, 1.0))
        s.path(i, duration=2.0)
    look = {
        "explicit": "Explicit Euler at this step lets the bodies drift off the curve within the "
                    "period.",
        "symplectic": "Symplectic Euler at this step keeps them on the figure eight for the whole "
                      "period.",
        "implicit": "Implicit Euler's numerical damping slowly pulls them off the curve.",
        "linearized": "Linearized implicit Euler's numerical damping slowly pulls them off the "
                      "curve.",
    }[integ]
    s.description = ("The figure-eight three-body orbit (Chenciner and Montgomery, 2000): three "
                     "unit masses with G = 1, started from its known initial conditions, chase "
                     "each other around one figure-eight curve, the centre of mass fixed at the "
                     f"origin; after one period ({FIGURE_EIGHT_PERIOD} s, this scene's duration) "
                     "they are back where they started. " + look)
    return s


def newtoniangravity_solar_system_colours(integ):
    G, M = 1.0, 1000.0
    s = Scene(integ, dt=0.0005, duration=3.0, viewport=(0.0, 0.0, 3.3),
              background=DARK_BACKGROUND)
    s.what = "a coloured solar system with a moon, trails on a dark background"
    sun = s.particle(M, 0.0, 0.0, radius=0.15, color=(1.0, 0.85, 0.3))
    bodies = [sun]
    momentum = [0.0, 0.0]

    def orbiting(centre, m, r, angle, color, radius):
        c = s.particles[centre]
        co, sn = direction(angle)
        v = math.sqrt(G * (c.m + m) / r)
        p = s.particle(m, c.x + r * co, c.y + r * sn, c.vx - v * sn, c.vy + v * co,
                       radius=radius, color=color)
        momentum[0] += m * s.particles[p].vx
        momentum[1] += m * s.particles[p].vy
        bodies.append(p)
        return p

    orbiting(sun, 0.5, 0.8, 30.0, (0.75, 0.75, 0.75), 0.04)
    orbiting(sun, 2.0, 1.4, 150.0, (0.95, 0.6, 0.2), 0.06)
    earth = orbiting(sun, 3.0, 2.0, 270.0, (0.2, 0.5, 1.0), 0.07)
    moon = orbiting(earth, 0.001, 0.06, 0.0, (0.9, 0.9, 0.9), 0.02)
    orbiting(sun, 1.0, 2.8, 60.0, (0.9, 0.3, 0.2), 0.05)
    s.particles[sun].vx = -momentum[0] / M
    s.particles[sun].vy = -momentum[1] / M
    for n, i in enumerate(bodies):
        for j in bodies[n + 1:]:
            s.newtonian.append((i, j, G))
    for p in bodies[1:]:
        s.path(p, duration=0.15 if p == moon else 0.8, color=s.particle_colors[p])
    s.description = ("Particle colours, paths and a background colour: a sun (mass 1000) and "
                     "four planets at radii 0.8, 1.4, 2 and 2.8 on circular orbits, the blue one "
                     "with a small moon at distance 0.06, every pair attracting (G = 1). Each "
                     "body draws a trail of its recent path in its own colour; the moon's trail "
                     "loops around the blue planet's. " + NAMES[integ][0].upper()
                     + NAMES[integ][1:] + " with a small step (0.0005) for the fast moon.")
    return s


# --------------------------------------------------------------------------------------------
# stiff springs and nets
# --------------------------------------------------------------------------------------------
def springs_stiff_chain_large_step(integ):
    links, length, m, k = 10, 0.1, 0.01, 1.0e4
    s = Scene(integ, dt=0.01, duration=3.0, viewport=(0.0, -0.5, 1.1))
    s.what = "stiff chain (sqrt(k/m) dt = 10) at a large step: only the implicit integrators cope"
    s.gravity.append((0.0, -GRAVITY))
    chain = [s.particle(1.0, 0.0, 0.0, fixed=True, radius=0.03)]
    for n in range(1, links + 1):
        chain.append(s.particle(m, length * n, 0.0, radius=0.025, color=PALETTE[3]))
    for a, c in zip(chain, chain[1:]):
        s.spring(a, c, k, length)
    s.path(chain[-1], duration=1.0)
    omega = math.sqrt(k / m)
    s.description = (f"A chain of {links} light particles (mass {fmt(m)}) on very stiff springs "
                     f"(k = {fmt(k)}, so sqrt(k/m) = {fmt(omega)} rad/s) falls from horizontal "
                     f"under gravity with a large step dt = {s.dt}: sqrt(k/m) dt = "
                     f"{fmt(omega * s.dt)}. " + NAMES[integ][0].upper() + NAMES[integ][1:] +
                     " stays stable and swings the chain down like a rope, its links nearly "
                     "rigid. Explicit and symplectic Euler blow up at this step (within about "
                     "a second): the chain's fastest vibration has omega ~ 2 sqrt(k/m) = "
                     f"{fmt(2.0 * omega)}, so they need dt below about 2 / {fmt(2.0 * omega)} = "
                     f"{fmt(1.0 / omega)}.")
    return s


NET_DT = {"symplectic": 0.001, "implicit": 0.01, "linearized": 0.01}


def system_net(integ):
    n, spacing, m, k, k_shear, drag = 9, 0.25, 0.02, 800.0, 200.0, 0.01
    s = Scene(integ, dt=NET_DT[integ], duration=3.0, viewport=(1.0, -1.2, 1.8))
    s.what = "a 9 x 9 net of springs pinned at two corners, blown sideways"
    s.gravity.append((0.0, -GRAVITY))
    s.drag.append(drag)
    node = {}
    for row in range(n):
        for col in range(n):
            fixed = row == 0 and col in (0, n - 1)
            depth = row / (n - 1)
            vx = 0.0 if fixed else 1.5 * depth
            node[row, col] = s.particle(m, spacing * col, -spacing * row, vx, 0.0, fixed=fixed,
                                        radius=0.03,
                                        color=None if fixed else PALETTE[1 if row % 2 else 5])
    for row in range(n):
        for col in range(n):
            if col + 1 < n:
                s.spring(node[row, col], node[row, col + 1], k, radius=0.01)
            if row + 1 < n:
                s.spring(node[row, col], node[row + 1, col], k, radius=0.01)
            if row + 1 < n and col + 1 < n:
                s.spring(node[row, col], node[row + 1, col + 1], k_shear, radius=0.006,
                         color=(0.6, 0.75, 0.75))
                s.spring(node[row, col + 1], node[row + 1, col], k_shear, radius=0.006,
                         color=(0.6, 0.75, 0.75))
    look = {
        "symplectic": "Symplectic Euler needs a small step (0.001) for the net's fastest "
                      "vibrations.",
        "implicit": "Implicit Euler takes ten times larger steps (0.01) and damps the fast "
                    "vibrations.",
        "linearized": "Linearized implicit Euler takes ten times larger steps (0.01).",
    }[integ]
    s.description = (f"A 2D net of {n * n} particles (mass {fmt(m)}) joined by structural springs "
                     f"(k = {fmt(k)}) and diagonal shear springs (k = {fmt(k_shear)}), pinned at its "
                     "two top corners, in air (linear drag b = "
                     f"{fmt(drag)}). Under gravity it sags into a curtain while a sideways gust "
                     "(initial velocity growing with depth) makes it swing. " + look)
    return s


# (file name without .xml, builder, integrator family)
EXTRA_SCENES = [
    ("vortex_swirl_explicit", vortex_swirl, "explicit"),
    ("vortex_swirl_symplectic", vortex_swirl, "symplectic"),
    ("vortex_swirl_linearized", vortex_swirl, "linearized"),
    ("vortex_swirl_implicit", vortex_swirl, "implicit"),
    ("vortex_pair_explicit", vortex_pair, "explicit"),
    ("vortex_pair_symplectic", vortex_pair, "symplectic"),
    ("vortex_pair_linearized", vortex_pair, "linearized"),
    ("vortex_pair_implicit", vortex_pair, "implicit"),
    ("springs_alias_forward_backward_euler", springs_alias_forward_backward_euler, "symplectic"),
    ("simplegravity_alias_semi_implicit_euler", simplegravity_alias_semi_implicit_euler,
     "symplectic"),
    ("springdamping_alias_linearized_implicit", springdamping_alias_linearized_implicit,
     "linearized"),
    ("system_alias_implicit", system_alias_implicit, "implicit"),
    ("constantforce_wind_symplectic", constantforce_wind, "symplectic"),
    ("constantforce_wind_implicit", constantforce_wind, "implicit"),
    ("constantforce_balloons_explicit", constantforce_balloons, "explicit"),
    ("constantforce_balloons_linearized", constantforce_balloons, "linearized"),
    ("constantforce_pendulum_in_wind_implicit", constantforce_pendulum_in_wind, "implicit"),
    ("newtoniangravity_figure_eight_explicit", newtoniangravity_figure_eight, "explicit"),
    ("newtoniangravity_figure_eight_symplectic", newtoniangravity_figure_eight, "symplectic"),
    ("newtoniangravity_figure_eight_implicit", newtoniangravity_figure_eight, "implicit"),
    ("newtoniangravity_solar_system_colours", newtoniangravity_solar_system_colours,
     "symplectic"),
    ("springs_stiff_chain_large_step_implicit", springs_stiff_chain_large_step, "implicit"),
    ("springs_stiff_chain_large_step_linearized", springs_stiff_chain_large_step, "linearized"),
    ("system_net_symplectic", system_net, "symplectic"),
    ("system_net_implicit", system_net, "implicit"),
]
