#!/usr/bin/env python3
"""Coefficient of restitution sweep: drop a ball on a floor with COR from 0.1 to 1, measure the
COR each first bounce actually had, and plot the bounce heights over time.

    PYTHONPATH=build/release/python python3 examples/python/cor_sweep.py [OUTPUT.png]

Writes the plot (default cor_sweep.png) and prints the measured coefficients; exits with
status 1 if one differs from the scene's by more than 1e-12.
"""

import sys

import matplotlib

matplotlib.use("Agg")  # files only, no window
import matplotlib.pyplot as plt
import numpy as np

import fosssim

SCENE = """<scene>
  <duration time="4"/>
  <integrator type="symplectic-euler" dt="0.001"/>
  <particle m="1" px="0" py="1.5" vx="0" vy="0" fixed="0" radius="0.1"/>
  <simplegravity fx="0" fy="-9.81"/>
  <halfplane px="0" py="0" nx="0" ny="1"/>
  <collision type="simple" COR="{cor}"/>
</scene>
"""


def drop(cor):
    """Runs the drop; returns the times and heights, and the COR of the first bounce measured as
    -(normal velocity after) / (normal velocity before)."""
    scene = fosssim.load_scene_text(SCENE.format(cor=cor), f"cor={cor}")
    simulation = fosssim.Simulation(scene)
    g = scene.force(scene.initial_q)[1] / scene.mass[1]
    times, heights, measured = [0.0], [simulation.q[1]], None
    while not simulation.finished:
        # Symplectic Euler's velocity before any response: v + h g.
        before = simulation.v[1] + scene.dt * g
        simulation.step()
        if measured is None and simulation.collisions:
            measured = -simulation.v[1] / before
        times.append(simulation.time)
        heights.append(simulation.q[1])
    return np.array(times), np.array(heights), measured


def main():
    output = sys.argv[1] if len(sys.argv) > 1 else "cor_sweep.png"
    cors = np.round(np.linspace(0.1, 1.0, 10), 2)
    figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4))
    worst = 0.0
    measured_all = []
    for cor in cors:
        times, heights, measured = drop(cor)
        measured_all.append(measured)
        worst = max(worst, abs(measured - cor))
        print(f"COR {cor:.2f}: first bounce measured {measured:.15f}")
        if cor in (0.3, 0.6, 0.9, 1.0):
            right.plot(times, heights, label=f"COR {cor:.1f}")
    left.plot(cors, measured_all, "o-", label="measured at the first bounce")
    left.plot([0, 1], [0, 1], ":", color="grey", label="scene's COR")
    left.set_xlabel("coefficient of restitution (scene)")
    left.set_ylabel("-v after / v before")
    left.legend()
    right.set_xlabel("time (s)")
    right.set_ylabel("height of the ball's centre (m)")
    right.legend()
    figure.tight_layout()
    figure.savefig(output, dpi=80)
    print(f"largest difference {worst:.3g}; wrote {output}")
    return 0 if worst <= 1e-12 else 1


if __name__ == "__main__":
    sys.exit(main())
