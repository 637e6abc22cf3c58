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


def test_a_dropped_ball_reports_its_impact_at_the_closed_form_time_and_impulse():
    h0, cr = 10.0, 0.8  # m of fall, C_R of the floor (C_R = max of the two shapes')
    space = gp.Space(gp.Settings(gravity=(0.0, -G)))
    ground = space.add_body(gp.BodyDef(
        "ground", type=gp.BodyType.static,
        shapes=[gp.ShapeDef(gp.Shape.segment((-10, 0), (10, 0)), cr)]))
    ball = space.add_body(puck("ball", (0.0, h0 + 0.5)))
    impacts = []
    for _ in range(120):  # 2 s: the first bounce only, the second is at 3.7 s
        space.step(1 / 60)
        impacts += space.impacts()
    assert len(impacts) == 1
    impact = impacts[0]
    # Free fall for h0: t_c = √(2 h0 / g), at v = √(2 g h0); against a static floor IM:col2D's
    # j = (1 + C_R) m v.
    assert impact.time == pytest.approx(math.sqrt(2 * h0 / G), abs=5e-15)
    assert impact.impulse == pytest.approx((1 + cr) * 2.0 * math.sqrt(2 * G * h0), rel=1e-14)
    up = 1.0 if impact.body_a == ball else -1.0  # the normal points from B towards A
    assert {impact.body_a, impact.body_b} == {ground, ball}
    assert list(impact.normal) == pytest.approx([0.0, up], abs=1e-15)
    assert list(impact.point) == pytest.approx([0.0, 0.0], abs=1e-12)


def test_the_contact_points_of_a_box_at_rest_carry_its_weight():
    space = gp.Space(gp.Settings(gravity=(0.0, -G)))
    ground = space.add_body(gp.BodyDef("ground", type=gp.BodyType.static,
                                       shapes=[gp.ShapeDef(gp.Shape.segment((-5, 0), (5, 0)))]))
    box = space.add_body(gp.BodyDef("box", position=(0.0, 0.5),
                                    shapes=[gp.ShapeDef(gp.Shape.box(1.0, 1.0))]))
    dt = 1 / 60
    for _ in range(60):
        space.step(dt)
    points = space.contact_points()
    assert len(points) == 2  # one at each corner of the box's bottom edge
    # At rest the floor's impulses over a step cancel what gravity adds, m g dt (the exact solve
    # of a small island holds to its compliance, 1e-10).
    assert sum(p.normal_impulse for p in points) == pytest.approx(space.mass(box) * G * dt,
                                                                  rel=1e-9)
    for p in points:
        assert {p.body_a, p.body_b} == {ground, box}
        assert abs(p.tangent_impulse) < 1e-15
        up = 1.0 if p.body_a == box else -1.0
        assert list(p.normal) == pytest.approx([0.0, up], abs=1e-15)
    # At the corners of the box's bottom edge, on the floor.
    corners = sorted(tuple(p.point) for p in points)
    assert [x for corner in corners for x in corner] == pytest.approx([-0.5, 0.0, 0.5, 0.0],
                                                                      abs=1e-12)
