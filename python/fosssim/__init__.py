"""FOSSSim, a physically based particle and mass-spring simulator, from Python.

Load a scene, step it, read its state as NumPy arrays, evaluate its forces and their
derivatives, write and grade trajectories, draw pictures. See docs/python.md.

    import fosssim
    scene = fosssim.load_scene("assets/t1m1/simplegravity.xml")
    sim = fosssim.Simulation(scene)
    sim.step(100)
    print(sim.time, sim.positions)
"""

__version__ = "@PROJECT_VERSION@"

from ._core import (
    Collision,
    Error,
    Force,
    Scene,
    SceneError,
    Simulation,
    StepError,
    TrajectoryWriter,
    contact_methods,
    grade,
    integrators,
    load_scene,
    load_scene_text,
    read_trajectory,
)

__all__ = [
    "__version__",
    "Collision",
    "Error",
    "Force",
    "Scene",
    "SceneError",
    "Simulation",
    "StepError",
    "TrajectoryWriter",
    "contact_methods",
    "grade",
    "integrators",
    "load_scene",
    "load_scene_text",
    "read_trajectory",
]
