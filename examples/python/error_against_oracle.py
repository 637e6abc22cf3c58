"""Our error against the SUNDIALS oracle, beside Chipmunk2D's and Box2D's, on the bouncing ball.

The oracle (gp.oracle) solves the same scene to 1e-12; each engine runs it at five steps, from
1/15 s to 1/240 s, and its largest height error over 3 s is drawn against the step. Ours (velocity
Verlet, impacts at their exact time) stays at round-off; the peers' symplectic Euler and
end-of-step impacts err by centimetres to metres. Like for like, ours with symplectic Euler errs
by as much as the peers: the gap is the integrator's. The peers run through `gamephysics peer`,
matched to our physics (`--config matched`).

    PYTHONPATH=build/python python3 examples/python/error_against_oracle.py [--out error.png]
"""
import csv
import os
import pathlib
import subprocess
import tempfile

import numpy as np

import gamephysics as gp
from _figure import close_figure, open_figure

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENE = ROOT / "scenes" / "bouncing_ball.json"
# The command line beside the module (build/python/gamephysics → build/bin), unless GP_BIN says.
CLI = os.environ.get("GP_BIN", str(pathlib.Path(gp.__file__).resolve().parents[2] / "bin" /
                                   "gamephysics"))
DURATION = 3.0  # s: the first impact is at 1.39 s, the second at 3.6 s
OUTPUT_DT = 1 / 15  # s: instants shared by every run
STEPS = [1 / 15, 1 / 30, 1 / 60, 1 / 120, 1 / 240]


def peer_heights(engine, dt):
    """The ball's height at the shared instants, run by a peer engine."""
    with tempfile.TemporaryDirectory() as folder:
        out = pathlib.Path(folder) / "peer.csv"
        subprocess.run([CLI, "peer", str(SCENE), "--engine", engine, "--config", "matched",
                        "--out", str(out), "--dt", str(dt), "--duration", str(DURATION),
                        "--output-dt", str(OUTPUT_DT)], check=True, capture_output=True)
        with open(out, newline="") as rows:
            return np.array([float(r["y"]) for r in csv.DictReader(rows) if r["body"] == "ball"])


def main():
    args, figure, axes = open_figure(__doc__)
    reference = gp.oracle(SCENE, duration=DURATION, output_dt=OUTPUT_DT)["ball"].y
    errors = {"ours (velocity Verlet, double)": [], "ours (symplectic Euler, double)": [],
              "Chipmunk2D 7 (symplectic Euler, double)": [],
              "Box2D 2.4 (symplectic Euler, float)": []}
    for dt in STEPS:
        ours = gp.simulate(SCENE, dt=dt, duration=DURATION, output_dt=OUTPUT_DT)["ball"].y
        errors["ours (velocity Verlet, double)"].append(np.max(np.abs(ours - reference)))
        alike = gp.simulate(SCENE, integrator="symplectic_euler", dt=dt, duration=DURATION,
                            output_dt=OUTPUT_DT)["ball"].y
        errors["ours (symplectic Euler, double)"].append(np.max(np.abs(alike - reference)))
        errors["Chipmunk2D 7 (symplectic Euler, double)"].append(
            np.max(np.abs(peer_heights("chipmunk", dt) - reference)))
        errors["Box2D 2.4 (symplectic Euler, float)"].append(
            np.max(np.abs(peer_heights("box2d", dt) - reference)))
    for name, values in errors.items():
        print(f"{name}: " + ", ".join(f"{e:.2g} m" for e in values))
        axes.loglog(STEPS, np.maximum(values, 1e-16), marker="o", label=name)
    # Ours is exact between impacts and finds each impact's time: round-off at every step. The
    # peers integrate with symplectic Euler and resolve impacts at the end of the step.
    assert max(errors["ours (velocity Verlet, double)"]) < 1e-8
    first_order = [e for name, values in errors.items() if "symplectic" in name for e in values]
    assert min(first_order) > 1e-4
    close_figure(args, figure, axes, "step [s]", "largest height error against the oracle [m]",
                 "Bouncing ball: error against the SUNDIALS oracle")


if __name__ == "__main__":
    main()
