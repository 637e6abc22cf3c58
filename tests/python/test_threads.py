"""set_threads: the engine's threads from Python, one by default as on the command line, with the
same numbers on any count."""
import subprocess

import numpy as np
import pytest

import gamephysics as gp


@pytest.fixture
def restore_threads():
    before = gp.threads()
    yield
    gp.set_threads(before)


def test_one_thread_by_default_as_on_the_command_line():
    assert gp.threads() == 1


@pytest.mark.parametrize("threads", [2, 0])
def test_any_thread_count_gives_the_command_lines_numbers(tmp_path, root, cli, restore_threads,
                                                           threads):
    # rain1000's second: its thousand discs' pairs are searched for impacts block by block on
    # the threads, and the falling discs collide among themselves.
    scene = str(root / "scenes/rain1000.json")
    csv = tmp_path / "rain.csv"
    subprocess.run([cli, "simulate", scene, "--out", str(csv), "--duration", "1",
                    "--threads", "1"], check=True, capture_output=True)
    rows = np.genfromtxt(csv, delimiter=",", skip_header=1, usecols=(2, 3, 4, 5, 6, 7))
    gp.set_threads(threads)
    assert gp.threads() == threads
    run = gp.simulate(scene, duration=1.0)
    # The CSV lists each instant's bodies in turn, as states holds them.
    assert np.array_equal(run.states.reshape(-1, 6), rows)


def space_after_a_second(scene):
    """The states of the bodies of `scene` after 60 calls of Space.step(1/60)."""
    space = gp.load_scene(scene).space()
    for _ in range(60):
        space.step(1 / 60)
    return [(*space.state(b).position, space.state(b).angle) for b in range(space.body_count)]


@pytest.mark.parametrize("threads", [2, 0])
def test_space_steps_give_the_same_numbers_on_any_thread_count(root, restore_threads, threads):
    scene = str(root / "scenes/rain1000.json")
    gp.set_threads(1)
    alone = space_after_a_second(scene)
    gp.set_threads(threads)
    assert space_after_a_second(scene) == alone


def test_a_negative_count_is_refused_and_changes_nothing(restore_threads):
    gp.set_threads(2)
    with pytest.raises(gp.InputError, match=r"^threads: must be >= 0 \(0: every core\), got -1$"):
        gp.set_threads(-1)
    assert gp.threads() == 2
