#!/usr/bin/env python3
"""Every integrator of the registry on an undamped spring: how its total energy behaves, against
what the registry says of it (grows, bounded or decays).

    PYTHONPATH=build/release/python python3 examples/python/integrator_energy.py [OUTPUT.png]

Writes the plot (default integrator_energy.png) and a table; exits with status 1 if a method's
energy does not behave as the registry says.
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import fosssim

# A particle on a spring of k = 4 pi^2 with a fixed anchor: period 1 s, energy 0.5 k 0.5^2.
SCENE = """<scene>
  <duration time="5"/>
  <integrator type="explicit-euler" dt="0.01"/>
  <particle m="1" px="0" py="0" vx="0" vy="0" fixed="1"/>
  <particle m="1" px="1.5" py="0" vx="0" vy="0" fixed="0"/>
  <edge i="0" j="1"/>
  <springforce edge="0" k="39.47841760435743" l0="1"/>
</scene>
"""
DT = 0.01


def energies(method):
    scene = fosssim.load_scene_text(SCENE, "spring.xml")
    scene.set_integrator(method, dt=DT)
    simulation = fosssim.Simulation(scene)
    out = [scene.kinetic_energy(simulation.v) + scene.potential_energy(simulation.q)]
    while not simulation.finished:
        simulation.step()
        out.append(scene.kinetic_energy(simulation.v) + scene.potential_energy(simulation.q))
    return np.arange(len(out)) * DT, np.array(out)


def behaviour(energy):
    """'grows', 'decays' or 'bounded', from the energy at the end against its start, with the
    largest excursion allowed for a bounded method: 5% of the start."""
    start, end = energy[0], energy[-1]
    if np.max(np.abs(energy - start)) <= 0.05 * start:
        return "bounded"
    return "grows" if end > start else "decays"


def main():
    output = sys.argv[1] if len(sys.argv) > 1 else "integrator_energy.png"
    figure, axes = plt.subplots(figsize=(8, 5))
    failures = 0
    print(f"{'integrator':30s} {'registry':>8s} {'measured':>8s} {'E(5 s)/E(0)':>12s}")
    for method in fosssim.integrators():
        if not method["runs_2d"]:
            continue
        times, energy = energies(method["name"])
        measured = behaviour(energy)
        failures += measured != method["energy"]
        print(f"{method['name']:30s} {method['energy']:>8s} {measured:>8s} "
              f"{energy[-1] / energy[0]:12.6f}")
        axes.plot(times, energy / energy[0], label=method["name"])
    axes.set_yscale("log")
    axes.set_xlabel("time (s)")
    axes.set_ylabel("total energy / initial energy")
    axes.legend(fontsize="small")
    figure.tight_layout()
    figure.savefig(output, dpi=80)
    print(f"wrote {output}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
