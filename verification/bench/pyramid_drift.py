#!/usr/bin/env python3
"""How far the boxes of Box2D 3's pyramids drift, from a trajectory CSV of `gamephysics simulate`.

large_pyramid: how far its top box (box099_099) sank at the end and at most, how far it moved
sideways at most and at the end, and how far row 50's middle box (box050_075) moved sideways at
most. many_pyramids: how far its 400 top boxes (p*_9_9) sank, the deepest at the end and at most.
Read at the CSV's output instants only, so write it often (`--output-dt 0.25`).

Usage: pyramid_drift.py TRAJECTORY.csv
"""
import csv
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


def main(path):
    large = paths_of(path, lambda name: name in (TOP, MIDDLE))
    if len(large) == 2:
        top, middle = large[TOP], large[MIDDLE]
        end, most = sinks(top)
        x0, middle_x0 = top[min(top)][0], middle[min(middle)][0]
        print(f"top box sinks {end:.3f} m at the end, {most:.3f} m at most; sideways "
              f"{max(abs(x - x0) for x, _ in top.values()):.3f} m at most, "
              f"{abs(top[max(top)][0] - x0):.3f} m at the end; row 50's middle box sideways "
              f"{max(abs(x - middle_x0) for x, _ in middle.values()):.3f} m at most")
        return
    tops = paths_of(path, lambda name: name.startswith("p") and name.endswith("_9_9"))
    if not tops:
        sys.exit(f"error: {path}: neither large_pyramid's {TOP} and {MIDDLE} nor many_pyramids' "
                 "p*_9_9 top boxes")
    ends, mosts = zip(*(sinks(track) for track in tops.values()))
    print(f"{len(tops)} top boxes sink {max(ends) * 1000:.1f} mm at the end (the deepest), "
          f"{max(mosts) * 1000:.1f} mm at most")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
