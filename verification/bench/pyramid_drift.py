#!/usr/bin/env python3
"""How far the boxes of Box2D 3's pyramids drift, from a trajectory CSV of `gamephysics simulate`.

large_pyramid: how far its top box (box099_099) sank at the end and at most, how far it moved
sideways at most and at the end, and how far row 50's middle box (box050_075) moved sideways at
most. many_pyramids: how far its 400 top boxes (p*_9_9) sank, the deepest at the end and at most.
Both: the farthest any box moved from where it started.
Read at the CSV's output instants only, so write it often (`--output-dt 0.25`).

Usage: pyramid_drift.py TRAJECTORY.csv
"""
import csv
import math
import sys

TOP, MIDDLE = "box099_099", "box050_075"


def paths_of(path, wanted):
    """{body: {t: (x, y)}} of the bodies for which wanted(name) is true."""
    paths = {}
    with open(path, newline="") as file:
        for row in csv.DictReader(file):
            if wanted(row["body"]):
                paths.setdefault(row["body"], {})[float(row["t"])] = (float(row["x"]), float(row["y"]))
    return paths


def sinks(track):
    """How far a box sank [m]: at the last instant, and at most."""
    y0 = track[min(track)][1]
    return y0 - track[max(track)][1], max(y0 - y for _, y in track.values())


def farthest(paths):
    """The farthest any of the boxes `paths` moved from where it started [m]."""
    def moved(track):
        x0, y0 = track[min(track)]
        return max(math.hypot(x - x0, y - y0) for x, y in track.values())
    return max(moved(track) for track in paths.values())


def main(path):
    boxes = paths_of(path, lambda name: name.startswith(("box", "p")))
    if TOP in boxes and MIDDLE in boxes:
        top, middle = boxes[TOP], boxes[MIDDLE]
        end, most = sinks(top)
        x0, middle_x0 = top[min(top)][0], middle[min(middle)][0]
        print(f"top box sinks {end:.3g} m at the end, {most:.3g} m at most; sideways "
              f"{max(abs(x - x0) for x, _ in top.values()):.3g} m at most, "
              f"{abs(top[max(top)][0] - x0):.3g} m at the end; row 50's middle box sideways "
              f"{max(abs(x - middle_x0) for x, _ in middle.values()):.3g} m at most; "
              f"no box moved more than {farthest(boxes):.3g} m")
        return
    tops = {name: track for name, track in boxes.items() if name.endswith("_9_9")}
    if not tops:
        sys.exit(f"error: {path}: neither large_pyramid's {TOP} and {MIDDLE} nor many_pyramids' "
                 "p*_9_9 top boxes")
    ends, mosts = zip(*(sinks(track) for track in tops.values()))
    print(f"{len(tops)} top boxes sink {max(ends):.3g} m at the end (the deepest), "
          f"{max(mosts):.3g} m at most; no box moved more than {farthest(boxes):.3g} m")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
