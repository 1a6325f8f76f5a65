"""Loading scenes, their errors, and choosing integrators through the registry."""

import os

import numpy as np
import pytest

import fosssim
from conftest import FORCES_SCENE


def test_load_scene_reads_the_model(source_dir):
    scene = fosssim.load_scene(str(source_dir / "assets/t1m1/accuracy_spring_period.xml"))
    assert scene.dim == 2
    assert scene.num_particles == 2
    assert scene.dt == 0.001
    assert scene.duration == 3
    assert scene.num_steps == 3000
    assert scene.integrator == "explicit-euler"
    assert list(scene.fixed) == [True, False]
    assert scene.edges == [(0, 1)]
    np.testing.assert_array_equal(scene.initial_q, [0, 0, 1.5, 0])
    assert len(scene.forces) == 1
    assert "spring" in scene.forces[0].label


def test_scene_arrays_are_read_only_views_that_keep_the_scene_alive():
    scene = fosssim.load_scene_text(FORCES_SCENE)
    mass = scene.mass
    np.testing.assert_array_equal(mass, [1.5, 1.5, 2, 2, 0.7, 0.7])
    with pytest.raises(ValueError):
        mass[0] = 3.0
    del scene
    assert mass.sum() == pytest.approx(8.4)  # the view still reads the scene it came from


def test_a_scene_error_names_file_line_and_problem():
    text = ('<scene>\n  <duration time="1"/>\n  <integrator type="explicit-euler" dt="0.1"/>\n'
            '  <particle m="-1" px="0" py="0" vx="0" vy="0" fixed="0"/>\n</scene>\n')
    with pytest.raises(fosssim.SceneError) as caught:
        fosssim.load_scene_text(text, "bad.xml")
    error = caught.value
    assert error.file == "bad.xml"
    assert error.line == 4
    assert "m" in error.problem and "positive" in error.problem
    assert str(error).startswith("bad.xml:4:")
    assert error.kind == "bad-input"
    assert isinstance(error, ValueError) and isinstance(error, fosssim.Error)


def test_a_missing_file_is_a_scene_error_without_a_line(tmp_path):
    with pytest.raises(fosssim.SceneError) as caught:
        fosssim.load_scene(str(tmp_path / "nothing.xml"))
    assert caught.value.line == 0
    assert caught.value.file.endswith("nothing.xml")


def test_integrators_come_from_the_registry():
    methods = {m["name"]: m for m in fosssim.integrators()}
    assert {"explicit-euler", "symplectic-euler", "implicit-euler"} <= set(methods)
    assert methods["symplectic-euler"]["energy"] == "bounded"
    assert "semi-implicit-euler" in methods["symplectic-euler"]["aliases"]
    for method in methods.values():
        for option in method["options"]:
            assert option["type"] in ("number", "integer", "choice")
            assert option["help"]


def test_contact_methods_come_from_the_registry():
    methods = {m["name"]: m for m in fosssim.contact_methods()}
    assert list(methods)[:5] == ["none", "simple", "penalty", "continuous-time", "hybrid"]
    assert methods["hybrid"]["runs_2d"] and not methods["hybrid"]["runs_3d"]
    assert methods["hybrid"]["has_stage"] and methods["hybrid"]["has_force"]
    assert methods["penalty"]["records"] == "frames"
    assert methods["simple"]["records"] == "collisions"
    assert methods["continuous-time"]["records"] == "collisions and polynomials"
    hybrid_options = {o["name"]: o for o in methods["hybrid"]["options"]}
    assert hybrid_options["k"]["default"] == 10.0
    assert hybrid_options["penalty-jacobian"]["choices"] == ["none", "exact"]
    for method in methods.values():
        assert method["summary"]
        for option in method["options"]:
            assert option["help"]
    scene = fosssim.load_scene_text(FORCES_SCENE)
    assert scene.collisions == "none"


def test_rigid_body_responses_are_contact_methods(source_dir):
    methods = {m["name"]: m for m in fosssim.contact_methods()}
    rigid = [name for name, m in methods.items() if "planar rigid bodies" in m["bodies"]]
    assert rigid == ["lcp", "velocity-projection", "gr-lcp", "gr-velocity-projection"]
    for name in rigid:
        assert methods[name]["bodies"] == ["planar rigid bodies"]
        assert methods[name]["runs_2d"] and not methods[name]["runs_3d"]
        assert methods[name]["has_stage"] and not methods[name]["has_force"]
        assert methods[name]["records"] == "frames"
    scene = fosssim.load_scene(str(source_dir / "assets/t3m2/gr_lcp_newtons_cradle.xml"))
    assert scene.collisions == "gr-lcp"


def test_set_integrator_takes_aliases_dt_and_options():
    scene = fosssim.load_scene_text(FORCES_SCENE)
    scene.set_integrator("semi-implicit-euler", dt=0.002)
    assert scene.integrator == "symplectic-euler"
    assert scene.dt == 0.002
    implicit = {m["name"]: m for m in fosssim.integrators()}["implicit-euler"]
    numbers = [o for o in implicit["options"] if o["type"] == "integer"]
    assert numbers, "implicit Euler has integer options"
    option = numbers[0]
    value = option["default"] + 1
    scene.set_integrator("implicit-euler", **{option["name"].replace("-", "_"): value})
    assert scene.integrator_options[option["name"]] == value


def test_set_integrator_refuses_what_the_registry_refuses():
    scene = fosssim.load_scene_text(FORCES_SCENE)
    with pytest.raises(fosssim.Error, match="unknown integrator 'leapfrog'.*symplectic-euler"):
        scene.set_integrator("leapfrog")
    with pytest.raises(fosssim.Error, match="has no option 'colour'"):
        scene.set_integrator("explicit-euler", colour=3)
    implicit = {m["name"]: m for m in fosssim.integrators()}["implicit-euler"]
    option = [o for o in implicit["options"] if o["type"] == "integer"][0]
    with pytest.raises(fosssim.Error, match=option["name"]):
        scene.set_integrator("implicit-euler", **{option["name"]: option["lowest"] - 1})
    with pytest.raises(ValueError, match="dt"):
        scene.set_integrator("explicit-euler", dt=-1.0)
    assert scene.integrator == "symplectic-euler"  # a refused change changes nothing


def test_the_integrator_cannot_change_under_a_simulation():
    scene = fosssim.load_scene_text(FORCES_SCENE)
    simulation = fosssim.Simulation(scene)
    with pytest.raises(ValueError, match="in use"):
        scene.set_integrator("explicit-euler")
    del simulation
    scene.set_integrator("explicit-euler")
    assert scene.integrator == "explicit-euler"


def test_the_package_has_the_projects_version():
    expected = os.environ.get("FOSSSIM_VERSION")
    if not expected:
        pytest.skip("FOSSSIM_VERSION is not set")
    assert fosssim.__version__ == expected
