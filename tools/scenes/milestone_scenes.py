"""The scenes of the milestone suites (assets/t1m1, t1m2, t1m3): one physical set-up per scene,
built for a given integrator family (explicit, symplectic, linearized, implicit).

Each builder returns a Scene; only the time step and the "what to look for" sentence depend on
the integrator. Numbers quoted in descriptions (periods, terminal velocities, orbit speeds) are
computed here from the same parameters the scene uses.
"""

import math

from scene_writer import FIXED_COLOR, GRAVITY, PALETTE, Scene, direction

# What the integrator does to a conservative oscillation, in a sentence.
ENERGY_BEHAVIOUR = {
    "explicit": "Explicit Euler adds a little energy every step, so the motion slowly grows.",
    "symplectic": "Symplectic Euler keeps the energy bounded: the motion neither grows nor decays.",
    "linearized": "Linearized implicit Euler removes a little energy every step (numerical "
                  "damping), so the motion slowly decays.",
    "implicit": "Implicit Euler removes a little energy every step (numerical damping), so the "
                "motion slowly decays.",
}

NAMES = {
    "explicit": "explicit Euler",
    "symplectic": "symplectic Euler",
    "linearized": "linearized implicit Euler",
    "implicit": "implicit Euler",
}


def oscillator_dt(integrator, explicit_dt=0.001, other_dt=0.01):
    """Explicit Euler needs a smaller step to stay faithful on undamped oscillations."""
    return explicit_dt if integrator == "explicit" else other_dt


def fmt(x, digits=4):
    """A number for prose: whole numbers as they are, others to `digits` significant digits."""
    if float(x).is_integer() and abs(x) < 1e9:
        return str(int(x))
    return f"{x:.{digits}g}"


# --------------------------------------------------------------------------------------------
# inertia
# --------------------------------------------------------------------------------------------
def inertia_single(integ):
    s = Scene(integ, dt=0.01, duration=2.0, viewport=(1.0, 0.5, 1.2))
    s.what = "one particle, no force: straight line at constant velocity"
    p = s.particle(1.0, 0.0, 0.0, 1.0, 0.5, radius=0.08, color=PALETTE[0])
    s.path(p)
    s.description = ("Inertia: one particle of mass 1 and no forces moves in a straight line at "
                     "constant velocity (1, 0.5) and is at (2, 1) at t = 2. Every integrator is "
                     "exact here, " + NAMES[integ] + " included.")
    return s


def inertia_several(integ):
    s = Scene(integ, dt=0.01, duration=2.0, viewport=(0.0, 0.0, 2.6))
    s.what = "different masses and velocities; fixed particles at rest and moving"
    s.particle(1.0, 0.0, 0.0, 1.0, 0.0, radius=0.08, color=PALETTE[0])
    s.particle(5.0, 0.0, 0.5, -0.5, 0.5, radius=0.14, color=PALETTE[1])
    s.particle(0.2, 0.5, -0.5, 0.0, -1.0, radius=0.05, color=PALETTE[2])
    s.particle(1.0, -0.5, -0.5, 0.0, 0.0, fixed=True, radius=0.08)
    s.particle(1.0, -0.5, 0.5, 0.5, 0.25, fixed=True, radius=0.08)
    for i in range(len(s.particles)):
        s.path(i)
    s.description = ("Inertia with five particles and no forces: each moves in its own straight "
                     "line at its own constant velocity, whatever its mass. The grey particles "
                     "are fixed: the one at rest stays at (-0.5, -0.5); the one with velocity "
                     "(0.5, 0.25) still moves in a straight line, because a fixed particle gets "
                     "no force but keeps its velocity.")
    return s


# --------------------------------------------------------------------------------------------
# simple gravity
# --------------------------------------------------------------------------------------------
def simplegravity_projectile(integ):
    speed = 5.0
    s = Scene(integ, dt=0.01, duration=0.9, viewport=(1.95, -0.4, 2.1))
    s.what = "projectiles at 30, 45 and 60 degrees: parabolas, equal ranges for 30 and 60"
    s.gravity.append((0.0, -GRAVITY))
    for k, angle in enumerate((30.0, 45.0, 60.0)):
        c, sn = direction(angle)
        p = s.particle(1.0, 0.0, 0.0, speed * c, speed * sn, radius=0.05,
                       color=PALETTE[k])
        s.path(p)
    r45 = speed * speed / GRAVITY
    r30 = speed * speed * math.sin(math.radians(60.0)) / GRAVITY
    bias = ("Explicit Euler's parabolas lie slightly above the exact ones (by g t dt / 2)"
            if integ == "explicit" else
            NAMES[integ][0].upper() + NAMES[integ][1:] +
            "'s parabolas lie slightly below the exact ones (by g t dt / 2)")
    s.description = (f"Simple gravity g = (0, -{GRAVITY}): three particles launched at speed "
                     f"{fmt(speed)} at 30, 45 and 60 degrees fly on parabolas. Back at y = 0, the "
                     f"45 degree one lands farthest, at x = v^2/g = {fmt(r45)}; the 30 and 60 "
                     f"degree ones land at the same x = {fmt(r30)}. {bias}.")
    return s


def simplegravity_fixed_moving(integ):
    s = Scene(integ, dt=0.01, duration=1.0, viewport=(1.0, 0.5, 2.7))
    s.what = "a fixed particle with velocity ignores gravity and moves straight"
    free = s.particle(1.0, 0.0, 0.0, 2.0, 3.0, radius=0.07, color=PALETTE[0])
    fixed = s.particle(1.0, 0.0, 0.0, 2.0, 3.0, fixed=True, radius=0.07)
    s.particle(1.0, 1.0, 0.0, 0.0, 0.0, fixed=True, radius=0.07)
    s.gravity.append((0.0, -GRAVITY))
    s.path(free)
    s.path(fixed, color=FIXED_COLOR)
    y_free = 3.0 - 0.5 * GRAVITY
    s.description = ("Fixed particles under gravity: a free particle and a fixed one start at the "
                     "origin with the same velocity (2, 3). The free one falls on a parabola to "
                     f"about (2, {fmt(y_free, 3)}) at t = 1; the fixed one gets no force and goes "
                     "straight to (2, 3). The grey particle at (1, 0) is fixed at rest and "
                     "stays there.")
    return s


def simplegravity_masses(integ):
    g = (3.0, -4.0)
    s = Scene(integ, dt=0.01, duration=1.0, viewport=(1.25, -1.0, 1.6))
    s.what = "masses 0.1, 1 and 10 fall together along a slanted g"
    s.gravity.append(g)
    for k, m in enumerate((0.1, 1.0, 10.0)):
        p = s.particle(m, 0.5 * k, 0.0, radius=0.05 * m ** (1.0 / 3.0) + 0.03, color=PALETTE[k])
        s.path(p)
    s.description = ("Simple gravity is an acceleration, so mass does not matter: particles of "
                     "mass 0.1, 1 and 10 fall together along g = (3, -4), keeping their spacing, "
                     "and each moves by (1.5, -2) in one second (g t^2 / 2).")
    return s


# --------------------------------------------------------------------------------------------
# springs
# --------------------------------------------------------------------------------------------
def springs_single(integ):
    k, m, l0 = 10.0, 1.0, 1.0
    s = Scene(integ, dt=oscillator_dt(integ), duration=5.0)
    s.what = "one spring to a fixed anchor: harmonic oscillation"
    anchor = s.particle(1.0, 0.0, 0.0, fixed=True, radius=0.06)
    p = s.particle(m, 1.5, 0.0, radius=0.08, color=PALETTE[0])
    s.spring(anchor, p, k, l0)
    period = 2.0 * math.pi * math.sqrt(m / k)
    s.description = (f"One spring (k = {fmt(k)}, rest length {fmt(l0)}) between a fixed anchor "
                     f"and a particle of mass {fmt(m)}, stretched by 0.5 and released: it "
                     f"oscillates between x = 0.5 and x = 1.5 with period 2 pi sqrt(m/k) = "
                     f"{fmt(period)} s. " + ENERGY_BEHAVIOUR[integ])
    return s


def springs_two_masses(integ):
    m1, m2, k, l0 = 1.0, 3.0, 12.0, 0.6
    s = Scene(integ, dt=oscillator_dt(integ), duration=4.0)
    s.what = "two free masses 1 and 3 on a spring: centre of mass stays put"
    a = s.particle(m1, -0.75, 0.0, radius=0.06, color=PALETTE[0])
    b = s.particle(m2, 0.25, 0.0, radius=0.09, color=PALETTE[1])
    s.spring(a, b, k, l0)
    mu = m1 * m2 / (m1 + m2)
    period = 2.0 * math.pi * math.sqrt(mu / k)
    s.description = (f"Two free particles of mass {fmt(m1)} and {fmt(m2)} on a stretched spring "
                     f"(k = {fmt(k)}, rest length {fmt(l0)}): their centre of mass stays at the "
                     f"origin, the light one moves three times as far as the heavy one, and the "
                     f"period is 2 pi sqrt(mu/k) = {fmt(period)} s with the reduced mass mu = "
                     f"{fmt(mu)}. " + ENERGY_BEHAVIOUR[integ])
    return s


def springs_plucked_string(integ):
    m, k, l0, spacing, n_free = 0.2, 20.0, 0.4, 0.5, 5
    s = Scene(integ, dt=oscillator_dt(integ, explicit_dt=0.0005), duration=3.0)
    s.what = "a chain of springs between two fixed ends, plucked: transverse wave"
    indices = [s.particle(1.0, 0.0, 0.0, fixed=True, radius=0.06)]
    for n in range(1, n_free + 1):
        vy = 1.0 if n == (n_free + 1) // 2 else 0.0
        indices.append(s.particle(m, spacing * n, 0.0, 0.0, vy, radius=0.06, color=PALETTE[1]))
    indices.append(s.particle(1.0, spacing * (n_free + 1), 0.0, fixed=True, radius=0.06))
    for a, b in zip(indices, indices[1:]):
        s.spring(a, b, k, l0)
    tension = k * (spacing - l0)
    wave_speed = math.sqrt(tension / (m / spacing))
    length = spacing * (n_free + 1)
    s.description = (f"A string of {n_free} particles (mass {fmt(m)}) and {n_free + 1} springs "
                     f"(k = {fmt(k)}, rest length {fmt(l0)}, pre-stretched to {fmt(spacing)}) "
                     "between two fixed ends; the middle particle is plucked upwards. A transverse "
                     f"wave runs along the string at about sqrt(T/rho) = {fmt(wave_speed, 3)} and "
                     f"the string swings with a period of about 2 L / c = "
                     f"{fmt(2.0 * length / wave_speed, 3)} s. " + ENERGY_BEHAVIOUR[integ])
    return s


def springs_zero_rest_length(integ):
    k, m = 1.0, 1.0
    s = Scene(integ, dt=oscillator_dt(integ), duration=6.3, viewport=(0.0, 0.0, 1.3))
    s.what = "zero-rest-length spring: elliptical orbit about the anchor"
    anchor = s.particle(1.0, 0.0, 0.0, fixed=True, radius=0.05)
    p = s.particle(m, 1.0, 0.0, 0.0, 0.5, radius=0.07, color=PALETTE[0])
    s.spring(anchor, p, k, 0.0)
    s.path(p)
    s.description = ("A zero-rest-length spring (k = 1, mass 1) pulls with force k d, like an "
                     "isotropic 2D oscillator: starting at (1, 0) with velocity (0, 0.5) the "
                     "particle traces the ellipse x = cos t, y = 0.5 sin t about the fixed anchor "
                     "and closes it at t = 2 pi ~ 6.28. " + ENERGY_BEHAVIOUR[integ])
    return s


def springs_spinning_triangle(integ):
    k, m, side, omega = 20.0, 1.0, 1.0, 2.0
    s = Scene(integ, dt=oscillator_dt(integ), duration=4.0, viewport=(0.0, 0.0, 1.2))
    s.what = "a spinning triangle of springs: centrifugal stretching, breathing"
    height = side * math.sqrt(3.0) / 2.0
    corners = []
    # Corners about the centroid at the origin: top, bottom left, bottom right.
    for n, (x, y) in enumerate(((0.0, 2.0 * height / 3.0), (-0.5 * side, -height / 3.0),
                                (0.5 * side, -height / 3.0))):
        corners.append(s.particle(m, x, y, -omega * y, omega * x, radius=0.07, color=PALETTE[n]))
    for n in range(3):
        s.spring(corners[n], corners[(n + 1) % 3], k, side)
    for c in corners:
        s.path(c, duration=1.0)
    s.description = ("Three particles on an equilateral triangle of springs at rest length "
                     f"{fmt(side)} (k = {fmt(k)}), spinning at {fmt(omega)} rad/s about their "
                     "centre: the springs stretch under the centrifugal pull, so the triangle "
                     "breathes in and out while it turns; it stays equilateral and its centre "
                     "stays at the origin. " + ENERGY_BEHAVIOUR[integ])
    return s


def springs_moving_anchor(integ):
    k, m, l0 = 10.0, 1.0, 1.0
    s = Scene(integ, dt=oscillator_dt(integ), duration=4.0, viewport=(1.5, 0.0, 2.8))
    s.what = "a fixed anchor with velocity drags a particle on a spring"
    anchor = s.particle(1.0, 0.0, 0.0, 1.0, 0.0, fixed=True, radius=0.07)
    p = s.particle(m, -1.0, 0.0, radius=0.08, color=PALETTE[0])
    s.spring(anchor, p, k, l0)
    s.path(p)
    amplitude = 1.0 / math.sqrt(k / m)
    s.description = ("The grey anchor is fixed but starts with velocity (1, 0): it moves in a "
                     "straight line at constant speed whatever the spring does. The particle, one "
                     "rest length behind it and at rest, is dragged along and oscillates about a "
                     "point one rest length behind the anchor with amplitude v / omega = "
                     f"{fmt(amplitude, 3)}. " + ENERGY_BEHAVIOUR[integ])
    return s


# --------------------------------------------------------------------------------------------
# spring damping
# --------------------------------------------------------------------------------------------
def springdamping_single(integ):
    k, m, l0, b = 10.0, 1.0, 1.0, 1.0
    s = Scene(integ, dt=oscillator_dt(integ), duration=5.0)
    s.what = "one damped spring: decaying oscillation"
    anchor = s.particle(1.0, 0.0, 0.0, fixed=True, radius=0.06)
    p = s.particle(m, 1.5, 0.0, radius=0.08, color=PALETTE[0])
    s.spring(anchor, p, k, l0, b)
    zeta = b / (2.0 * math.sqrt(k * m))
    envelope = 0.5 * math.exp(-b / (2.0 * m) * s.duration)
    s.description = (f"A damped spring (k = {fmt(k)}, rest length {fmt(l0)}, b = {fmt(b)}) to a "
                     f"fixed anchor, stretched by 0.5 and released: damping ratio "
                     f"b / (2 sqrt(k m)) = {fmt(zeta, 3)}, so it oscillates with an amplitude "
                     f"that decays like 0.5 exp(-b t / 2m), down to about {fmt(envelope, 2)} at "
                     f"t = {fmt(s.duration)}.")
    return s


def springdamping_compare(integ):
    k, m, l0 = 10.0, 1.0, 1.0
    critical = 2.0 * math.sqrt(k * m)
    s = Scene(integ, dt=oscillator_dt(integ), duration=4.0)
    s.what = "under-, critically and over-damped springs side by side"
    for n, b in enumerate((1.0, critical, 20.0)):
        y = -0.6 * n
        anchor = s.particle(1.0, 0.0, y, fixed=True, radius=0.05)
        p = s.particle(m, 1.5, y, radius=0.08, color=PALETTE[n])
        s.spring(anchor, p, k, l0, b)
    s.description = (f"Three springs (k = {fmt(k)}, rest length {fmt(l0)}, mass {fmt(m)}) "
                     "stretched by 0.5 and released. Top: b = 1, under-damped, overshoots and "
                     f"rings down. Middle: b = 2 sqrt(k m) = {fmt(critical)}, critically damped, "
                     "returns fastest without overshoot. Bottom: b = 20, over-damped, creeps back "
                     "slowly. None of them overshoots except the top one.")
    return s


def spinning_dumbbell(integ, spring_damping, drag):
    """Two particles of mass 1 on a spring (k = 20, rest length 0.8) 1 apart, spinning at 3 rad/s
    about the origin, with the given spring damping and linear drag."""
    m, k, l0, speed = 1.0, 20.0, 0.8, 1.5
    s = Scene(integ, dt=oscillator_dt(integ), duration=5.0, viewport=(0.0, 0.0, 0.9))
    a = s.particle(m, 0.5, 0.0, 0.0, speed, radius=0.07, color=PALETTE[0])
    c = s.particle(m, -0.5, 0.0, 0.0, -speed, radius=0.07, color=PALETTE[1])
    s.spring(a, c, k, l0, spring_damping)
    if drag:
        s.drag.append(drag)
    s.path(a, duration=1.0)
    s.path(c, duration=1.0)
    return s


def springdamping_spinning(integ):
    s = spinning_dumbbell(integ, spring_damping=2.0, drag=0.0)
    s.what = "a spinning damped dumbbell keeps spinning: damping acts along the spring only"
    s.description = ("Two particles on a damped spring (k = 20, rest length 0.8, b = 2), "
                     "spinning about their centre at 3 rad/s. Spring damping only resists the "
                     "relative velocity along the spring: the stretching oscillation dies out but "
                     "the dumbbell keeps spinning with constant angular momentum (compare "
                     "drag_spinning, where drag slows the rotation too).")
    return s


def springdamping_hanging_chain(integ):
    n_free, m, k, l0, b = 6, 0.1, 50.0, 0.3, 3.0
    s = Scene(integ, dt=oscillator_dt(integ), duration=5.0, viewport=(0.0, -1.2, 1.4))
    s.what = "a damped vertical chain settles to its analytic stretched length"
    s.gravity.append((0.0, -GRAVITY))
    chain = [s.particle(1.0, 0.0, 0.0, fixed=True, radius=0.05)]
    for n in range(1, n_free + 1):
        chain.append(s.particle(m, 0.0, -l0 * n, radius=0.05, color=PALETTE[1]))
    for a, c in zip(chain, chain[1:]):
        s.spring(a, c, k, l0, b)
    # The spring n (from the top, 1-based) carries the weight of the n_free - n + 1 particles below.
    bottom = -(n_free * l0 + sum((n_free - n + 1) * m * GRAVITY / k for n in range(1, n_free + 1)))
    s.description = (f"A chain of {n_free} particles (mass {fmt(m)}) on damped springs (k = "
                     f"{fmt(k)}, rest length {fmt(l0)}, b = {fmt(b)}) hangs from a fixed point, "
                     "released unstretched under gravity. It bounces and settles where each spring "
                     "carries the weight below it: spring n from the top stretches by "
                     f"(7 - n) m g / k, so the bottom particle comes to rest at y = {fmt(bottom)}.")
    return s


# --------------------------------------------------------------------------------------------
# Newtonian gravity
# --------------------------------------------------------------------------------------------
def newtoniangravity_two_bodies(integ):
    G, m, d = 1.0, 1.0, 1.0
    v = 0.5 * math.sqrt(G * 2.0 * m / d)
    period = 2.0 * math.pi * d / math.sqrt(G * 2.0 * m / d)
    s = Scene(integ, dt=oscillator_dt(integ, other_dt=0.005), duration=4.5,
              viewport=(0.0, 0.0, 0.8))
    s.what = "two equal bodies on a circular orbit about their centre of mass"
    a = s.particle(m, 0.5 * d, 0.0, 0.0, v, radius=0.06, color=PALETTE[0])
    c = s.particle(m, -0.5 * d, 0.0, 0.0, -v, radius=0.06, color=PALETTE[1])
    s.newtonian.append((a, c, G))
    s.path(a)
    s.path(c)
    s.description = (f"Two bodies of mass {fmt(m)} at distance {fmt(d)} with G = {fmt(G)}, each "
                     f"given speed sqrt(G (m1 + m2) / d) / 2 = {fmt(v, 6)} in opposite directions: "
                     "they circle their common centre of mass at the origin on one circle of "
                     f"radius 0.5, period {fmt(period)} s. " + ENERGY_BEHAVIOUR[integ])
    return s


def newtoniangravity_ellipse(integ):
    G, M, m, r = 1.0, 10.0, 0.1, 1.0
    v = 0.8 * math.sqrt(G * M / r)
    energy = 0.5 * v * v - G * M / r
    a = -G * M / (2.0 * energy)
    perihelion = 2.0 * a - r
    period = 2.0 * math.pi * math.sqrt(a ** 3 / (G * M))
    s = Scene(integ, dt=0.001, duration=2.5, viewport=(0.27, 0.0, 0.95))
    s.what = "a planet on an ellipse about a fixed sun (Kepler)"
    sun = s.particle(M, 0.0, 0.0, fixed=True, radius=0.08, color=PALETTE[4])
    p = s.particle(m, r, 0.0, 0.0, v, radius=0.04, color=PALETTE[1])
    s.newtonian.append((sun, p, G))
    s.path(p)
    s.description = (f"A planet starts at distance {fmt(r)} from a fixed sun (G M = {fmt(G * M)}) "
                     f"with 0.8 times the circular speed, {fmt(v, 6)}: it falls on a Kepler ellipse "
                     f"with semi-major axis {fmt(a)}, nearest approach {fmt(perihelion)} and "
                     f"period {fmt(period)} s, speeding up near the sun. The orbit should close "
                     "on itself; " + ENERGY_BEHAVIOUR[integ][0].lower() +
                     ENERGY_BEHAVIOUR[integ][1:])
    return s


def newtoniangravity_planets(integ):
    G, M = 1.0, 20.0
    s = Scene(integ, dt=0.001, duration=4.0, viewport=(0.0, 0.0, 2.8))
    s.what = "a free sun and three planets, all pairs attracting"
    sun = s.particle(M, 0.0, 0.0, radius=0.12, color=PALETTE[4])
    planets = []
    momentum = [0.0, 0.0]
    speeds = []
    for n, (r, angle, m) in enumerate(((1.0, 0.0, 0.1), (1.6, 90.0, 0.2), (2.4, 180.0, 0.05))):
        c, sn = direction(angle)
        v = math.sqrt(G * M / r)
        speeds.append(v)
        x, y = r * c, r * sn
        vx, vy = -v * sn, v * c
        planets.append(s.particle(m, x, y, vx, vy, radius=0.05 + 0.1 * m, color=PALETTE[n]))
        momentum[0] += m * vx
        momentum[1] += m * vy
    s.particles[sun].vx = -momentum[0] / M
    s.particles[sun].vy = -momentum[1] / M
    bodies = [sun] + planets
    for n, i in enumerate(bodies):
        for j in bodies[n + 1:]:
            s.newtonian.append((i, j, G))
    for p in planets:
        s.path(p, duration=1.0)
    s.description = (f"A free sun (mass {fmt(M)}) and three planets (masses 0.1, 0.2 and 0.05) at "
                     "radii 1, 1.6 and 2.4 with circular speeds sqrt(G M / r) = "
                     f"{', '.join(fmt(v, 3) for v in speeds)}; every pair attracts (G = 1). The "
                     "sun starts with the velocity that makes the total momentum zero, so the "
                     "centre of mass stays put. The inner planet laps the outer ones and the "
                     "planets slightly perturb each other's circles. " + ENERGY_BEHAVIOUR[integ])
    return s


# --------------------------------------------------------------------------------------------
# drag
# --------------------------------------------------------------------------------------------
def drag_coasting(integ):
    b, v0 = 1.0, 2.0
    s = Scene(integ, dt=0.01, duration=5.0, viewport=(2.0, -0.5, 2.3))
    s.what = "coasting particles slow down exponentially; stopping distance v0 m / b"
    s.drag.append(b)
    for n, m in enumerate((0.5, 1.0, 2.0)):
        p = s.particle(m, 0.0, -0.5 * n, v0, 0.0, radius=0.04 + 0.03 * m, color=PALETTE[n])
        s.path(p)
    s.description = (f"Linear drag (b = {fmt(b)}) on particles of mass 0.5, 1 and 2 launched at "
                     f"speed {fmt(v0)}: the velocity decays like exp(-b t / m), so each coasts "
                     "towards x = v0 m / b = 1, 2 and 4; exactly, at t = 5 they are at 1.00, 1.99 "
                     "and 3.67 (each Euler method is off by up to h v0 = 0.02). Heavier particles "
                     "coast farther.")
    return s


def drag_terminal_velocity(integ):
    b = 4.0
    s = Scene(integ, dt=0.01, duration=3.0, viewport=(0.5, -6.2, 6.5))
    s.what = "drag plus gravity: falling particles reach terminal velocity m g / b"
    s.gravity.append((0.0, -GRAVITY))
    s.drag.append(b)
    speeds = []
    for n, m in enumerate((0.5, 1.0, 2.0)):
        p = s.particle(m, 0.5 * n, 0.0, radius=0.06 + 0.04 * m, color=PALETTE[n])
        s.path(p)
        speeds.append(m * GRAVITY / b)
    s.description = (f"Gravity and linear drag (b = {fmt(b)}) on particles of mass 0.5, 1 and 2 "
                     "dropped from rest: each speeds up and approaches its terminal velocity "
                     f"m g / b = {', '.join(fmt(v) for v in speeds)}, with time constant m / b = "
                     "0.125, 0.25 and 0.5 s. Heavier particles fall faster.")
    return s


def drag_spinning(integ):
    b = 0.3
    s = spinning_dumbbell(integ, spring_damping=0.0, drag=b)
    s.what = "drag slows a spinning dumbbell down (angular momentum decays)"
    s.description = (f"The spinning dumbbell of springdamping_spinning with linear drag b = "
                     f"{fmt(b)} instead of spring damping: drag resists all motion, so the "
                     f"angular momentum decays like exp(-b t / m) (to {fmt(math.exp(-b * 5.0), 2)} "
                     "of its start at t = 5) and the dumbbell spins down.")
    return s


def drag_projectile(integ):
    speed, b = 8.0, 0.5
    s = Scene(integ, dt=0.01, duration=1.4, viewport=(3.5, -0.9, 3.7))
    s.what = "projectiles with drag: shorter, asymmetric trajectories"
    s.gravity.append((0.0, -GRAVITY))
    s.drag.append(b)
    for n, angle in enumerate((30.0, 45.0, 60.0)):
        c, sn = direction(angle)
        p = s.particle(1.0, 0.0, 0.0, speed * c, speed * sn, radius=0.05,
                       color=PALETTE[n])
        s.path(p)
    s.description = (f"Three projectiles of mass 1 at speed {fmt(speed)} (30, 45 and 60 degrees) "
                     f"under gravity and linear drag b = {fmt(b)}: the paths are no longer "
                     "parabolas; the way down is steeper than the way up and the 45 degree "
                     f"range is shorter than the {fmt(speed * speed / GRAVITY, 3)} it would be "
                     "without drag.")
    return s


# --------------------------------------------------------------------------------------------
# accuracy
# --------------------------------------------------------------------------------------------
def accuracy_orbit_fixed_sun(integ):
    G, M, m, r = 1.0, 10.0, 0.1, 1.0
    v = math.sqrt(G * M / r)
    period = 2.0 * math.pi * r / v
    s = Scene(integ, dt=0.001, duration=4.0, viewport=(0.0, 0.0, 1.3))
    s.what = "circular orbit about a fixed sun: radius should stay 1"
    sun = s.particle(M, 0.0, 0.0, fixed=True, radius=0.1, color=PALETTE[4])
    p = s.particle(m, r, 0.0, 0.0, v, radius=0.05, color=PALETTE[1])
    s.newtonian.append((sun, p, G))
    s.path(p)
    drift = {
        "explicit": "Explicit Euler spirals outwards: the radius grows to about 1.08 in these two "
                    "orbits.",
        "symplectic": "Symplectic Euler keeps the radius within 0.2% of 1 and the orbit closed.",
        "linearized": "Linearized implicit Euler spirals inwards: the radius shrinks to about 0.92 "
                      "in these two orbits.",
        "implicit": "Implicit Euler spirals inwards: the radius shrinks to about 0.92 in these two "
                    "orbits.",
    }[integ]
    s.description = (f"Accuracy: a light planet (mass {fmt(m)}) around a fixed sun (mass "
                     f"{fmt(M)}, G = {fmt(G)}) at radius {fmt(r)}, given the circular-orbit speed "
                     f"v = sqrt(G M / r) = sqrt(10) = {v!r}. Exactly, it stays on the circle "
                     f"of radius 1 with period 2 pi r / v = {fmt(period)} s (two orbits here). "
                     + drift)
    return s


def accuracy_orbit_free_sun(integ):
    G, M, m, r = 1.0, 10.0, 1.0, 1.0
    relative = math.sqrt(G * (M + m) / r)
    v_planet = relative * M / (M + m)
    v_sun = -relative * m / (M + m)
    period = 2.0 * math.pi * r / relative
    s = Scene(integ, dt=0.001, duration=4.0, viewport=(0.1, 0.0, 1.2))
    s.what = "two-body circular orbit with a free sun: both circle the centre of mass"
    sun = s.particle(M, 0.0, 0.0, 0.0, v_sun, radius=0.1, color=PALETTE[4])
    p = s.particle(m, r, 0.0, 0.0, v_planet, radius=0.05, color=PALETTE[1])
    s.newtonian.append((sun, p, G))
    s.path(p)
    s.path(sun)
    s.description = (f"Accuracy: a planet (mass {fmt(m)}) and a free sun (mass {fmt(M)}, G = "
                     f"{fmt(G)}) at distance {fmt(r)}. For a circular orbit the relative speed is "
                     f"sqrt(G (M + m) / r) = sqrt(11) = {relative!r}, shared against the masses "
                     f"so that the momentum is zero: planet vy = sqrt(11) M / (M + m) = "
                     f"{v_planet!r}, sun vy = -sqrt(11) m / (M + m) = {v_sun!r}. Both circle the "
                     f"centre of mass (1/11, 0) with period {fmt(period)} s; their distance should "
                     "stay 1. " + ENERGY_BEHAVIOUR[integ])
    return s


def accuracy_spring_period(integ):
    m, l0 = 1.0, 1.0
    k = 4.0 * math.pi * math.pi * m
    s = Scene(integ, dt=0.001, duration=3.0)
    s.what = "a spring with period exactly 1 s: back at x = 1.5 at t = 1, 2, 3"
    anchor = s.particle(1.0, 0.0, 0.0, fixed=True, radius=0.06)
    p = s.particle(m, 1.5, 0.0, radius=0.08, color=PALETTE[0])
    s.spring(anchor, p, k, l0)
    s.description = (f"Accuracy: a spring with k = 4 pi^2 = {k!r} and a particle of mass "
                     f"{fmt(m)} has period exactly 1 s, so the particle, released at x = 1.5, "
                     "should be back there at t = 1, 2 and 3 with zero velocity. Compare the "
                     "amplitude and phase after three periods: " +
                     ENERGY_BEHAVIOUR[integ][0].lower() + ENERGY_BEHAVIOUR[integ][1:])
    return s


# --------------------------------------------------------------------------------------------
# systems
# --------------------------------------------------------------------------------------------
PENDULUM_DT = {"explicit": 0.0005, "symplectic": 0.001, "linearized": 0.01, "implicit": 0.01}


def system_multiple_pendulum(integ):
    links, length, m, k, b = 5, 0.5, 1.0, 1.0e4, 20.0
    s = Scene(integ, dt=PENDULUM_DT[integ], duration=5.0,
              viewport=(0.0, -1.0, 2.9))
    s.what = "a 5-link pendulum of stiff damped springs, released horizontally"
    s.gravity.append((0.0, -GRAVITY))
    chain = [s.particle(1.0, 0.0, 0.0, fixed=True, radius=0.06)]
    for n in range(1, links + 1):
        chain.append(s.particle(m, length * n, 0.0, radius=0.07,
                                color=PALETTE[(n - 1) % len(PALETTE)]))
    for a, c in zip(chain, chain[1:]):
        s.spring(a, c, k, length, b, radius=0.02)
    s.path(chain[-1], duration=1.0)
    look = {
        "explicit": "Explicit Euler needs the small step (0.0005) for the stiff springs, whose "
                    "damping keeps it stable; the swing keeps most of its energy.",
        "symplectic": "Symplectic Euler (step 0.001) keeps most of the swing's energy; only the "
                      "springs' damping removes some when the links jerk.",
        "linearized": "At this large step (0.01) linearized implicit Euler damps the stiff "
                      "stretching at once and slowly drains the swing's energy: the chain calms "
                      "down over the five seconds.",
        "implicit": "At this large step (0.01) implicit Euler damps the stiff stretching at once "
                    "and slowly drains the swing's energy: the chain calms down over the five "
                    "seconds.",
    }[integ]
    s.description = (f"A multiple pendulum: {links} particles of mass {fmt(m)} on stiff damped "
                     f"springs (k = {fmt(k)}, b = {fmt(b)}, length {fmt(length)}) hanging from a "
                     "fixed point, released horizontally under gravity. It swings chaotically "
                     "while the links stay nearly rigid (they stretch by a few percent, up to "
                     "about 8% when the chain whips). "
                     + look)
    return s


def system_elastic_pendulum(integ):
    m, l0 = 1.0, 1.0
    k = 3.0 * m * GRAVITY / l0  # equilibrium length 4/3 l0, spring frequency twice the swing's
    hang = l0 + m * GRAVITY / k
    r = hang + 0.15
    c, sn = direction(-90.0 + 4.0)
    s = Scene(integ, dt=oscillator_dt(integ), duration=8.0, viewport=(0.0, -1.0, 1.0))
    s.what = "elastic pendulum at 2:1 resonance: bouncing turns into swinging"
    s.gravity.append((0.0, -GRAVITY))
    anchor = s.particle(1.0, 0.0, 0.0, fixed=True, radius=0.05)
    p = s.particle(m, r * c, r * sn, radius=0.08, color=PALETTE[0])
    s.spring(anchor, p, k, l0)
    s.path(p, duration=2.0)
    s.description = (f"An elastic pendulum: a particle of mass {fmt(m)} on a spring of rest "
                     f"length {fmt(l0)} with k = 3 m g / l0 = {fmt(k)}, so it hangs at length "
                     f"{fmt(hang)} and its bouncing frequency is exactly twice its swinging "
                     "frequency. Started stretched 0.15 below that and 4 degrees off vertical, "
                     "it first bounces, then the bouncing slowly turns into swinging "
                     "(autoparametric resonance): without numerical damping the sideways swing "
                     "grows from 0.1 to about 0.3 by t = 8, when nearly all the bouncing "
                     "energy has moved into it. " + ENERGY_BEHAVIOUR[integ])
    return s


CANTILEVER_DT = {"explicit": 0.0002, "symplectic": 0.0005, "linearized": 0.005,
                 "implicit": 0.005}


def system_cantilever(integ):
    columns, spacing, height, m, k, b = 9, 0.25, 0.25, 0.1, 2.0e4, 10.0
    s = Scene(integ, dt=CANTILEVER_DT[integ], duration=3.0,
              viewport=(0.9, -0.3, 1.3))
    s.what = "a cantilever: triangulated strip of springs, one end fixed, sags and bounces"
    s.gravity.append((0.0, -GRAVITY))
    top, bottom = [], []
    for c in range(columns):
        fixed = c == 0
        color = None if fixed else PALETTE[1]
        top.append(s.particle(m, spacing * c, 0.0, fixed=fixed, radius=0.03, color=color))
        bottom.append(s.particle(m, spacing * c, -height, fixed=fixed, radius=0.03, color=color))
    for c in range(columns - 1):
        s.spring(top[c], top[c + 1], k, b=b)
        s.spring(bottom[c], bottom[c + 1], k, b=b)
        # Alternate the diagonals so the strip is symmetric overall.
        if c % 2 == 0:
            s.spring(top[c], bottom[c + 1], k, b=b)
        else:
            s.spring(bottom[c], top[c + 1], k, b=b)
    for c in range(1, columns):
        s.spring(top[c], bottom[c], k, b=b)
    s.path(top[-1], duration=1.0)
    s.description = (f"A cantilever beam: a strip of {2 * columns} particles (mass {fmt(m)}, "
                     f"length {fmt(spacing * (columns - 1))}) triangulated by springs (k = "
                     f"{fmt(k)}, b = {fmt(b)}), its left end fixed, released straight under "
                     "gravity. It bends: its free end swings between 0 and about -0.25 around "
                     "its sagged rest position near -0.13, once every 0.6 s, the top springs "
                     "stretching and the bottom ones compressing by up to 3%. " + {
                         "explicit": "Explicit Euler needs a tiny step (0.0002) for the stiff "
                                     "springs.",
                         "symplectic": "Symplectic Euler needs a small step (0.0005) for the "
                                       "stiff springs; the bending swing keeps nearly all its "
                                       "energy.",
                         "linearized": "Linearized implicit Euler takes ten times larger steps "
                                       "(0.005) and damps the swing noticeably in three seconds.",
                         "implicit": "Implicit Euler takes ten times larger steps (0.005) and "
                                     "damps the swing noticeably in three seconds.",
                     }[integ])
    return s


# (category, what, builder) in the order of the README table.
MILESTONE_SCENES = [
    ("inertia", "single", inertia_single),
    ("inertia", "several", inertia_several),
    ("simplegravity", "projectile", simplegravity_projectile),
    ("simplegravity", "fixed_moving", simplegravity_fixed_moving),
    ("simplegravity", "masses", simplegravity_masses),
    ("springs", "single", springs_single),
    ("springs", "two_masses", springs_two_masses),
    ("springs", "plucked_string", springs_plucked_string),
    ("springs", "zero_rest_length", springs_zero_rest_length),
    ("springs", "spinning_triangle", springs_spinning_triangle),
    ("springs", "moving_anchor", springs_moving_anchor),
    ("springdamping", "single", springdamping_single),
    ("springdamping", "compare", springdamping_compare),
    ("springdamping", "spinning", springdamping_spinning),
    ("springdamping", "hanging_chain", springdamping_hanging_chain),
    ("newtoniangravity", "two_bodies", newtoniangravity_two_bodies),
    ("newtoniangravity", "ellipse", newtoniangravity_ellipse),
    ("newtoniangravity", "planets", newtoniangravity_planets),
    ("drag", "coasting", drag_coasting),
    ("drag", "terminal_velocity", drag_terminal_velocity),
    ("drag", "spinning", drag_spinning),
    ("drag", "projectile", drag_projectile),
    ("accuracy", "orbit_fixed_sun", accuracy_orbit_fixed_sun),
    ("accuracy", "orbit_free_sun", accuracy_orbit_free_sun),
    ("accuracy", "spring_period", accuracy_spring_period),
    ("system", "multiple_pendulum", system_multiple_pendulum),
    ("system", "elastic_pendulum", system_elastic_pendulum),
    ("system", "cantilever", system_cantilever),
]

# folder -> [(integrator family, file-name prefix)]
MILESTONES = {
    "t1m1": [("explicit", "")],
    "t1m2": [("symplectic", "symplectic_"), ("linearized", "linearized_")],
    "t1m3": [("implicit", "")],
}
