"""The model functions from Python, against hand computations, and their docstrings."""
import inspect
import re

import pytest

import gamephysics as gp
from gamephysics.models import dd, gd, im, tm


def test_kinetic_energy_by_hand():
    # m = 2 kg, v = (3, 4) m/s, I = 0.5 kg·m², ω = 2 rad/s: ½ · 2 · 25 + ½ · 0.5 · 4 = 26 J.
    assert dd.kinetic_energy(2.0, [3.0, 4.0], 0.5, 2.0) == 26.0
    assert dd.kinetic_energy(mass=2.0, velocity=(3.0, 4.0)) == 25.0


def test_collision_impulse_and_response_by_hand():
    # Equal 1 kg discs head on, A at −1 m/s and B at +1 m/s along n = (1, 0) from B to A,
    # C_R = 1: j = −(1 + 1)(−2) / (1 + 1) = 2 N·s, and they swap velocities.
    j = gd.collision_impulse(1.0, (-2.0, 0.0), (1.0, 0.0), 1.0, 1.0, 0.0, 0.0, (0, 0), (0, 0))
    assert j == 2.0
    a = im.CollidingBody(1.0, 0.0, (-1.0, 0.0), 0.0, (0.0, 0.0))
    b = im.CollidingBody(1.0, 0.0, (1.0, 0.0), 0.0, (0.0, 0.0))
    response = im.collision_response(a, b, (1.0, 0.0), 1.0)
    assert list(response.velocity_a) == [1.0, 0.0]
    assert list(response.velocity_b) == [-1.0, 0.0]
    assert response.impulse == 2.0


def test_gravitation_and_second_law_by_hand():
    # F = G m₁ m₂ / d² towards body 2: 6.674e-11 · 1e3 · 2e3 / 2² = 3.337e-5 N along +x.
    force = tm.gravitational_force(6.674e-11, 1e3, 2e3, (2.0, 0.0))
    assert force[0] == pytest.approx(3.337e-5, rel=1e-12)
    assert list(tm.acceleration_from_force((4.0, -2.0), 2.0)) == [2.0, -1.0]
    assert list(im.translational_acceleration((0.0, -9.81), (0.0, 9.81), 1.0)) == [0.0, 0.0]


@pytest.mark.parametrize("module", [tm, gd, dd, im], ids=["tm", "gd", "dd", "im"])
def test_every_model_function_documents_its_srs_id_equation_and_units(module):
    prefix = module.__name__.rsplit(".", 1)[1].upper()
    functions = [f for name, f in vars(module).items()
                 if callable(f) and not inspect.isclass(f) and not name.startswith("_")]
    assert functions
    for f in functions:
        doc = f.__doc__
        assert re.search(rf"^{prefix}:\w+ — ", doc, re.MULTILINE), f.__name__
        assert " = " in doc, f.__name__      # the equation
        assert re.search(r"\[[^\]]+\]", doc), f.__name__  # units in brackets
