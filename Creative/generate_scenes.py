#!/usr/bin/env python3
"""Writes the creative scenes of this folder (see README.md).

The scenes are ordinary FOSSSim scene files; this script only saves typing hundreds of
particles by hand. Run it from anywhere: python3 Creative/generate_scenes.py
"""

import colorsys
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def rgb(h, s, v):
    return colorsys.hsv_to_rgb(h % 1.0, s, v)


def fmt(x):
    return f"{x:.6g}"


class SceneWriter:
    def __init__(self, dim=2):
        self.dim = dim
        self.lines = []
        self.particles = 0
        self.edges = 0

    def add(self, line):
        self.lines.append("  " + line)

    def particle(self, pos, vel, m, fixed=False, radius=0.1, color=None, tag=None):
        names = ["px", "py", "pz"][: self.dim]
        vnames = ["vx", "vy", "vz"][: self.dim]
        attributes = f'm="{fmt(m)}" ' + " ".join(f'{n}="{fmt(p)}"' for n, p in zip(names, pos))
        attributes += " " + " ".join(f'{n}="{fmt(v)}"' for n, v in zip(vnames, vel))
        attributes += f' fixed="{1 if fixed else 0}" radius="{fmt(radius)}"'
        if tag:
            attributes += f' tag="{tag}"'
        self.add(f"<particle {attributes}/>")
        index = self.particles
        self.particles += 1
        if color is not None:
            self.add(f'<particlecolor i="{index}" r="{fmt(color[0])}" g="{fmt(color[1])}" b="{fmt(color[2])}"/>')
        return index

    def edge(self, i, j, radius=0.015, color=None):
        self.add(f'<edge i="{i}" j="{j}" radius="{fmt(radius)}"/>')
        index = self.edges
        self.edges += 1
        if color is not None:
            self.add(f'<edgecolor i="{index}" r="{fmt(color[0])}" g="{fmt(color[1])}" b="{fmt(color[2])}"/>')
        return index

    def spring(self, edge, k, l0, b=0.0):
        extra = f' b="{fmt(b)}"' if b else ""
        self.add(f'<springforce edge="{edge}" k="{fmt(k)}" l0="{fmt(l0)}"{extra}/>')

    def path(self, i, duration, color):
        self.add(f'<particlepath i="{i}" duration="{fmt(duration)}" r="{fmt(color[0])}" g="{fmt(color[1])}" b="{fmt(color[2])}"/>')

    def checks(self, n, squares, dark, light):
        """Colours the vertices of a generated n x n cloth (vertex (r, c) is r n + c) in a
        checkerboard of about `squares` x `squares` checks."""
        for r in range(n):
            for c in range(n):
                color = dark if (r * squares // n + c * squares // n) % 2 else light
                self.add(f'<particlecolor i="{r * n + c}" r="{fmt(color[0])}" g="{fmt(color[1])}" '
                         f'b="{fmt(color[2])}"/>')

    def save(self, name, header):
        root = '<scene dim="3">' if self.dim == 3 else "<scene>"
        text = "\n".join(["<!-- Written by Creative/generate_scenes.py; see Creative/README.md -->", root]
                         + ["  " + h for h in header] + self.lines + ["</scene>", ""])
        with open(os.path.join(HERE, name), "w") as f:
            f.write(text)
        print(f"{name}: {self.particles} particles, {self.edges} edges")


def vortex_spiral():
    """Six coloured spokes held by soft springs to a heavy centre and spun by vortex forces:
    inner particles circle faster than outer ones, so the spokes wind into a spiral galaxy."""
    s = SceneWriter()
    centre = s.particle((0, 0), (0, 0), 1.0, fixed=True, radius=0.13, color=(1.0, 0.93, 0.75))
    arms, per_arm = 6, 40
    for a in range(arms):
        hue = 0.55 + 0.45 * a / arms
        for k in range(per_arm):
            r = 0.32 + 2.75 * k / (per_arm - 1)
            angle = 2 * math.pi * a / arms
            pos = (r * math.cos(angle), r * math.sin(angle))
            fade = 1.0 - 0.55 * k / (per_arm - 1)
            color = rgb(hue + 0.08 * k / per_arm, 0.75, fade)
            j = s.particle(pos, (0, 0), 0.02, radius=0.055 - 0.025 * k / per_arm, color=color)
            e = s.edge(centre, j, radius=0.0)  # an invisible tether
            s.spring(e, 6.0, r)
            s.add(f'<vortexforce i="{centre}" j="{j}" kbs="1.1" kvc="0.03"/>')
            if k % 4 == 1:
                s.path(j, 0.45, rgb(hue + 0.08 * k / per_arm, 0.6, 0.85 * fade))
    s.save("vortex_spiral.xml", [
        '<description text="Vortex spiral: six spokes wound into a galaxy by vortex forces (symplectic Euler)"/>',
        '<duration time="8.0"/>',
        '<integrator type="symplectic-euler" dt="0.004"/>',
        '<maxsimfreq max="250"/>',
        '<backgroundcolor r="0.02" g="0.02" b="0.06"/>',
        '<viewport cx="0" cy="0" size="3.3"/>',
    ])


def fountain():
    """Water drops under gravity and light drag; the ParticleFountain scene tag sends every drop
    that falls below the basin back to the spout with a random upward velocity."""
    s = SceneWriter()
    stone = (0.55, 0.52, 0.5)
    water = (0.16, 0.32, 0.55)
    # Basin, water line and column: fixed and only decorative.
    corners = [(-1.7, -1.05), (-1.7, -1.45), (1.7, -1.45), (1.7, -1.05)]
    ids = [s.particle(c, (0, 0), 1, fixed=True, radius=0.06, color=stone) for c in corners]
    for a, b in zip(ids, ids[1:]):
        s.edge(a, b, radius=0.06, color=stone)
    shore_l = s.particle((-1.62, -1.25), (0, 0), 1, fixed=True, radius=0.0, color=water)
    shore_r = s.particle((1.62, -1.25), (0, 0), 1, fixed=True, radius=0.0, color=water)
    s.edge(shore_l, shore_r, radius=0.025, color=water)
    base = s.particle((0, -1.45), (0, 0), 1, fixed=True, radius=0.05, color=stone)
    spout = s.particle((0, -0.06), (0, 0), 1, fixed=True, radius=0.09, color=(0.75, 0.7, 0.62))
    s.edge(base, spout, radius=0.07, color=stone)
    # Drops already in flight at t = 0, at evenly spread phases of their flights.
    g = 9.81
    drops = 260
    for k in range(drops):
        u1 = (k * 0.618034) % 1.0
        u2 = (k * 0.414214 + 0.3) % 1.0
        vx, vy = 2.0 * u1 - 1.0, 4.0 + 2.0 * u2
        flight = (vy + math.sqrt(vy * vy + 2 * g * 1.25)) / g
        t = flight * ((k * 0.7548777) % 1.0)
        pos = (vx * t, vy * t - 0.5 * g * t * t)
        vel = (vx, vy - g * t)
        color = rgb(0.52 + 0.1 * u2, 0.35 + 0.5 * u1, 0.95)
        s.particle(pos, vel, 0.01, radius=0.022 + 0.016 * u2, color=color, tag="teleport")
    s.add('<simplegravity fx="0" fy="-9.81"/>')
    s.add('<dragdamping b="0.002"/>')
    s.save("fountain.xml", [
        '<description text="Fountain: the ParticleFountain scene tag recycles every drop (explicit Euler)"/>',
        '<duration time="8.0"/>',
        '<integrator type="explicit-euler" dt="0.004"/>',
        '<maxsimfreq max="250"/>',
        '<scenetag tag="ParticleFountain"/>',
        '<backgroundcolor r="0.05" g="0.07" b="0.12"/>',
        '<viewport cx="0" cy="0.25" size="1.85"/>',
    ])


def pendulum_wave():
    """Fifteen pendulums seen from above, their lengths chosen so that pendulum k swings 6 + k
    times in 24 s: they fall in and out of step in travelling waves and line up again at the
    end. Stiff springs stand in for the strings (linearized implicit Euler, 3D)."""
    s = SceneWriter(dim=3)
    g, cycle, count, lead, offset = 9.81, 24.0, 15, 6, 0.15
    k_spring, mass = 4000.0, 0.05
    for k in range(count):
        period = cycle / (lead + k)
        # The length whose large-amplitude period is `period` when pulled `offset` sideways.
        length = g * (period / (2 * math.pi)) ** 2
        for _ in range(30):
            theta = math.asin(offset / length)
            correction = 1 + theta ** 2 / 16 + 11 * theta ** 4 / 3072
            length = g * (period / (2 * math.pi * correction)) ** 2
        x = -1.2 + 2.4 * k / (count - 1)
        pivot = s.particle((x, 0, 0), (0, 0, 0), 1, fixed=True, radius=0.018, color=(0.35, 0.35, 0.4))
        height = math.sqrt(length * length - offset * offset)
        color = rgb(0.95 * k / count, 0.65, 0.95)
        bob = s.particle((x, offset, -height), (0, 0, 0), mass, radius=0.06, color=color)
        e = s.edge(pivot, bob, radius=0.006, color=(0.55, 0.55, 0.6))
        # Rest length shortened by the static stretch m g / k, so that the hanging string has
        # the computed length.
        s.spring(e, k_spring, length - mass * g / k_spring)
    s.add('<simplegravity fx="0" fy="0" fz="-9.81"/>')
    s.save("pendulum_wave.xml", [
        '<description text="Pendulum wave seen from above: 15 pendulums swing 6 to 20 times in 24 s (linearized implicit Euler, 3D)"/>',
        '<duration time="24.0"/>',
        '<integrator type="linearized-implicit-euler" dt="0.0005"/>',
        '<maxsimfreq max="2000"/>',
        '<backgroundcolor r="0.97" g="0.96" b="0.93"/>',
        '<viewport cx="0" cy="0" size="0.45"/>',
    ])


def ropes():
    """Seven ropes of stiff, damped springs hang from one pin, held out in a fan and let go:
    they fall, whip and tangle. Stiff springs call for an implicit method (implicit Euler with
    Newton's method), which also damps the ropes' stretching."""
    s = SceneWriter()
    pin = s.particle((0, 0), (0, 0), 1, fixed=True, radius=0.07, color=(0.25, 0.25, 0.3))
    count, nodes = 7, 36
    k_spring, damping, mass = 3000.0, 0.05, 0.01
    for r in range(count):
        length = 1.3 + 1.0 * r / (count - 1)
        segment = length / nodes
        angle = math.radians(75 - 14 * r)
        color = rgb(0.02 + 0.62 * r / (count - 1), 0.8, 0.9)
        previous = pin
        for n in range(1, nodes + 1):
            pos = (n * segment * math.cos(angle), n * segment * math.sin(angle))
            tip = n == nodes
            j = s.particle(pos, (0, 0), mass * (4 if tip else 1), radius=0.07 if tip else 0.0,
                           color=color)
            e = s.edge(previous, j, radius=0.022, color=color)
            s.spring(e, k_spring, segment, damping)
            previous = j
        s.path(previous, 1.2, rgb(0.02 + 0.62 * r / (count - 1), 0.6, 0.95))
    s.add('<simplegravity fx="0" fy="-9.81"/>')
    s.save("ropes.xml", [
        '<description text="Seven ropes fall from a fan, whip and tangle (implicit Euler, Newton)"/>',
        '<duration time="8.0"/>',
        '<integrator type="implicit-euler" dt="0.004"/>',
        '<maxsimfreq max="250"/>',
        '<backgroundcolor r="0.99" g="0.98" b="0.96"/>',
        '<viewport cx="0" cy="-0.35" size="2.6"/>',
    ])


def tablecloth():
    """A checkered tablecloth of 49 x 49 vertices, held at the two corners of one edge, drops
    from flat, swings and folds in a light breeze: the local/global solver of Liu et al. 2013
    on a generated cloth (3D). The checks are the vertices' colours, which the shaded surface
    takes; the camera is a <camera3d> looking at where the cloth will hang."""
    s = SceneWriter(dim=3)
    n, squares = 49, 8
    s.add(f'<generate type="cloth" nx="{n}" ny="{n}" plane="xz" pin="corners" k="800" b="0.002" '
          'mass="total" total="0.6"/>')
    s.checks(n, squares, (0.8, 0.13, 0.12), (0.97, 0.94, 0.86))
    s.add('<simplegravity fx="0" fy="-9.8" fz="0"/>')
    s.add('<constantforce fx="0.0002" fy="0" fz="0.0005"/>')
    s.save("tablecloth.xml", [
        '<description text="A checkered tablecloth held at two corners drops, swings and folds in a light breeze (local/global, 3D)"/>',
        '<duration time="6.0"/>',
        '<integrator type="local-global" dt="0.01666666666666667" iterations="15"/>',
        '<maxsimfreq max="60"/>',
        '<backgroundcolor r="0.93" g="0.95" b="0.97"/>',
        '<camera3d yaw="32" pitch="18" tx="-0.05" ty="-0.42" tz="0.15" distance="3.2"/>',
    ])


def billiards():
    """A break: the cue ball hits a rack of fifteen balls on a table bounded by four cushions
    (half-planes drawn in their colour). Simple impulses with a coefficient of restitution of
    0.95 answer every contact, Gauss-Seidel in the course's pair order; light drag stands in for
    the cloth's rolling resistance (symplectic Euler)."""
    s = SceneWriter()
    r, half_w, half_h = 0.09, 2.0, 1.0
    # Pockets: fixed, so they act as round bumpers too; drawn first, under the balls.
    for x in (-half_w, 0.0, half_w):
        for y in (-half_h, half_h):
            inset = 0.0 if x == 0.0 else 0.02
            s.particle((x - math.copysign(inset, x) if x else 0.0, y - math.copysign(inset, y)),
                       (0, 0), 1, fixed=True, radius=0.13, color=(0.04, 0.04, 0.04))
    solids = [(0.98, 0.8, 0.1), (0.1, 0.25, 0.8), (0.85, 0.1, 0.1), (0.45, 0.15, 0.6),
              (0.98, 0.5, 0.05), (0.1, 0.62, 0.32), (0.5, 0.12, 0.08)]
    colors = solids + [(0.03, 0.03, 0.03)] + [tuple(0.55 * c + 0.45 for c in col) for col in solids]
    order = [0, 8, 1, 9, 7, 2, 10, 3, 11, 4, 12, 5, 13, 6, 14]  # the 8 ball in the middle
    gap = 0.002  # rack balls just apart, so that no pair starts in contact
    row_step = (2 * r + gap) * math.sqrt(3) / 2
    apex = 0.9
    k = 0
    for row in range(5):
        for n in range(row + 1):
            pos = (apex + row * row_step, (n - row / 2) * (2 * r + gap))
            s.particle(pos, (0, 0), 0.16, radius=r, color=colors[order[k]])
            k += 1
    cue = s.particle((-1.1, 0.012), (10.0, 0), 0.17, radius=r, color=(0.97, 0.96, 0.9))
    s.path(cue, 1.0, (0.97, 0.96, 0.9))
    cushion = (0.3, 0.16, 0.07)
    for px, py, nx, ny in ((-half_w, 0, 1, 0), (half_w, 0, -1, 0), (0, -half_h, 0, 1),
                           (0, half_h, 0, -1)):
        s.add(f'<halfplane px="{fmt(px)}" py="{fmt(py)}" nx="{fmt(nx)}" ny="{fmt(ny)}"/>')
    for h in range(4):
        s.add(f'<halfplanecolor i="{h}" r="{fmt(cushion[0])}" g="{fmt(cushion[1])}" b="{fmt(cushion[2])}"/>')
    s.add('<collision type="simple" COR="0.95"/>')
    s.add('<dragdamping b="0.045"/>')
    s.save("billiards.xml", [
        '<description text="Billiards: a break on a table with four cushions (simple impulses, COR 0.95, symplectic Euler)"/>',
        '<duration time="8.0"/>',
        '<integrator type="symplectic-euler" dt="0.001666666666666667"/>',
        '<maxsimfreq max="600"/>',
        '<backgroundcolor r="0.05" g="0.42" b="0.2"/>',
        '<viewport cx="0" cy="0" size="1.2"/>',
    ])


def cloth_on_sphere():
    """A checkered cloth of 81 x 81 vertices dropped flat over a sphere onto a floor: penalty
    contact with the sphere and the half-space, which the local/global solver takes into its
    global matrix (3D). Seen through a <camera3d>."""
    s = SceneWriter(dim=3)
    n, squares = 81, 9
    s.add(f'<generate type="cloth" nx="{n}" ny="{n}" width="1.6" height="1.6" plane="xz" '
          'pin="none" k="200" b="0.01" mass="total" total="0.4" tx="0" ty="0.5" tz="-0.8"/>')
    s.checks(n, squares, (0.12, 0.3, 0.62), (0.95, 0.93, 0.86))
    s.add('<sphere px="0" py="0" pz="0" radius="0.35"/>')
    s.add('<spherecolor i="0" r="0.9" g="0.55" b="0.15"/>')
    s.add('<halfplane px="0" py="-0.4" pz="0" nx="0" ny="1" nz="0"/>')
    s.add('<halfplanecolor i="0" r="0.72" g="0.7" b="0.66"/>')
    # The thickness must stay below the vertex spacing (0.02) minus two vertex radii (2 x 0.003):
    # a larger one makes neighbouring vertices of the cloth a contact, a penalty force that
    # local/global takes explicitly, and the cloth blows up at once (0.015 does). A smaller one
    # lets more of the sphere show through the cloth in pictures (see README.md).
    s.add('<collision type="penalty" k="1000" thickness="0.01"/>')
    s.add('<simplegravity fx="0" fy="-9.8" fz="0"/>')
    s.save("cloth_on_sphere.xml", [
        '<description text="An 81 x 81 cloth dropped over a sphere onto a floor (penalty contact, local/global, 3D)"/>',
        '<duration time="4.0"/>',
        '<integrator type="local-global" dt="0.01666666666666667" iterations="10"/>',
        '<maxsimfreq max="60"/>',
        '<backgroundcolor r="0.93" g="0.95" b="0.97"/>',
        '<camera3d yaw="30" pitch="25" tx="0" ty="-0.1" tz="0" distance="3"/>',
    ])

def soft_bodies():
    """Two soft 2D bodies made of constant strain triangles (Theme 4) fall onto a floor and a
    ramp (half-planes, Theme 2): a disc of rings of triangles and a square block. The penalty
    force (k 2000, thickness 0.01) keeps every particle out of the half-planes and off the
    other body's boundary edges; symplectic Euler with a small step keeps it all stable. Render it coloured by strain
    to see where the bodies are squeezed on impact."""
    s = SceneWriter()
    E, nu, density = 300.0, 0.3, 1.0
    triangles = []

    def add_triangle(a, b, c, pts):
        (ax, ay), (bx, by), (cx, cy) = pts[a], pts[b], pts[c]
        if (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) < 0:  # counter-clockwise
            b, c = c, b
        triangles.append((a, b, c))

    # The disc: a centre and rings of 6 k particles on circles of radius k h.
    rings, h, centre, vel = 4, 0.07, (-0.55, 0.75), (0.6, 0.0)
    pts, index = [], []
    pts.append(centre)
    ring_start = [0]
    for k in range(1, rings + 1):
        ring_start.append(len(pts))
        for j in range(6 * k):
            a = 2 * math.pi * j / (6 * k)
            pts.append((centre[0] + k * h * math.cos(a), centre[1] + k * h * math.sin(a)))
    # Triangulate ring k-1 to ring k by walking both rings in angle.
    for k in range(1, rings + 1):
        inner = [0] if k == 1 else list(range(ring_start[k - 1], ring_start[k - 1] + 6 * (k - 1)))
        outer = list(range(ring_start[k], ring_start[k] + 6 * k))
        def angle(i):
            x, y = pts[i][0] - centre[0], pts[i][1] - centre[1]
            return math.atan2(y, x) % (2 * math.pi)
        if k == 1:
            for j in range(6):
                add_triangle(0, outer[j], outer[(j + 1) % 6], pts)
            continue
        i = o = 0
        n_in, n_out = len(inner), len(outer)
        while i < n_in or o < n_out:
            a_in = angle(inner[(i + 1) % n_in]) if i + 1 < n_in else 2 * math.pi
            a_out = angle(outer[(o + 1) % n_out]) if o + 1 < n_out else 2 * math.pi
            if o < n_out and (i >= n_in or a_out <= a_in):
                add_triangle(inner[i % n_in], outer[o], outer[(o + 1) % n_out], pts)
                o += 1
            else:
                add_triangle(inner[i], inner[(i + 1) % n_in], outer[o % n_out], pts)
                i += 1
    disc = pts
    # The block: an n x n grid of particles, each square cut along alternating diagonals.
    n, side, origin = 6, 0.08, (0.25, 0.55)
    base = len(disc)
    block = [(origin[0] + c * side, origin[1] + r * side) for r in range(n) for c in range(n)]
    pts = disc + block
    for r in range(n - 1):
        for c in range(n - 1):
            a, b = base + r * n + c, base + r * n + c + 1
            d, e = base + (r + 1) * n + c, base + (r + 1) * n + c + 1
            if (r + c) % 2 == 0:
                add_triangle(a, b, e, pts)
                add_triangle(a, e, d, pts)
            else:
                add_triangle(a, b, d, pts)
                add_triangle(b, e, d, pts)
    # Lumped masses: a third of each triangle's area times the density.
    mass = [0.0] * len(pts)
    for a, b, c in triangles:
        (ax, ay), (bx, by), (cx, cy) = pts[a], pts[b], pts[c]
        area = 0.5 * abs((bx - ax) * (cy - ay) - (by - ay) * (cx - ax))
        for p in (a, b, c):
            mass[p] += density * area / 3.0
    for p, pos in enumerate(pts):
        v = vel if p < base else (-0.3, 0.0)
        s.particle(pos, v, mass[p], radius=0.008, color=(0.15, 0.2, 0.35))
    # Boundary edges (sides of one triangle only): the penalty force keeps the other body's
    # particles off them, so the bodies push each other apart instead of interpenetrating.
    sides = {}
    for a, b, c in triangles:
        for e in ((a, b), (b, c), (c, a)):
            key = (min(e), max(e))
            sides[key] = sides.get(key, 0) + 1
    for (a, b), count in sorted(sides.items()):
        if count == 1:
            s.edge(a, b, radius=0.004, color=(0.15, 0.2, 0.35))
    for a, b, c in triangles:
        s.add(f'<elasticbodycstforce i1="{a}" i2="{b}" i3="{c}" youngsmodulus="{fmt(E)}" '
              f'poissonratio="{fmt(nu)}"/>')
    s.add('<simplegravity fx="0" fy="-9.81"/>')
    s.add('<dragdamping b="0.003"/>')
    slope = (math.sin(0.35), math.cos(0.35))
    for px, py, nx, ny in ((0, -0.2, 0, 1), (-1.1, 0.0, slope[0], slope[1]), (0.8, 0, -1, 0)):
        s.add(f'<halfplane px="{fmt(px)}" py="{fmt(py)}" nx="{fmt(nx)}" ny="{fmt(ny)}"/>')
    for h in range(3):
        s.add(f'<halfplanecolor i="{h}" r="0.55" g="0.5" b="0.45"/>')
    s.add('<collision type="penalty" k="2000" thickness="0.01"/>')
    s.save("soft_bodies.xml", [
        '<description text="Soft bodies: a disc and a block of constant strain triangles fall onto a floor and a ramp (penalty contact, symplectic Euler)"/>',
        '<duration time="4.0"/>',
        '<integrator type="symplectic-euler" dt="0.0005"/>',
        '<maxsimfreq max="2000"/>',
        '<viewport cx="-0.05" cy="0.4" size="0.9"/>',
    ])


def hair_strand():
    """A curly strand of hair: a chain of particles held by elastic springs (stiff, so it
    barely stretches) and bending hinges whose rest angle curls it. Held at its root, it starts
    straight and horizontal, swings down under gravity and curls up as it goes; implicit Euler
    (Newton) takes the stiff springs in its stride."""
    s = SceneWriter()
    n, seg = 31, 0.04
    for k in range(n):
        t = k / (n - 1)
        color = rgb(0.08 - 0.06 * t, 0.75, 0.35 + 0.5 * t)
        s.particle((-0.6 + k * seg, 0.6), (0, 0), 0.01 if k else 1.0, fixed=(k == 0),
                   radius=0.012 if k else 0.03, color=color)
    for k in range(n - 1):
        s.add(f'<elasticbodyspringforce i1="{k}" i2="{k + 1}" alpha="{fmt(200.0)}" l0="{fmt(seg)}"/>')
    for k in range(1, n - 1):
        theta0 = 0.05 + 0.3 * (k / (n - 2)) ** 1.5  # straighter at the root, curlier at the tip
        s.add(f'<elasticbodybendingforce i1="{k - 1}" i2="{k}" i3="{k + 1}" alpha="{fmt(0.2)}" '
              f'theta0="{fmt(theta0)}"/>')
    s.add('<simplegravity fx="0" fy="-9.81"/>')
    s.add('<dragdamping b="0.002"/>')
    s.path(n - 1, 0.8, (0.85, 0.45, 0.2))
    s.save("hair_strand.xml", [
        '<description text="A curly hair strand: elastic springs and bending hinges with curled rest angles, held at the root, swings under gravity (implicit Euler)"/>',
        '<duration time="6.0"/>',
        '<integrator type="implicit-euler" dt="0.004"/>',
        '<maxsimfreq max="250"/>',
        '<backgroundcolor r="0.97" g="0.96" b="0.93"/>',
        '<viewport cx="0" cy="0.1" size="0.9"/>',
    ])



class RigidSceneWriter:
    """Theme 3 scenes: rigid bodies from vertices (point masses), hulls as repeated p
    attributes, clockwise, as the course's files write them."""

    def __init__(self):
        self.vertices = []
        self.bodies = []
        self.extra = []

    def body(self, points, vel=(0, 0), omega=0.0, r=0.1, fixed=False, mass=1.0, color=None):
        indices = []
        for x, y in points:
            indices.append(len(self.vertices))
            self.vertices.append(f'<rigidbodyvertex x="{fmt(x)}" y="{fmt(y)}" m="{fmt(mass)}"/>')
        hull = " ".join(f'p="{i}"' for i in indices)
        fixed_attribute = ' fixed="1"' if fixed else ""
        self.bodies.append(f'<rigidbody {hull} vx="{fmt(vel[0])}" vy="{fmt(vel[1])}" '
                           f'omega="{fmt(omega)}" r="{fmt(r)}"{fixed_attribute}/>')
        index = len(self.bodies) - 1
        if color is not None:
            self.extra.append(f'<rigidbodycolor body="{index}" r="{fmt(color[0])}" g="{fmt(color[1])}" '
                              f'b="{fmt(color[2])}"/>')
        return index

    def add(self, line):
        self.extra.append(line)

    def save(self, name, header):
        lines = ["<!-- Written by Creative/generate_scenes.py; see Creative/README.md -->", "<scene>",
                 '  <simtype type="rigid-body"/>'] + ["  " + h for h in header]
        lines += ["  " + v for v in self.vertices] + ["  " + b for b in self.bodies]
        lines += ["  " + e for e in self.extra] + ["</scene>", ""]
        with open(os.path.join(HERE, name), "w") as f:
            f.write("\n".join(lines))
        print(f"{name}: {len(self.bodies)} rigid bodies, {len(self.vertices)} vertices")


def box(x0, y0, x1, y1):
    """The corners of an axis-aligned box, clockwise."""
    return [(x0, y1), (x1, y1), (x1, y0), (x0, y0)]


def rigid_tower():
    s = RigidSceneWriter()
    s.body(box(-8, -1, 8, 0), r=0.15, fixed=True, color=(0.45, 0.42, 0.4))
    # A tower of ten blocks, alternately wide and tall, 0.2 apart (within the radii: resting).
    y = 0.25
    for k in range(10):
        w, h = (1.6, 0.5) if k % 2 == 0 else (1.2, 0.7)
        s.body(box(2 - w / 2, y, 2 + w / 2, y + h), color=rgb(0.05 + 0.06 * k, 0.6, 0.9))
        y += h + 0.2
    # A heavy octagon thrown at the tower's upper half.
    octagon = [(-5 + 0.6 * math.cos(-2 * math.pi * k / 8), 5 + 0.6 * math.sin(-2 * math.pi * k / 8))
               for k in range(8)]
    s.body(octagon, vel=(7, 1.5), omega=-2, mass=3, color=(0.2, 0.25, 0.3))
    s.add('<rigidbodygravityforce fx="0" fy="-9.81"/>')
    s.add('<rigidbodycollisionhandling detection="all-pairs" response="velocity-projection"/>')
    s.save("rigid_tower.xml", [
        '<description text="A heavy octagon knocks over a tower of ten blocks (rigid bodies, velocity projection)"/>',
        '<duration time="4.0"/>',
        '<rigidbodyintegrator type="symplectic-euler" dt="0.004"/>',
        '<maxsimfreq max="250"/>',
        '<backgroundcolor r="0.96" g="0.95" b="0.92"/>',
        '<viewport cx="1.5" cy="3.5" size="7.5"/>',
    ])


def rigid_planks():
    s = RigidSceneWriter()
    s.body(box(2.3, -2.5, 2.9, 4), r=0.1, fixed=True, color=(0.45, 0.42, 0.4))
    # Five planks hung from world points by stiff springs at their top ends, released at
    # different angles; they swing into the wall and into each other.
    for k in range(5):
        hx, hy = -2.2 + 1.0 * k, 3.0
        angle = math.radians(-80 + 8 * k)  # from the vertical, to the left
        length, width = 2.4 - 0.15 * k, 0.25
        c, si = math.cos(angle), math.sin(angle)
        # the plank hangs from (hx, hy) along direction (sin a, -cos a)
        ux, uy = si, -c
        px, py = -uy, ux  # across the plank
        corners = [(hx + px * width / 2, hy + py * width / 2),
                   (hx - px * width / 2, hy - py * width / 2),
                   (hx - px * width / 2 + ux * length, hy - py * width / 2 + uy * length),
                   (hx + px * width / 2 + ux * length, hy + py * width / 2 + uy * length)]
        area = sum(corners[i][0] * corners[(i + 1) % 4][1] - corners[(i + 1) % 4][0] * corners[i][1]
                   for i in range(4))
        if area > 0:
            corners.reverse()  # clockwise
        body = s.body(corners, r=0.06, color=rgb(0.55 + 0.07 * k, 0.55, 0.85))
        # attachment: the top end's middle, in body space (relative to the centre of mass,
        # which for four equal masses is the plank's middle)
        s.add(f'<rigidbodyspringforce i="{body}" pix="{fmt(-ux * length / 2)}" piy="{fmt(-uy * length / 2)}" '
              f'j="-1" pjx="{fmt(hx)}" pjy="{fmt(hy)}" k="400" l0="0"/>')
        s.add(f'<rigidbodyspringcolor spring="{k}" r="0.3" g="0.3" b="0.3"/>')
    s.add('<rigidbodygravityforce fx="0" fy="-9.81"/>')
    s.add('<rigidbodycollisionhandling detection="all-pairs" response="velocity-projection"/>')
    s.save("rigid_planks.xml", [
        '<description text="Five planks hung by springs swing into a wall and into each other (rigid bodies, velocity projection)"/>',
        '<duration time="6.0"/>',
        '<rigidbodyintegrator type="symplectic-euler" dt="0.002"/>',
        '<maxsimfreq max="500"/>',
        '<backgroundcolor r="0.96" g="0.95" b="0.92"/>',
        '<viewport cx="0.5" cy="1" size="7"/>',
    ])


def add_floor_ramp_wall(s, wall_x):
    """The half-planes of soft_drape and bodies_with_holes: a floor at y = -0.2, a ramp rising
    to the left from (-1.5, 0.3), a wall on the right at x = wall_x, all in one brown."""
    planes = ((0, -0.2, 0, 1),                                   # floor
              (-1.5, 0.3, math.sin(0.5), math.cos(0.5)),         # ramp on the left
              (wall_x, 0, -1, 0))                                # wall on the right
    for px, py, nx, ny in planes:
        s.add(f'<halfplane px="{fmt(px)}" py="{fmt(py)}" nx="{fmt(nx)}" ny="{fmt(ny)}"/>')
    for h in range(len(planes)):
        s.add(f'<halfplanecolor i="{h}" r="0.55" g="0.5" b="0.45"/>')


def soft_drape():
    """Elastic bodies written as one element each (<elasticbody>, docs/scene-format.md): a soft
    sheet of 20 x 3 cells falls across a peg (a fixed particle) and drapes over it, an annulus
    tyre rolls down a ramp and bounces along the floor, and a star (a polygon triangulated at a
    spacing of 5 cm) drops onto the floor beside a wall. Penalty contact keeps every particle
    out of the half-planes and off the peg; symplectic Euler with small steps, as in
    soft_bodies."""
    s = SceneWriter()
    s.particle((0.0, 0.2), (0, 0), 1.0, fixed=True, radius=0.07, color=(0.3, 0.3, 0.35))
    s.add('<elasticbody shape="sheet" nx="20" ny="3" width="1.2" height="0.12" x="-0.6" '
          'y="0.45" youngsmodulus="120" poissonratio="0.3" totalmass="1" '
          'particleradius="0.004" edgeradius="0.002"/>')
    s.add('<elasticbody shape="ring" segments="24" radius="0.18" innerradius="0.12" '
          'x="-1.2" y="1.0" vx="0.5" youngsmodulus="1600" poissonratio="0.35" totalmass="0.6" '
          'particleradius="0.004" edgeradius="0.002"/>')
    star = []
    for k in range(10):
        a = math.pi / 2 + k * math.pi / 5
        r = 0.2 if k % 2 == 0 else 0.09
        star += [r * math.cos(a), r * math.sin(a)]
    s.add('<elasticbody shape="polygon" points="' + " ".join(fmt(x) for x in star) + '" '
          'spacing="0.05" x="0.95" y="0.9" rotation="12" youngsmodulus="1500" poissonratio="0.3" '
          'totalmass="0.5" particleradius="0.004" edgeradius="0.002"/>')
    s.add('<simplegravity fx="0" fy="-9.81"/>')
    s.add('<dragdamping b="0.002"/>')
    add_floor_ramp_wall(s, wall_x=1.4)
    s.add('<collision type="penalty" k="3000" thickness="0.01"/>')
    s.save("soft_drape.xml", [
        '<description text="Elastic bodies from one element each: a sheet drapes over a peg, a tyre bounces down a ramp, a star drops (penalty contact, symplectic Euler)"/>',
        '<duration time="4.0"/>',
        '<integrator type="symplectic-euler" dt="0.0005"/>',
        '<maxsimfreq max="2000"/>',
        '<viewport cx="0" cy="0.45" size="1.4"/>',
    ])


def membrane_drape():
    """A square membrane of constant strain triangles (Theme 4's elasticbodycstforce, which in
    3D is a membrane: it resists stretching and shearing in its plane, not bending) dropped flat
    onto a sphere: it wraps over the top, its sides fall past and fold onto the floor. Render it
    coloured by strain: red where the sphere stretches it, blue where the skirt is squeezed.
    Without bending stiffness the compressed skirt crumples at the scale of the mesh. Symplectic
    Euler with a small step (3000 steps take 0.4 s): implicit Euler's Newton iterations do not
    converge once the sheet folds against the sphere (the triangles' Hessians are indefinite
    under compression), and the linearized one blows up there."""
    s = SceneWriter(dim=3)
    n, side, height = 28, 1.4, 0.45          # cells per side, metres, height of the sheet
    E, nu, density = 8.0, 0.3, 0.2           # N/m (a membrane's modulus), -, kg/m²
    h = side / n
    index = lambda r, c: r * (n + 1) + c
    triangles = []
    for r in range(n):
        for c in range(n):
            a, b, d, e = index(r, c), index(r, c + 1), index(r + 1, c + 1), index(r + 1, c)
            # Vertex (r, c) at (x, z) = (c h, -r h) from the corner: counter-clockwise seen from
            # above (+y), so the front of every triangle faces up. Diagonals alternate.
            if (r + c) % 2 == 0:
                triangles += [(a, b, d), (a, d, e)]
            else:
                triangles += [(a, b, e), (b, d, e)]
    mass = [0.0] * ((n + 1) * (n + 1))
    for t in triangles:
        for p in t:
            mass[p] += density * 0.5 * h * h / 3.0
    for r in range(n + 1):
        for c in range(n + 1):
            x, z = -side / 2 + c * h, side / 2 - r * h
            s.particle((x, height, z), (0, 0, 0), mass[index(r, c)], radius=0.004)
    for a, b, c in triangles:
        s.add(f'<elasticbodycstforce i1="{a}" i2="{b}" i3="{c}" youngsmodulus="{fmt(E)}" '
              f'poissonratio="{fmt(nu)}"/>')
    s.add('<simplegravity fx="0" fy="-9.8" fz="0"/>')
    s.add('<dragdamping b="0.002"/>')
    s.add('<sphere px="0" py="0" pz="0" radius="0.3"/>')
    s.add('<spherecolor i="0" r="0.35" g="0.55" b="0.35"/>')
    s.add('<halfplane px="0" py="-0.35" pz="0" nx="0" ny="1" nz="0"/>')
    s.add('<halfplanecolor i="0" r="0.72" g="0.7" b="0.66"/>')
    # Thickness 0.02 stays below the vertex spacing (0.05) minus two radii, so that neighbours
    # on the sheet never touch; with 0.01 the sphere's facets showed through at its top (the
    # painter's algorithm, see cloth_on_sphere).
    s.add('<collision type="penalty" k="400" thickness="0.02"/>')
    s.save("membrane_drape.xml", [
        '<description text="A square membrane of CST triangles drapes over a sphere onto a floor (symplectic Euler, penalty contact, 3D)"/>',
        '<duration time="3.0"/>',
        '<integrator type="symplectic-euler" dt="0.001"/>',
        '<maxsimfreq max="1000"/>',
        '<backgroundcolor r="0.93" g="0.95" b="0.97"/>',
        '<camera3d yaw="30" pitch="28" tx="0" ty="-0.05" tz="0" distance="3.1"/>',
    ])


def loop_text(corners):
    return " ".join(f"{fmt(x)} {fmt(y)}" for x, y in corners)


def circle_corners(cx, cy, r, n, phase=0.0):
    return [(cx + r * math.cos(phase + 2 * math.pi * k / n),
             cy + r * math.sin(phase + 2 * math.pi * k / n)) for k in range(n)]


def bodies_with_holes():
    """Polygons with holes (<elasticbody shape="polygon" holes="...">, docs/scene-format.md): a
    plate with a round hole and a triangular one hangs by its round hole on a peg (a fixed
    particle that passes through the hole) and swings; a letter A, its counter a hole, drops
    onto the floor and bounces. Penalty contact keeps the peg inside the hole and the bodies out
    of the half-planes; symplectic Euler with steps of 0.25 ms (at 0.5 ms, as in soft_drape,
    the letter's smallest vertices, of 0.4 g, make the explicit steps blow up)."""
    s = SceneWriter()
    s.particle((-0.55, 0.75), (0, 0), 1.0, fixed=True, radius=0.03, color=(0.3, 0.3, 0.35))
    # The plate, in its own frame: the round hole's centre (0.1, 0.22) goes onto the peg.
    plate = [(0, 0), (0.5, 0), (0.5, 0.32), (0, 0.32)]
    round_hole = circle_corners(0.1, 0.22, 0.065, 16)
    triangle_hole = [(0.26, 0.07), (0.43, 0.07), (0.43, 0.24)]
    s.add(f'<elasticbody shape="polygon" points="{loop_text(plate)}" '
          f'holes="{loop_text(round_hole)}; {loop_text(triangle_hole)}" spacing="0.04" '
          'x="-0.65" y="0.53" youngsmodulus="1500" poissonratio="0.3" totalmass="0.5" '
          'particleradius="0.004" edgeradius="0.002"/>')
    letter = [(0, 0), (0.1, 0), (0.13, 0.1), (0.27, 0.1), (0.3, 0), (0.4, 0), (0.25, 0.5),
              (0.15, 0.5)]
    counter = [(0.16, 0.2), (0.24, 0.2), (0.2, 0.36)]
    s.add(f'<elasticbody shape="polygon" points="{loop_text(letter)}" '
          f'holes="{loop_text(counter)}" spacing="0.03" x="0.35" y="0.55" rotation="-25" '
          'vx="-0.3" youngsmodulus="1200" poissonratio="0.3" totalmass="0.4" '
          'particleradius="0.004" edgeradius="0.002"/>')
    s.add('<simplegravity fx="0" fy="-9.81"/>')
    s.add('<dragdamping b="0.002"/>')
    add_floor_ramp_wall(s, wall_x=1.3)
    s.add('<collision type="penalty" k="3000" thickness="0.01"/>')
    s.save("bodies_with_holes.xml", [
        '<description text="Polygons with holes: a plate hangs by one of its two holes on a peg and swings; a letter A drops and bounces (penalty contact, symplectic Euler)"/>',
        '<duration time="4.0"/>',
        '<integrator type="symplectic-euler" dt="0.00025"/>',
        '<maxsimfreq max="4000"/>',
        '<viewport cx="0" cy="0.35" size="1.0"/>',
    ])


if __name__ == "__main__":
    vortex_spiral()
    fountain()
    pendulum_wave()
    ropes()
    tablecloth()
    billiards()
    cloth_on_sphere()
    soft_bodies()
    hair_strand()
    rigid_tower()
    rigid_planks()
    soft_drape()
    membrane_drape()
    bodies_with_holes()
