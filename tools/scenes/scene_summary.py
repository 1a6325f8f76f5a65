#!/usr/bin/env python3
"""Summarises a scene's trajectory by numbers: energy at start and end (kinetic plus the
potentials of docs/forces.md: springs, simple gravity, Newtonian gravity, constant force), the
largest spring strain and the closest approach of Newtonian and vortex pairs.

Usage: scene_summary.py SCENE.xml TRAJECTORY.bin
"""

import math
import sys
import xml.etree.ElementTree as ET

from trajectory import layout_of_scene, point, read_records


def f(element, name, default=None):
    value = element.get(name)
    return float(value) if value is not None else default


class SceneData:
    def __init__(self, path):
        root = ET.parse(path).getroot()
        self.particles = root.findall("particle")
        self.mass = [f(p, "m") for p in self.particles]
        self.fixed = [p.get("fixed").strip() == "1" for p in self.particles]
        edges = [(int(e.get("i")), int(e.get("j"))) for e in root.findall("edge")]
        self.springs = [(edges[int(s.get("edge"))], f(s, "k"), f(s, "l0"))
                        for s in root.findall("springforce")]
        self.gravity = [(f(g, "fx"), f(g, "fy")) for g in root.findall("simplegravity")]
        self.newtonian = [(int(g.get("i")), int(g.get("j")), f(g, "G"))
                          for g in root.findall("gravitationalforce")]
        self.constant = [(f(c, "fx"), f(c, "fy")) for c in root.findall("constantforce")]
        self.vortex = [(int(v.get("i")), int(v.get("j"))) for v in root.findall("vortexforce")]
        self.dt = f(root.find("integrator"), "dt")

    def energy(self, q, v):
        """Kinetic plus potential energy (free particles only for the kinetic part)."""
        e = 0.0
        for i, m in enumerate(self.mass):
            vx, vy = point(v, i)
            if not self.fixed[i]:
                e += 0.5 * m * (vx * vx + vy * vy)
        for (i, j), k, l0 in self.springs:
            e += 0.5 * k * (math.dist(point(q, i), point(q, j)) - l0) ** 2
        for gx, gy in self.gravity:
            for i, m in enumerate(self.mass):
                if not self.fixed[i]:
                    x, y = point(q, i)
                    e -= m * (gx * x + gy * y)
        for fx, fy in self.constant:
            for i in range(len(self.mass)):
                if not self.fixed[i]:
                    x, y = point(q, i)
                    e -= fx * x + fy * y
        for i, j, G in self.newtonian:
            e -= G * self.mass[i] * self.mass[j] / math.dist(point(q, i), point(q, j))
        return e

    def max_strain(self, q):
        strains = [abs(math.dist(point(q, i), point(q, j)) - l0) / l0
                   for (i, j), k, l0 in self.springs if l0 > 0]
        return max(strains, default=0.0)

    def min_distance(self, q, pairs):
        return min((math.dist(point(q, i), point(q, j)) for i, j in pairs), default=math.inf)


def summarise(scene_path, trajectory_path):
    scene = SceneData(scene_path)
    with open(scene_path) as f:
        layout = layout_of_scene(f.read())
    records = read_records(trajectory_path, len(scene.mass), layout=layout)
    if layout == "polynomials":  # keep the end-of-step records, not the sync records
        records = records[::2]
    frames = [(r["q"], r["v"]) for r in records]
    energies = [scene.energy(q, v) for q, v in frames]
    pairs = [(i, j) for i, j, _ in scene.newtonian] + scene.vortex
    return {
        "frames": len(frames),
        "energy_start": energies[0],
        "energy_end": energies[-1],
        "energy_min": min(energies),
        "energy_max": max(energies),
        "max_strain": max(scene.max_strain(q) for q, _ in frames),
        "min_pair_distance": min(scene.min_distance(q, pairs) for q, _ in frames),
        "finite": all(math.isfinite(x) for q, v in frames for x in q + v),
    }


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    for key, value in summarise(argv[1], argv[2]).items():
        print(f"{key:18} {value}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
