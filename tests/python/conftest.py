"""Shared fixtures of the Python module's tests (tests/python/CMakeLists.txt runs them)."""

import os
import pathlib

import pytest


@pytest.fixture(scope="session")
def source_dir():
    """The repository, where assets/ and examples/ are."""
    return pathlib.Path(os.environ.get("FOSSSIM_SOURCE_DIR",
                                       pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture(scope="session")
def program():
    """The FOSSSim program of the same build, to compare bytes with."""
    path = os.environ.get("FOSSSIM_PROGRAM")
    if not path:
        pytest.skip("FOSSSIM_PROGRAM is not set")
    return path


# A scene with every kind of 2D force the registry sums, in the order of the file, with
# particles in general position: the derivatives tests evaluate each force there.
FORCES_SCENE = """<scene>
  <duration time="1"/>
  <integrator type="symplectic-euler" dt="0.01"/>
  <particle m="1.5" px="0.1" py="0.2" vx="0.3" vy="-0.1" fixed="0"/>
  <particle m="2" px="1.3" py="0.4" vx="-0.2" vy="0.5" fixed="0"/>
  <particle m="0.7" px="0.6" py="1.5" vx="0.1" vy="0.2" fixed="0"/>
  <edge i="0" j="1"/>
  <edge i="1" j="2"/>
  <springforce edge="0" k="7" l0="0.8" b="0.3"/>
  <springforce edge="1" k="3" l0="1.4"/>
  <gravitationalforce i="0" j="2" G="0.9"/>
  <vortexforce i="1" j="2" kbs="1.1" kvc="4"/>
  <dragdamping b="0.4"/>
  <simplegravity fx="0.5" fy="-9.81"/>
  <constantforce fx="2" fy="1"/>
</scene>
"""
