"""set_lanes: the width of the engine's SIMD paths from Python, as the command line's --lanes,
with the same numbers on any width."""
import subprocess

import numpy as np
import pytest

import gamephysics as gp


@pytest.fixture
def restore_lanes():
    before = gp.lanes()
    yield
    gp.set_lanes(before)


def test_one_lane_runs_one_at_a_time(restore_lanes):
    gp.set_lanes(1)
    assert gp.lanes() == 1


@pytest.mark.parametrize("lanes", [1, 2])
def test_any_width_gives_the_command_lines_numbers(tmp_path, root, cli, restore_lanes, lanes):
    # rain1000's first two seconds: its discs land in a pile whose one-point contacts the widest
    # lanes solve four at a time.
    scene = str(root / "scenes/rain1000.json")
    csv = tmp_path / "rain.csv"
    subprocess.run([cli, "simulate", scene, "--out", str(csv), "--duration", "2"], check=True,
                   capture_output=True)
    rows = np.genfromtxt(csv, delimiter=",", skip_header=1, usecols=(2, 3, 4, 5, 6, 7))
    gp.set_lanes(lanes)
    assert gp.lanes() <= lanes
    run = gp.simulate(scene, duration=2.0)
    # The CSV lists each instant's bodies in turn, as states holds them.
    assert np.array_equal(run.states.reshape(-1, 6), rows)


def test_a_width_other_than_1_2_or_4_is_refused_and_changes_nothing(restore_lanes):
    gp.set_lanes(2)
    width = gp.lanes()
    with pytest.raises(gp.InputError, match=r"^lanes: must be 1, 2 or 4, got 3$"):
        gp.set_lanes(3)
    assert gp.lanes() == width
