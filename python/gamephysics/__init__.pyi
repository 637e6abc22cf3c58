"""Type stubs of gamephysics (python/gamephysics/__init__.py and its compiled part, _core)."""
import enum
import os
from typing import Callable, NamedTuple, Optional, Union

import numpy
import numpy.typing

from . import models as models

Vector = numpy.typing.ArrayLike  # two numbers, SI units
Body = Union[int, str]  # a body's id or its name

class InputError(ValueError): ...
class NumericalError(ArithmeticError): ...

class Integrator(enum.Enum):
    symplectic_euler = ...
    velocity_verlet = ...
    rk4 = ...

class BodyType(enum.Enum):
    dynamic = ...
    static = ...
    kinematic = ...

class Settings:
    gravity: numpy.ndarray
    G: Optional[float]
    integrator: Integrator
    velocity_iterations: int
    position_iterations: int
    restitution_threshold: float
    max_impacts_per_step: int
    sleep: bool
    sleep_speed: float
    sleep_angular_speed: float
    time_to_sleep: float
    coloured_island_contacts: int
    island_part_contacts: int
    island_parts: int
    def __init__(self, gravity: Vector = ..., G: Optional[float] = ...,
                 integrator: Integrator = ...) -> None: ...

class Shape:
    @staticmethod
    def circle(radius: float, center: Vector = ...) -> Shape: ...
    @staticmethod
    def box(width: float, height: float, center: Vector = ...) -> Shape: ...
    @staticmethod
    def polygon(vertices: list[Vector]) -> Shape: ...
    @staticmethod
    def segment(a: Vector, b: Vector, radius: float = ...) -> Shape: ...

class ShapeDef:
    shape: Shape
    restitution: float
    friction: float
    density: float
    def __init__(self, shape: Shape, restitution: float = ..., friction: float = ...,
                 density: float = ...) -> None: ...

class BodyDef:
    name: str
    type: BodyType
    position: numpy.ndarray
    angle: float
    velocity: numpy.ndarray
    angular_velocity: float
    mass: Optional[float]
    moment: Optional[float]
    force: numpy.ndarray
    force_point: Optional[numpy.ndarray]
    torque: float
    shapes: list[ShapeDef]
    def __init__(self, name: str, type: BodyType = ..., position: Vector = ...,
                 angle: float = ..., velocity: Vector = ..., angular_velocity: float = ...,
                 mass: Optional[float] = ..., moment: Optional[float] = ...,
                 force: Vector = ..., force_point: Optional[Vector] = ..., torque: float = ...,
                 shapes: list[ShapeDef] = ...) -> None: ...

class BodyState:
    position: numpy.ndarray
    angle: float
    velocity: numpy.ndarray
    angular_velocity: float

class Wrench:
    force: numpy.ndarray
    torque: float
    def __init__(self, force: Vector = ..., torque: float = ...) -> None: ...

class Impact:
    time: float
    body_a: int
    body_b: int
    normal: numpy.ndarray
    point: numpy.ndarray
    impulse: float

class ContactPoint:
    body_a: int
    body_b: int
    point: numpy.ndarray
    normal: numpy.ndarray
    normal_impulse: float
    tangent_impulse: float

class Space:
    time: float
    body_count: int
    def __init__(self, settings: Settings = ...) -> None: ...
    def add_body(self, body: BodyDef) -> int: ...
    def step(self, dt: float) -> None: ...
    def name(self, body: int) -> str: ...
    def find_body(self, name: str) -> Optional[int]: ...
    def state(self, body: Body) -> BodyState: ...
    def mass(self, body: Body) -> float: ...
    def moment(self, body: Body) -> float: ...
    def set_position(self, body: Body, position: Vector) -> None: ...
    def set_angle(self, body: Body, angle: float) -> None: ...
    def set_velocity(self, body: Body, velocity: Vector) -> None: ...
    def set_angular_velocity(self, body: Body, angular_velocity: float) -> None: ...
    def apply_impulse(self, body: Body, impulse: Vector, point: Optional[Vector] = ...) -> None: ...
    def apply_force(self, body: Body, force: Vector, point: Optional[Vector] = ...) -> None: ...
    def remove_body(self, body: Body) -> None: ...
    def removed(self, body: int) -> bool: ...
    def impacts(self) -> list[Impact]: ...
    def contact_points(self) -> list[ContactPoint]: ...
    def set_force_callback(self, body: Body,
                           callback: Callable[[float, int, BodyState], Wrench]) -> None: ...

class Scene:
    path: str
    dt: float
    duration: float
    output_dt: float
    settings: Settings
    bodies: list[BodyDef]
    def space(self) -> Space: ...

def load_scene(path: str, integrator: Optional[str] = ..., dt: Optional[float] = ...,
               duration: Optional[float] = ..., output_dt: Optional[float] = ...) -> Scene: ...

class BodyTrajectory(NamedTuple):
    x: numpy.ndarray
    y: numpy.ndarray
    angle: numpy.ndarray
    vx: numpy.ndarray
    vy: numpy.ndarray
    omega: numpy.ndarray

class Trajectory:
    t: numpy.ndarray
    names: list[str]
    states: numpy.ndarray
    def __getitem__(self, body: Union[str, int]) -> BodyTrajectory: ...

def set_threads(threads: int) -> None: ...
def threads() -> int: ...
def set_lanes(lanes: int) -> None: ...
def lanes() -> int: ...

def simulate(scene: Union[Scene, str, os.PathLike[str]], integrator: Optional[str] = ...,
             dt: Optional[float] = ..., duration: Optional[float] = ...,
             output_dt: Optional[float] = ...) -> Trajectory: ...

def oracle(scene: Union[Scene, str, os.PathLike[str]], method: str = ..., rtol: float = ...,
           atol: float = ..., duration: Optional[float] = ...,
           output_dt: Optional[float] = ..., step: float = ...) -> Trajectory: ...
