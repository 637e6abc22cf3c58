"""GamePhysics: 2D rigid bodies after the GamePhysics SRS (Drasil project), for Python.

A Space owns bodies made of shapes and advances them with step(); load_scene reads a scene file
(docs/scene-format.md) and simulate runs one into NumPy arrays. Both run on one thread unless
set_threads asks for more, with the same numbers on any count. The SRS's models are functions of
gamephysics.models.tm, .gd, .dd and .im, each documented with its SRS id, equation and units.
Units are SI throughout; vectors are NumPy arrays of two numbers.
"""
import os
import sys
from typing import NamedTuple, Optional, Union

import numpy as np

from ._core import (BodyDef, BodyState, BodyType, ContactPoint, Impact, InputError, Integrator,
                    NumericalError, Scene, Settings, Shape, ShapeDef, Space, Wrench, _oracle, _run,
                    lanes, load_scene, models, set_lanes, set_threads, threads)

# So that `from gamephysics.models import dd` works: the submodules are made by the compiled part.
sys.modules[__name__ + ".models"] = models
for _name in ("tm", "gd", "dd", "im"):
    sys.modules[f"{__name__}.models.{_name}"] = getattr(models, _name)

__all__ = ["BodyDef", "BodyState", "BodyTrajectory", "BodyType", "ContactPoint", "Impact",
           "InputError", "Integrator", "NumericalError", "Scene", "Settings", "Shape", "ShapeDef",
           "Space", "Trajectory", "Wrench", "lanes", "load_scene", "models", "oracle", "set_lanes",
           "set_threads", "simulate", "threads"]


class BodyTrajectory(NamedTuple):
    """One body's state at every output instant: the columns of the command line's CSV."""
    x: np.ndarray      # m, centre of mass
    y: np.ndarray      # m
    angle: np.ndarray  # rad, in [0, 2π)
    vx: np.ndarray     # m/s
    vy: np.ndarray     # m/s
    omega: np.ndarray  # rad/s


class Trajectory:
    """A run: the output instants t [s], the bodies' names, and each body's BodyTrajectory by name
    or id (run["ball"].y). states holds them all, shaped (instants, bodies, 6)."""

    def __init__(self, t: np.ndarray, names: list, states: np.ndarray):
        self.t = t
        self.names = names
        self.states = states

    def __getitem__(self, body: Union[str, int]) -> BodyTrajectory:
        j = self.names.index(body) if isinstance(body, str) else body
        return BodyTrajectory(*(self.states[:, j, q] for q in range(6)))

    def __repr__(self) -> str:
        return f"Trajectory({len(self.t)} instants from {self.t[0]} to {self.t[-1]} s, bodies {self.names})"


def simulate(scene: Union[Scene, str, os.PathLike], integrator: Optional[str] = None,
             dt: Optional[float] = None, duration: Optional[float] = None,
             output_dt: Optional[float] = None) -> Trajectory:
    """Runs a scene (a Scene, or the path of a scene file) as `gamephysics simulate` does, the
    options replacing the file's values as the command line's do (integrator: symplectic_euler,
    velocity_verlet or rk4; dt, duration, output_dt in s), on the threads of set_threads. Raises
    InputError with the command line's message for bad input, NumericalError if a state becomes
    non-finite."""
    overrides = dict(integrator=integrator, dt=dt, duration=duration, output_dt=output_dt)
    if not isinstance(scene, Scene):
        scene = load_scene(os.fspath(scene), **overrides)
    elif any(value is not None for value in overrides.values()):
        # Read again, so that the options are checked as the command line checks them.
        scene = load_scene(scene.path, **overrides)
    return Trajectory(*_run(scene))


def oracle(scene: Union[Scene, str, os.PathLike], method: str = "cvode-adams",
           rtol: float = 1e-12, atol: float = 1e-12, duration: Optional[float] = None,
           output_dt: Optional[float] = None, step: float = 1e-3) -> Trajectory:
    """Solves a scene (a Scene, or the path of a scene file) with the SUNDIALS oracle, as
    `gamephysics oracle` does (method: cvode-adams, cvode-bdf or arkode-erk; rtol, atol its
    tolerances; or time-stepping, first order, for piles, with its step in s), into the same
    Trajectory as simulate, at the same output instants: the reference
    to measure a simulation's error against (docs/oracle.md). Raises InputError for bad input,
    ValueError (a std::domain_error) when the scene leaves the oracle's domain."""
    overrides = dict(duration=duration, output_dt=output_dt)
    if not isinstance(scene, Scene):
        scene = load_scene(os.fspath(scene), **overrides)
    elif any(value is not None for value in overrides.values()):
        scene = load_scene(scene.path, **overrides)
    return Trajectory(*_oracle(scene, method, rtol, atol, step))
