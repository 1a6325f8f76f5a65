#!/usr/bin/env python3
"""Integrators written in Python, stepping FOSSSim's forces.

Symplectic Euler written with NumPy takes the same steps as FOSSSim's symplectic-euler bit for
bit (same operations, same order, no fused multiply-add); velocity Verlet, which FOSSSim does
not have, is second order: after three periods of a spring its error is far smaller.

    PYTHONPATH=build/release/python python3 examples/python/custom_integrator.py

Exits with status 1 if either claim fails.
"""

import sys

import numpy as np

import fosssim

# Period 1 s: after 3 s the particle is back at x = 1.5 with zero velocity.
SCENE = """<scene>
  <duration time="3"/>
  <integrator type="symplectic-euler" dt="0.01"/>
  <particle m="1" px="0" py="0" vx="0" vy="0" fixed="1"/>
  <particle m="1" px="1.5" py="0" vx="0" vy="0" fixed="0"/>
  <edge i="0" j="1"/>
  <springforce edge="0" k="39.47841760435743" l0="1"/>
</scene>
"""


def symplectic_euler(scene, q, v, h):
    force = scene.force(q, v, zero_fixed=True)
    v = v + h * (force / scene.mass)
    q = q + h * v
    return q, v


def velocity_verlet(scene, q, v, h):
    a = scene.force(q, v, zero_fixed=True) / scene.mass
    half = v + 0.5 * h * a
    q = q + h * half
    v = half + 0.5 * h * scene.force(q, half, zero_fixed=True) / scene.mass
    return q, v


def run(scene, step):
    q, v = np.array(scene.initial_q), np.array(scene.initial_v)
    for _ in range(scene.num_steps):
        q, v = step(scene, q, v, scene.dt)
    return q, v


def main():
    scene = fosssim.load_scene_text(SCENE, "spring.xml")
    reference = fosssim.Simulation(scene)
    reference.run()

    q, v = run(scene, symplectic_euler)
    same = np.array_equal(q, reference.q) and np.array_equal(v, reference.v)
    print(f"Python symplectic Euler equals FOSSSim's bit for bit: {same}")

    exact = np.array([0, 0, 1.5, 0])
    euler_error = np.linalg.norm(q - exact)
    q, v = run(scene, velocity_verlet)
    verlet_error = np.linalg.norm(q - exact)
    print(f"position error after 3 periods: symplectic Euler {euler_error:.3e}, "
          f"velocity Verlet {verlet_error:.3e}")
    return 0 if same and verlet_error < 0.1 * euler_error else 1


if __name__ == "__main__":
    sys.exit(main())
