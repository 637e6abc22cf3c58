#!/usr/bin/env python3
"""docs/first-program.md is right: builds and runs exactly the code it shows, in C++ against a
fresh install of this build (find_package(gamephysics)) and in Python against build/python, and
checks that each prints the output the page shows, and that this output is the closed form of a
ball dropped from 5 m that bounces with C_R = 0.8.

Usage: check_first_program.py ROOT BUILD PYTHON [LINK_FLAGS]
"""
import math
import os
import pathlib
import re
import subprocess
import sys
import tempfile

G = 9.81  # m/s²


def blocks(markdown):
    """The code blocks marked with <!-- file: NAME --> by name, and the one marked <!-- output -->."""
    files, output = {}, None
    pattern = re.compile(r"<!-- (file: (\S+)|output) -->\n```\w*\n(.*?)```", re.DOTALL)
    for match in pattern.finditer(markdown):
        if match.group(2):
            files[match.group(2)] = match.group(3)
        else:
            output = match.group(3)
    return files, output


def closed_form(t):
    """y [m] and v [m/s] of the ball's centre: free fall from 5 m to the ground at 0.5 m, then
    up at 0.8 of the impact speed."""
    t1 = math.sqrt(2 * 4.5 / G)
    if t < t1:
        return 5 - 0.5 * G * t * t, -G * t
    up = 0.8 * G * t1
    return 0.5 + up * (t - t1) - 0.5 * G * (t - t1) ** 2, up - G * (t - t1)


def run(command, **kwargs):
    result = subprocess.run(command, capture_output=True, text=True, **kwargs)
    if result.returncode != 0:
        sys.exit(f"failed: {' '.join(command)}\n{result.stdout}{result.stderr}")
    return result.stdout


def main(root, build, python, link_flags=""):
    files, expected = blocks((pathlib.Path(root) / "docs/first-program.md").read_text("utf-8"))
    assert set(files) == {"CMakeLists.txt", "first.cpp", "first.py"}, files.keys()
    for line in expected.splitlines():
        t, y, v = (float(x) for x in re.findall(r"-?\d+\.\d+", line))
        exact_y, exact_v = closed_form(t)
        assert abs(y - exact_y) <= 0.0005 + 1e-9 and abs(v - exact_v) <= 0.0005 + 1e-9, (
            f"the page shows {line!r}; the closed form is y = {exact_y:.4f}, v = {exact_v:.4f}")
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        first = tmp / "first"
        first.mkdir()
        for name, text in files.items():
            (first / name).write_text(text, encoding="utf-8")
        run(["cmake", "--install", build, "--prefix", str(tmp / "prefix")])
        run(["cmake", "-S", str(first), "-B", str(first / "build"), "-DCMAKE_BUILD_TYPE=Release",
             f"-DCMAKE_PREFIX_PATH={tmp / 'prefix'}", f"-DCMAKE_EXE_LINKER_FLAGS={link_flags}"])
        run(["cmake", "--build", str(first / "build")])
        cpp = run([str(first / "build/first")])
        env = dict(os.environ, PYTHONPATH=str(pathlib.Path(build).resolve() / "python"))
        py = run([python, "first.py"], cwd=first, env=env)
    for language, printed in (("C++", cpp), ("Python", py)):
        if printed != expected:
            sys.exit(f"the {language} program prints\n{printed}but the page shows\n{expected}")
    print(f"both programs print what docs/first-program.md shows:\n{expected}", end="")


if __name__ == "__main__":
    main(*sys.argv[1:])
