#!/usr/bin/env python3
"""Checks an ensemble of the bouncing ball (gamephysics ensemble ... --oracle) against the closed
form: each sample's ball falls from its perturbed height y (radius 0.5 m) under g = 9.81 m/s^2,
so its first impact is at t = sqrt(2 (y - 0.5) / g) whatever its step and mass; and the engine
stays within 1e-6 m of the oracle. Usage: check_bouncing_ball.py DIR SAMPLES."""

import csv
import json
import math
import sys
from pathlib import Path

out, samples = Path(sys.argv[1]), int(sys.argv[2])
rows = list(csv.DictReader(open(out / "samples.csv", newline="")))
assert len(rows) == samples, f"{len(rows)} rows, expected {samples}"
assert [int(r["sample"]) for r in rows] == list(range(samples)), "samples out of order"
worst = 0.0
for r in rows:
    assert not r["error"], r["error"]
    y = float(r["ball.y"])
    assert 9.0 <= y <= 11.0, f"y = {y} outside 10 (1 +- 0.1)"
    expected = math.sqrt(2 * (y - 0.5) / 9.81)
    worst = max(worst, abs(float(r["impact1_t"]) - expected))
    assert r["oracle"] == "ok", r["oracle"]
    assert float(r["oracle_position_error"]) < 1e-6, r["oracle_position_error"]
# The engine resolves impacts at their time (IM:col2D's t_c) to about 1e-11 s (README).
assert worst < 1e-9, f"first impact off the closed form by {worst} s"
summary = json.load(open(out / "summary.json"))
assert summary["samples"] == samples and summary["failed"] == 0, summary
ys = [float(r["ball.y"]) for r in rows]
mean = sum(ys) / len(ys)
assert abs(summary["columns"]["ball.y"]["mean"] - mean) < 1e-12
# Uniform on [9, 11]: mean 10, standard deviation 2 / sqrt(12) = 0.577; Sobol points come close.
assert abs(mean - 10) < 0.01, mean
assert abs(summary["columns"]["ball.y"]["std"] - 2 / math.sqrt(12)) < 0.01
print(f"ok: {samples} samples, first impact within {worst:.1e} s of the closed form")
