#!/usr/bin/env python3
"""How far large_pyramid's boxes drift, from a trajectory CSV of `gamephysics simulate`.

Prints, for the top box (box099_099): how far it sank at the end and at most, and how far it moved
sideways at most and at the end; and for the box in the middle of row 50 (box050_075), the farthest
it moved sideways. Read at the CSV's output instants only, so write it often (`--output-dt 0.25`).

Usage: pyramid_drift.py TRAJECTORY.csv
"""
import csv
import sys

TOP, MIDDLE = "box099_099", "box050_075"


def main(path):
    paths = {TOP: {}, MIDDLE: {}}
    with open(path, newline="") as file:
        for row in csv.DictReader(file):
            if row["body"] in paths:
                paths[row["body"]][float(row["t"])] = (float(row["x"]), float(row["y"]))
    if not all(paths.values()):
        sys.exit(f"error: {path}: no rows of {TOP} and {MIDDLE}; is it large_pyramid's?")
    top = paths[TOP]
    (x0, y0), end = top[min(top)], top[max(top)]
    middle = paths[MIDDLE]
    middle_x0 = middle[min(middle)][0]
    print(f"top box sinks {y0 - end[1]:.3f} m at the end, {max(y0 - y for _, y in top.values()):.3f} m at most; "
          f"sideways {max(abs(x - x0) for x, _ in top.values()):.3f} m at most, {abs(end[0] - x0):.3f} m "
          f"at the end; row 50's middle box sideways {max(abs(x - middle_x0) for x, _ in middle.values()):.3f} m at most")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
