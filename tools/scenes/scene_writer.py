"""Builds FOSSSim scene files (the XML format of docs/scene-format.md) from Python.

A Scene collects particles, edges, forces and appearance, and renders them in a fixed element
order with numbers printed exactly (shortest round-trip form), so regenerating a file that did
not change gives identical bytes.
"""

import math
from dataclasses import dataclass, field

# Integrator families used by the suites: the scene's integrator type string per family.
INTEGRATOR_TYPES = {
    "explicit": "explicit-euler",
    "symplectic": "symplectic-euler",
    "linearized": "linearized-implicit-euler",
    "implicit": "implicit-euler",
}

GRAVITY = 9.81

# Distinct colours (r, g, b in 0..1) for particles, edges and paths.
PALETTE = [
    (0.85, 0.33, 0.10),  # orange
    (0.00, 0.45, 0.74),  # blue
    (0.47, 0.67, 0.19),  # green
    (0.49, 0.18, 0.56),  # purple
    (0.93, 0.69, 0.13),  # yellow
    (0.30, 0.75, 0.93),  # light blue
    (0.64, 0.08, 0.18),  # dark red
    (0.20, 0.20, 0.20),  # dark grey
]
FIXED_COLOR = (0.25, 0.25, 0.25)
DARK_BACKGROUND = (0.05, 0.07, 0.15)


def number(x):
    """A number as scene text: integers without a decimal point, others in shortest exact form."""
    x = float(x)
    if not math.isfinite(x):
        raise ValueError(f"non-finite number {x}")
    if x == 0.0:
        return "0"
    if x.is_integer() and abs(x) < 1e15:
        return str(int(x))
    return repr(x)


def direction(degrees):
    """(cos, sin) of an angle in degrees: exact at multiples of 90 degrees, otherwise rounded to
    12 significant digits, so that the scene files do not depend on the last bit of the C
    library's sin and cos."""
    quarter, rest = divmod(degrees, 90.0)
    if rest == 0.0:
        return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[int(quarter) % 4]
    a = math.radians(degrees)
    return float(f"{math.cos(a):.12g}"), float(f"{math.sin(a):.12g}")


def escape(text):
    return (text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
            .replace('"', "&quot;"))


@dataclass
class Particle:
    m: float
    x: float
    y: float
    vx: float = 0.0
    vy: float = 0.0
    fixed: bool = False
    radius: float = 0.05


@dataclass
class Scene:
    """One scene file. `what` is the table line of the README, `description` the scene's text."""

    integrator: str  # family: explicit, symplectic, linearized, implicit
    dt: float
    duration: float
    description: str = ""
    what: str = ""
    integrator_type: str = ""  # overrides the family's type string (the alias scenes)
    viewport: tuple = None  # (cx, cy, size); size is the half-height of the visible square
    background: tuple = None
    particles: list = field(default_factory=list)
    edges: list = field(default_factory=list)  # (i, j, radius)
    springs: list = field(default_factory=list)  # (edge, k, l0, b)
    gravity: list = field(default_factory=list)  # (fx, fy)
    newtonian: list = field(default_factory=list)  # (i, j, G)
    constant: list = field(default_factory=list)  # (fx, fy)
    drag: list = field(default_factory=list)  # b
    vortex: list = field(default_factory=list)  # (i, j, kbs, kvc)
    particle_colors: dict = field(default_factory=dict)
    edge_colors: dict = field(default_factory=dict)
    paths: list = field(default_factory=list)  # (i, duration, color)
    half_planes: list = field(default_factory=list)  # (px, py, nx, ny, color or None)
    collision: dict = None  # attributes of <collision>, "type" first
    detection: str = ""  # type of <collisiondetection>, or none

    # --- building -------------------------------------------------------------------------
    def particle(self, m, x, y, vx=0.0, vy=0.0, fixed=False, radius=0.05, color=None):
        """Adds a particle and returns its index."""
        self.particles.append(Particle(m, x, y, vx, vy, fixed, round(radius, 4)))
        index = len(self.particles) - 1
        if color is not None:
            self.particle_colors[index] = color
        elif fixed:
            self.particle_colors[index] = FIXED_COLOR
        return index

    def edge(self, i, j, radius=0.015, color=None):
        """Adds an edge (drawing only) and returns its index."""
        self.edges.append((i, j, radius))
        index = len(self.edges) - 1
        if color is not None:
            self.edge_colors[index] = color
        return index

    def spring(self, i, j, k, l0=None, b=0.0, radius=0.015, color=None):
        """Adds an edge and a spring over it; l0 defaults to the particles' initial distance."""
        if l0 is None:
            l0 = self.distance(i, j)
        e = self.edge(i, j, radius, color)
        self.springs.append((e, k, l0, b))
        return e

    def half_plane(self, px, py, nx, ny, color=None):
        """Adds a half-plane (solid where (x - p)·n ≤ 0) and returns its index."""
        self.half_planes.append((px, py, nx, ny, color))
        return len(self.half_planes) - 1

    def collide(self, kind, **parameters):
        """Sets the <collision> element: its type and parameters (COR, k, thickness, ...)."""
        self.collision = {"type": kind, **parameters}

    def distance(self, i, j):
        a, b = self.particles[i], self.particles[j]
        return math.hypot(b.x - a.x, b.y - a.y)

    def path(self, i, duration=None, color=None):
        self.paths.append((i, self.duration if duration is None else duration,
                           color if color is not None else self.particle_colors.get(i, PALETTE[0])))

    # --- rendering ------------------------------------------------------------------------
    def type_string(self):
        return self.integrator_type or INTEGRATOR_TYPES[self.integrator]

    def to_xml(self, generator_note):
        out = [f"<!-- {generator_note} -->", "<scene>"]

        def line(tag, **attributes):
            text = " ".join(f'{k}="{v}"' for k, v in attributes.items())
            out.append(f"  <{tag} {text}/>")

        line("description", text=escape(self.description))
        line("duration", time=number(self.duration))
        line("integrator", type=self.type_string(), dt=number(self.dt))
        # Play back in real time in the window: one second of simulated time per second.
        line("maxsimfreq", max=number(round(1.0 / self.dt)))
        if self.viewport:
            cx, cy, size = self.viewport
            line("viewport", cx=number(cx), cy=number(cy), size=number(size))
        if self.background:
            r, g, b = self.background
            line("backgroundcolor", r=number(r), g=number(g), b=number(b))
        for p in self.particles:
            line("particle", m=number(p.m), px=number(p.x), py=number(p.y), vx=number(p.vx),
                 vy=number(p.vy), fixed="1" if p.fixed else "0", radius=number(p.radius))
        for i, j, radius in self.edges:
            line("edge", i=i, j=j, radius=number(radius))
        for e, k, l0, b in self.springs:
            if b:
                line("springforce", edge=e, k=number(k), l0=number(l0), b=number(b))
            else:
                line("springforce", edge=e, k=number(k), l0=number(l0))
        for fx, fy in self.gravity:
            line("simplegravity", fx=number(fx), fy=number(fy))
        for i, j, G in self.newtonian:
            line("gravitationalforce", i=i, j=j, G=number(G))
        for fx, fy in self.constant:
            line("constantforce", fx=number(fx), fy=number(fy))
        for b in self.drag:
            line("dragdamping", b=number(b))
        for i, j, kbs, kvc in self.vortex:
            line("vortexforce", i=i, j=j, kbs=number(kbs), kvc=number(kvc))
        for px, py, nx, ny, _ in self.half_planes:
            line("halfplane", px=number(px), py=number(py), nx=number(nx), ny=number(ny))
        for i, (_, _, _, _, color) in enumerate(self.half_planes):
            if color is not None:
                r, g, b = color
                line("halfplanecolor", i=i, r=number(r), g=number(g), b=number(b))
        if self.collision:
            line("collision", **{k: (v if isinstance(v, str) else number(v))
                                 for k, v in self.collision.items()})
        if self.detection:
            line("collisiondetection", type=self.detection)
        for i, (r, g, b) in sorted(self.particle_colors.items()):
            line("particlecolor", i=i, r=number(r), g=number(g), b=number(b))
        for i, (r, g, b) in sorted(self.edge_colors.items()):
            line("edgecolor", i=i, r=number(r), g=number(g), b=number(b))
        for i, duration, (r, g, b) in self.paths:
            line("particlepath", i=i, duration=number(duration), r=number(r), g=number(g),
                 b=number(b))
        out.append("</scene>")
        return "\n".join(out) + "\n"
