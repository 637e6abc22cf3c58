#!/usr/bin/env python3
"""Compares two trajectory CSVs (t,body,x,y,angle,vx,vy,omega) row by row.

Usage: compare_trajectories.py A.csv B.csv TOLERANCE
Exits 0 when both have the same instants and bodies in the same order and every number agrees
within TOLERANCE (absolute; angles modulo 2 pi), 1 otherwise, printing the worst difference.
Standard library only.
"""

import csv
import math
import sys


def rows(path):
    with open(path, newline="") as f:
        return list(csv.reader(f))


def main(a_path, b_path, tolerance):
    a, b = rows(a_path), rows(b_path)
    if a[0] != b[0] or len(a) != len(b):
        print(f"different headers or row counts: {len(a)} and {len(b)} rows")
        return 1
    worst, where = 0.0, None
    for ra, rb in zip(a[1:], b[1:]):
        if ra[:2] != rb[:2]:
            print(f"rows differ in time or body: {ra[:2]} and {rb[:2]}")
            return 1
        for column, (x, y) in enumerate(zip(ra[2:], rb[2:]), start=2):
            d = abs(float(x) - float(y))
            if a[0][column] == "angle":
                d = min(d, 2 * math.pi - d)
            if d > worst:
                worst, where = d, (ra[0], ra[1], a[0][column])
    print(f"worst difference {worst:.3g} at t = {where[0] if where else '-'}"
          f" ({where[1] if where else '-'}, {where[2] if where else '-'})")
    return 0 if worst <= tolerance else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2], float(sys.argv[3])))
