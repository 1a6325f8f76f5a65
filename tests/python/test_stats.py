"""Simulation.stats(): the run summary FOSSSim --stats-json writes (docs/command-line.md, 'Run
summaries'), as a dict: the same numbers as the program's file, collisions counted as the steps
reported them, and the energy drift of a hand-computed run."""

import json
import subprocess

import pytest

import fosssim

# One particle of mass 2 thrown at (3, 4) m/s under g = (0, -8), 8 steps of explicit Euler with
# h = 1/8 (exact in binary). Explicit Euler: q += h v, then v += h g, so after k steps
# v_y = 4 - k and y = 1 + h (4 + 3 + ... + (5 - k)); the total energy
# E = 1/2 m |v|² + m 8 y grows by m h² g² / 2 = 2 · 64 / 128 = 1 J every step: E_k = E_0 + k.
PROJECTILE = """<scene>
  <duration time="1"/>
  <integrator type="explicit-euler" dt="0.125"/>
  <particle m="2" px="0" py="1" vx="3" vy="4" fixed="0"/>
  <simplegravity fx="0" fy="-8"/>
</scene>
"""


def test_energy_drift_of_a_hand_computed_run():
    simulation = fosssim.Simulation(fosssim.load_scene_text(PROJECTILE))
    simulation.run()
    stats = simulation.stats()
    assert stats["schema"] == "fosssim-run-stats" and stats["version"] == 1
    assert stats["steps"] == 8
    assert stats["time"] == {"start": 0.0, "end": 1.0}
    assert stats["integrator"] == {"method": "explicit-euler", "dt": 0.125}
    energy = stats["energy"]
    initial = 0.5 * 2 * (3 * 3 + 4 * 4) + 2 * 8 * 1  # 25 + 16
    assert energy["initial"] == initial
    assert energy["final"] == initial + 8
    assert energy["drift"] == 8 and energy["max_drift"] == 8
    assert energy["relative_drift"] == pytest.approx(8 / initial, rel=1e-15)
    assert energy["min"] == initial and energy["max"] == initial + 8
    # Explicit Euler solves nothing and no collision handling is asked for.
    assert stats["solver"]["iterations"] is None
    assert stats["solver"]["linear_solves"] is None
    assert stats["collisions"]["total"] == 0
    assert set(stats["timings"]) == {"wall_seconds", "seconds_per_step", "threads"}


def test_collisions_are_counted_as_the_steps_reported_them(source_dir):
    simulation = fosssim.Simulation(
        fosssim.load_scene(str(source_dir / "assets/t2m1/explicit_cor_bouncing_ball.xml")))
    per_step = []
    while not simulation.finished:
        simulation.step()
        per_step.append(len(simulation.collisions))
    collisions = simulation.stats()["collisions"]
    assert sum(per_step) > 0
    assert collisions["total"] == sum(per_step)
    assert collisions["max_per_step"] == max(per_step)
    assert collisions["steps_with_collisions"] == sum(1 for n in per_step if n > 0)


def test_set_state_starts_a_new_summary():
    simulation = fosssim.Simulation(fosssim.load_scene_text(PROJECTILE))
    simulation.step(3)
    assert simulation.stats()["steps"] == 3
    simulation.set_state(time=0.0, step=0)
    assert simulation.stats()["steps"] == 0
    simulation.step(2)
    assert simulation.stats()["steps"] == 2


@pytest.mark.parametrize("name", [
    "assets/t1m3/system_multiple_pendulum.xml",  # implicit Euler: Newton iterations
    "assets/t2m1/explicit_cor_bouncing_ball.xml",  # collisions
    "assets3d/scenes/chain.xml",  # local/global: factorizations
])
def test_the_same_summary_as_the_programs_file(name, source_dir, program, tmp_path):
    scene_path = str(source_dir / name)
    out = tmp_path / "stats.json"
    subprocess.run([program, "-s", scene_path, "-d", "0", "-q", "--stats-json", str(out)],
                   check=True, capture_output=True)
    from_program = json.loads(out.read_text())
    simulation = fosssim.Simulation(fosssim.load_scene(scene_path))
    simulation.run()
    from_module = simulation.stats()
    # Everything but the timings is a function of the scene: the same in both.
    del from_program["timings"], from_module["timings"]
    assert from_module == from_program
    assert from_program["steps"] == simulation.num_steps
