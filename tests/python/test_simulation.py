"""Stepping, views of the state, collisions, trajectories (bytes of the program's), grading,
pictures, and stopping a long step."""

import _thread
import subprocess
import threading

import numpy as np
import pytest

import fosssim

# Scenes whose trajectories must be byte for byte the program's: one per trajectory layout
# (frames only; with collisions; with sync records and polynomials) and a penalty scene.
SAME_BYTES_SCENES = [
    "assets/t1m1/springs_spinning_triangle.xml",
    "assets/t2m1/explicit_cor_bouncing_ball.xml",
    "assets/t2m1/implicit_penalty_chain_on_edge.xml",
    "assets/t2m2/explicit_continuous_head_on.xml",
    "assets3d/scenes/chain.xml",  # 3D, a generated mesh, local/global
    "assets3d/json/cloth_9x9.json",  # the JSON format, an OBJ mesh
]

PROJECTILE = """<scene>
  <duration time="1"/>
  <integrator type="explicit-euler" dt="0.125"/>
  <particle m="2" px="0.5" py="1" vx="3" vy="4" fixed="0"/>
  <particle m="1" px="0" py="0" vx="1" vy="1" fixed="1"/>
  <simplegravity fx="0" fy="-8"/>
</scene>
"""


def test_explicit_euler_steps_by_hand():
    simulation = fosssim.Simulation(fosssim.load_scene_text(PROJECTILE))
    simulation.step(2)
    assert simulation.step_count == 2
    assert simulation.time == 0.25
    # Explicit Euler: q += h v, then v += h g, with h = 1/8 (exact in binary). The fixed
    # particle receives no force and keeps its velocity.
    np.testing.assert_array_equal(simulation.positions, [[0.5 + 0.75, 1 + 0.5 + 0.375], [0.25, 0.25]])
    np.testing.assert_array_equal(simulation.velocities, [[3, 2], [1, 1]])


def test_views_follow_the_simulation_and_are_read_only():
    simulation = fosssim.Simulation(fosssim.load_scene_text(PROJECTILE))
    q = simulation.q
    positions = simulation.positions
    assert positions.shape == (2, 2) and q.shape == (4,)
    assert np.shares_memory(q, positions)
    snapshot = q.copy()
    simulation.step()
    assert q[0] == 0.5 + 0.375 and snapshot[0] == 0.5
    with pytest.raises(ValueError):
        q[0] = 1.0
    simulation.set_state(q=np.zeros(4), v=np.ones((2, 2)), time=5.0)
    np.testing.assert_array_equal(positions, np.zeros((2, 2)))
    assert simulation.time == 5.0


def test_run_stops_at_the_duration():
    simulation = fosssim.Simulation(fosssim.load_scene_text(PROJECTILE))
    simulation.run()
    assert simulation.finished and simulation.step_count == 8 and simulation.time == 1.0


@pytest.mark.parametrize("name", SAME_BYTES_SCENES)
def test_a_run_writes_the_programs_bytes(name, source_dir, program, tmp_path):
    scene_path = str(source_dir / name)
    subprocess.run([program, "-s", scene_path, "-d", "0", "-o", str(tmp_path / "program.bin"), "-q"],
                   check=True, capture_output=True)
    simulation = fosssim.Simulation(fosssim.load_scene(scene_path))
    simulation.run(trajectory=str(tmp_path / "python.bin"))
    expected = (tmp_path / "program.bin").read_bytes()
    assert len(expected) > 0
    assert (tmp_path / "python.bin").read_bytes() == expected
    # And a step-by-step writer of the same run writes the same bytes.
    scene = fosssim.load_scene(scene_path)
    stepping = fosssim.Simulation(scene)
    with fosssim.TrajectoryWriter(scene, str(tmp_path / "writer.bin")) as writer:
        writer.write(stepping)
        while not stepping.finished:
            stepping.step()
            writer.write(stepping)
    assert (tmp_path / "writer.bin").read_bytes() == expected


def test_reading_and_grading_trajectories(source_dir, tmp_path):
    scene = fosssim.load_scene(str(source_dir / "assets/t1m1/springs_spinning_triangle.xml"))
    simulation = fosssim.Simulation(scene)
    path = str(tmp_path / "run.bin")
    simulation.run(trajectory=path)
    frames = fosssim.read_trajectory(scene, path)
    assert frames["q"].shape == (scene.num_steps + 1, scene.num_dofs)
    np.testing.assert_array_equal(frames["q"][-1], simulation.q)
    np.testing.assert_array_equal(frames["v"][0], scene.initial_v)
    del simulation
    report = fosssim.grade(scene, path)
    assert report["passed"] and report["steps_graded"] == scene.num_steps
    assert report["max_position"] == 0.0
    assert "Overall success: Passed." in report["report"]

    # A file whose step 7 is off by 1e-6 fails there.
    data = bytearray(open(path, "rb").read())
    frame_bytes = 16 * scene.num_dofs
    value = np.frombuffer(bytes(data[7 * frame_bytes:7 * frame_bytes + 8]), "<f8")[0]
    data[7 * frame_bytes:7 * frame_bytes + 8] = np.array([value + 1e-6], "<f8").tobytes()
    open(path, "wb").write(bytes(data))
    report = fosssim.grade(scene, path)
    assert not report["passed"]
    assert report["first_divergence"]["step"] == 7
    assert report["first_divergence"]["particle"] == 0


def test_grading_a_file_of_the_wrong_size_is_an_error(source_dir, tmp_path):
    scene = fosssim.load_scene(str(source_dir / "assets/t1m1/springs_spinning_triangle.xml"))
    path = tmp_path / "short.bin"
    path.write_bytes(b"\0" * 5)
    with pytest.raises(fosssim.Error) as caught:
        fosssim.grade(scene, str(path))
    assert caught.value.kind == "bad-input"


def test_collisions_of_the_last_step(source_dir, tmp_path):
    scene = fosssim.load_scene(str(source_dir / "assets/t2m1/explicit_cor_bouncing_ball.xml"))
    simulation = fosssim.Simulation(scene)
    while not simulation.collisions:
        assert not simulation.finished, "the ball must hit the floor"
        simulation.step()
    (collision,) = simulation.collisions
    assert collision.kind == "particle-halfplane"
    assert (collision.first, collision.second) == (0, 0)
    assert collision.normal[0] == 0 and 0 < abs(collision.normal[1]) < 0.1  # radius 0.1
    assert collision.time == 0.0  # discrete detection
    assert simulation.velocities[0, 1] > 0  # the impulse turned it upwards
    step = simulation.step_count
    simulation.step()
    assert simulation.collisions == []
    # The trajectory file records the same collision at the same step.
    del simulation
    path = str(tmp_path / "ball.bin")
    fosssim.Simulation(scene).run(trajectory=path)
    records = fosssim.read_trajectory(scene, path)["collisions"]
    assert [len(r) for r in records[:step]] == [0] * step
    (recorded,) = records[step]
    assert (recorded.kind, recorded.first, recorded.second) == ("particle-halfplane", 0, 0)
    np.testing.assert_array_equal(recorded.normal, collision.normal)


def test_a_failed_step_raises_step_error_with_its_number():
    simulation = fosssim.Simulation(fosssim.load_scene_text(PROJECTILE))
    simulation.step(3)
    simulation.set_state(v=np.array([np.nan, 0, 0, 0]))
    with pytest.raises(fosssim.StepError) as caught:
        simulation.step()
    assert caught.value.step == 4
    assert caught.value.kind == "step-failed"
    assert "particle 0" in str(caught.value)


def test_render_draws_the_scene(source_dir, tmp_path):
    simulation = fosssim.Simulation(
        fosssim.load_scene(str(source_dir / "assets/t2m1/explicit_cor_bouncing_ball.xml")))
    image = simulation.render(160, 120)
    assert image.shape == (120, 160, 3) and image.dtype == np.uint8
    assert tuple(image[0, 0]) == (255, 255, 255)  # the background
    ball = np.all(np.abs(image.astype(int) - [217, 84, 26]) <= 2, axis=2)  # colour 0.85 0.33 0.1
    assert ball.sum() > 10
    simulation.save_picture(str(tmp_path / "frame.png"), 64, 48)
    assert (tmp_path / "frame.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    with pytest.raises(ValueError, match="between 16 and 8192"):
        simulation.render(0, 10)
    chain = fosssim.Simulation(fosssim.load_scene(str(source_dir / "assets3d/scenes/chain.xml")))
    chain.step(10)
    picture = chain.render(64, 64)
    assert picture.shape == (64, 64, 3)
    assert np.any(np.any(picture != picture[0, 0], axis=2))  # something drawn on the background


def test_a_long_step_releases_the_gil_and_stops_on_ctrl_c():
    simulation = fosssim.Simulation(fosssim.load_scene_text(PROJECTILE))
    # The timer thread can only run while step() has released the GIL.
    timer = threading.Timer(0.3, _thread.interrupt_main)
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        simulation.step(10**12)
    timer.join()
    assert 0 < simulation.step_count < 10**12
    assert simulation.time == pytest.approx(simulation.step_count * 0.125)


def test_an_interrupted_run_leaves_only_an_incomplete_trajectory(tmp_path):
    scene = fosssim.load_scene_text(PROJECTILE.replace('time="1"', 'time="1e9"'))
    simulation = fosssim.Simulation(scene)
    path = tmp_path / "long.bin"
    timer = threading.Timer(0.2, _thread.interrupt_main)
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        simulation.run(trajectory=str(path))
    timer.join()
    assert not path.exists()
    kept = (tmp_path / "long.bin.incomplete").stat().st_size
    frame = 2 * scene.num_dofs * 8
    assert kept % frame == 0 and kept // frame == simulation.step_count + 1
