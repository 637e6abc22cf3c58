"""The Space API from Python: a set state, impulses, forces, removal, against closed forms."""
import math

import pytest

import gamephysics as gp

G = 9.81  # m/s²


def puck(name="puck", position=(0.0, 0.0)):
    """A disc of 2 kg with moment 0.5 kg·m², given."""
    return gp.BodyDef(name, position=position, mass=2.0, moment=0.5,
                      shapes=[gp.ShapeDef(gp.Shape.circle(0.5))])


def test_a_set_velocity_then_free_flight_is_the_parabola():
    space = gp.Space(gp.Settings(gravity=(0.0, -G)))
    ball = space.add_body(puck())
    space.set_position(ball, (1.0, 20.0))
    space.set_velocity("puck", (3.0, 4.0))
    for _ in range(100):
        space.step(0.01)
    t = space.time
    state = space.state(ball)
    assert state.position[0] == pytest.approx(1.0 + 3.0 * t, abs=1e-12)
    assert state.position[1] == pytest.approx(20.0 + 4.0 * t - 0.5 * G * t * t, abs=1e-12)


def test_an_impulse_changes_v_by_j_over_m_and_omega_by_r_cross_j_over_i():
    space = gp.Space()
    body = space.add_body(puck(position=(1.0, 2.0)))
    space.apply_impulse(body, (3.0, -1.0))  # at the centre of mass: Δv = J / 2 kg
    assert list(space.state(body).velocity) == [1.5, -0.5]
    assert space.state(body).angular_velocity == 0.0
    # J = (0, 4) N·s, 0.25 m right of the centre: r × J = 0.25 · 4 = 1 N·m·s, Δω = 1 / 0.5.
    space.apply_impulse(body, (0.0, 4.0), point=(1.25, 2.0))
    assert list(space.state(body).velocity) == [1.5, 1.5]
    assert space.state(body).angular_velocity == 2.0


def test_a_force_acts_for_one_step():
    space = gp.Space()
    body = space.add_body(puck())
    space.apply_force(body, (10.0, 0.0))
    space.step(0.1)
    space.step(0.1)
    # a = 5 m/s² for 0.1 s, then coasting: v = 0.5 m/s, x = ½ · 5 · 0.01 + 0.5 · 0.1.
    assert space.state(body).velocity[0] == pytest.approx(0.5, abs=1e-15)
    assert space.state(body).position[0] == pytest.approx(0.075, abs=1e-15)


def test_a_removed_body_no_longer_holds_up_another():
    space = gp.Space(gp.Settings(gravity=(0.0, -G)))
    space.add_body(gp.BodyDef("ground", type=gp.BodyType.static,
                              shapes=[gp.ShapeDef(gp.Shape.segment((-5, 0), (5, 0)))]))
    space.add_body(gp.BodyDef("block", position=(0.0, 0.5),
                              shapes=[gp.ShapeDef(gp.Shape.box(1.0, 1.0))]))
    ball = space.add_body(puck("ball", (0.0, 1.5)))
    for _ in range(60):
        space.step(1 / 60)
    resting = space.state(ball).position[1]
    assert resting == pytest.approx(1.5, abs=1e-2)
    space.remove_body("block")
    assert space.find_body("block") is None
    for _ in range(12):
        space.step(1 / 60)
    # Free fall for 0.2 s: ½ g t², with the ball's speed at rest (< 1e-3 m/s) well inside.
    assert space.state(ball).position[1] == pytest.approx(resting - 0.5 * G * 0.2 ** 2, abs=1e-3)


def test_changes_are_checked_like_the_scene_file():
    space = gp.Space()
    space.add_body(gp.BodyDef("wall", type=gp.BodyType.static))
    body = space.add_body(puck())
    with pytest.raises(gp.InputError, match=r"^bodies\[1\]\.velocity: must be finite numbers, got \[nan, 0\]$"):
        space.set_velocity(body, (math.nan, 0.0))
    with pytest.raises(gp.InputError, match=r"^bodies\[0\]\.type: must be dynamic to take an impulse, got static$"):
        space.apply_impulse("wall", (1.0, 0.0))
    with pytest.raises(gp.InputError, match=r'^body: must name a body of the space, got "nobody"$'):
        space.state("nobody")


def test_settings_are_checked_like_the_scene_file():
    settings = gp.Settings()
    assert settings.island_parts == 2
    settings.island_parts = 3
    with pytest.raises(gp.InputError, match=r"^island_parts: must be a power of two from 2 to 64, got 3$"):
        gp.Space(settings)
    settings.island_parts = 8
    assert gp.Space(settings).body_count == 0
