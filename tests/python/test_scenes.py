"""load_scene and simulate against closed forms and against the command line."""
import json
import math
import subprocess

import numpy as np
import pytest

import gamephysics as gp

G = 9.81  # m/s²


def ball_scene(path, restitution):
    """bouncing_ball.json with another C_R: a ball of radius 0.5 m dropped from 10 m."""
    scene = {
        "gravity": [0, -G], "dt": 1 / 60, "duration": 4.0, "output_dt": 0.01,
        "bodies": [
            {"name": "ground", "type": "static", "position": [0, 0],
             "shapes": [{"type": "segment", "a": [-10, 0], "b": [10, 0],
                         "restitution": restitution}]},
            {"name": "ball", "position": [0, 10],
             "shapes": [{"type": "circle", "radius": 0.5, "restitution": restitution}]}]}
    path.write_text(json.dumps(scene))
    return str(path)


@pytest.mark.parametrize("restitution", [0.5, 0.8, 1.0])
def test_a_bounce_follows_the_closed_form(tmp_path, restitution):
    run = gp.simulate(ball_scene(tmp_path / "ball.json", restitution))
    y = run["ball"].y
    # Free fall from 10 m to the ground at 0.5 m: t₁ = √(2 · 9.5 / g), v₁ = g t₁; then up at
    # C_R v₁ and down again: y = 0.5 + C_R v₁ (t − t₁) − ½ g (t − t₁)² until t₂ = t₁ + 2 C_R v₁ / g.
    t1 = math.sqrt(2 * 9.5 / G)
    v1 = G * t1
    t2 = t1 + 2 * restitution * v1 / G
    t = run.t
    before = t < t1
    after = (t > t1) & (t < min(t2, 4.0))
    exact_before = 10 - 0.5 * G * t[before] ** 2
    exact_after = 0.5 + restitution * v1 * (t[after] - t1) - 0.5 * G * (t[after] - t1) ** 2
    # Exact ballistic paths and the impact at its time of impact: rounding only (1e-9 is 1e6
    # times the rounding of 10 m, well under the 1e-6 the oracle test allows the game's run).
    assert np.max(np.abs(y[before] - exact_before)) < 1e-9
    assert np.max(np.abs(y[after] - exact_after)) < 1e-9
    assert after.sum() > 50
    # The top of the first rebound: 0.5 + C_R² · 9.5 m.
    assert np.max(y[after]) == pytest.approx(0.5 + restitution ** 2 * 9.5, abs=1e-3)


def test_simulate_gives_the_command_lines_numbers(tmp_path, root, cli):
    csv = tmp_path / "projectile.csv"
    subprocess.run([cli, "simulate", str(root / "scenes/projectile.json"), "--out", str(csv),
                    "--integrator", "rk4"], check=True, capture_output=True)
    rows = np.genfromtxt(csv, delimiter=",", skip_header=1, usecols=(0, 2, 3, 4, 5, 6, 7))
    run = gp.simulate(gp.load_scene(str(root / "scenes/projectile.json")), integrator="rk4")
    body = run["projectile"]
    ours = np.column_stack([run.t, body.x, body.y, body.angle, body.vx, body.vy, body.omega])
    # %.17g in the CSV reads back to the same double.
    assert np.array_equal(ours, rows)


def test_a_bad_scene_raises_the_command_lines_message(tmp_path, cli):
    bad = tmp_path / "bad.json"
    bad.write_text('{"dt": 0.01, "duration": 1, "bodies": '
                   '[{"name": "b", "position": [0, 0], "mass": -1}]}')
    result = subprocess.run([cli, "simulate", str(bad), "--out", str(tmp_path / "bad.csv")],
                            capture_output=True, text=True)
    assert result.returncode == 2
    with pytest.raises(gp.InputError) as error:
        gp.load_scene(str(bad))
    assert "error: " + str(error.value) + "\n" == result.stderr
    assert str(error.value).endswith("bodies[0].mass: must be > 0 (SRS data constraint m > 0), got -1")


def test_a_bad_option_raises_as_on_the_command_line(root):
    with pytest.raises(gp.InputError, match='integrator: must be one of symplectic_euler, '
                                            'velocity_verlet, rk4, got "euler"'):
        gp.simulate(str(root / "scenes/projectile.json"), integrator="euler")
    with pytest.raises(gp.InputError, match=r"dt: must be > 0"):
        gp.simulate(gp.load_scene(str(root / "scenes/projectile.json")), dt=-1.0)


@pytest.mark.parametrize("restitution", [0.5, 0.8])
def test_the_oracle_bounces_at_the_closed_form_times(tmp_path, restitution):
    run = gp.oracle(ball_scene(tmp_path / "ball.json", restitution), duration=2.5)
    t1 = math.sqrt(2 * 9.5 / G)
    v1 = G * t1
    t2 = t1 + 2 * restitution * v1 / G
    t = run.t
    y = run["ball"].y
    # Free fall, then the first rebound: the oracle is exact to its tolerance, 1e-12 here.
    before = t < t1
    between = (t > t1) & (t < t2)
    assert np.max(np.abs(y[before] - (10 - 0.5 * G * t[before] ** 2))) < 1e-9
    expected = 0.5 + restitution * v1 * (t[between] - t1) - 0.5 * G * (t[between] - t1) ** 2
    assert np.max(np.abs(y[between] - expected)) < 1e-9
    assert run.states.shape == (len(t), 2, 6)


def test_the_oracle_and_simulate_share_their_instants_and_agree(tmp_path):
    path = ball_scene(tmp_path / "ball.json", 0.8)
    game = gp.simulate(path, duration=1.0)
    reference = gp.oracle(path, duration=1.0, method="arkode-erk")
    np.testing.assert_array_equal(game.t, reference.t)
    # Free fall only (the first impact is at 1.39 s): velocity Verlet is exact under gravity.
    assert np.max(np.abs(game["ball"].y - reference["ball"].y)) < 1e-9


def test_the_oracle_time_steps_free_fall_exactly(tmp_path):
    # Time-stepping's positions follow the trapezoid, exact under constant gravity: the ball's
    # fall to 1 s (its first impact is at 1.39 s) matches the closed form to rounding.
    run = gp.oracle(ball_scene(tmp_path / "ball.json", 0.8), method="time-stepping", step=1e-3,
                    duration=1.0)
    assert np.max(np.abs(run["ball"].y - (10 - 0.5 * G * run.t ** 2))) < 1e-9


def test_the_oracle_refuses_a_scene_outside_its_domain(tmp_path):
    scene = json.loads(open(ball_scene(tmp_path / "ball.json", 0.5)).read())
    scene["bodies"][1]["position"] = [0, 0]  # the ball starts inside the ground
    path = tmp_path / "overlap.json"
    path.write_text(json.dumps(scene))
    with pytest.raises(ValueError, match="overlap"):
        gp.oracle(str(path))
    with pytest.raises(gp.InputError, match="method"):
        gp.oracle(str(path), method="euler")
