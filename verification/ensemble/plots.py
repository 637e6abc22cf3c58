#!/usr/bin/env python3
"""The plots of an ensemble's folder (gamephysics ensemble): histograms of the final outputs that
vary, and the total energy over time (median, 5-95% band, mean +- std). Writes PNGs into the folder
and their names into plots.txt. Usage: plots.py DIR."""

import csv
import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

OUT = Path(sys.argv[1])


def numbers(cells):
    values = []
    for cell in cells:
        try:
            values.append(float(cell))
        except ValueError:
            values.append(math.nan)
    return values


def histograms(made):
    with open(OUT / "samples.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    ran = [r for r in rows if not r["error"]]
    # The final state of the moving bodies, the first impact and the final energy; at most 8.
    wanted = [c for c in rows[0]
              if c.startswith("final.") and c.endswith((".x", ".y", ".vx", ".vy", ".omega"))]
    wanted += ["impact1_t", "final.energy", "oracle_position_error"]
    columns = []
    for name in wanted:
        if name not in rows[0]:
            continue
        values = [v for v in numbers(r[name] for r in ran) if not math.isnan(v)]
        if len(values) > 1 and max(values) > min(values):
            columns.append((name, values))
    columns = columns[:8]
    if not columns:
        return
    fig, axes = plt.subplots(math.ceil(len(columns) / 4), min(4, len(columns)),
                             figsize=(4 * min(4, len(columns)), 3 * math.ceil(len(columns) / 4)),
                             squeeze=False)
    for ax, (name, values) in zip(axes.flat, columns):
        ax.hist(values, bins=min(50, max(10, len(values) // 20)))
        ax.set_title(name, fontsize=9)
    for ax in list(axes.flat)[len(columns):]:
        ax.axis("off")
    fig.suptitle(f"{len(ran)} samples ({len(rows) - len(ran)} failed)")
    fig.tight_layout()
    fig.savefig(OUT / "histograms.png", dpi=90)
    made.append("histograms.png")


def energy_over_time(made):
    with open(OUT / "energy.csv", newline="") as f:
        reader = csv.reader(f)
        times = [float(t) for t in next(reader)[1:]]
        series = [numbers(row[1:]) for row in reader]
    if not series:
        return
    median, low, high, mean, std = [], [], [], [], []
    for k in range(len(times)):
        column = sorted(s[k] for s in series if not math.isnan(s[k]))
        if not column:
            column = [math.nan]
        n = len(column)
        median.append(column[n // 2])
        low.append(column[int(0.05 * (n - 1))])
        high.append(column[int(math.ceil(0.95 * (n - 1)))])
        m = sum(column) / n
        mean.append(m)
        std.append(math.sqrt(sum((x - m) ** 2 for x in column) / max(1, n - 1)))
    fig, ax = plt.subplots(figsize=(8, 4))
    ax.fill_between(times, low, high, alpha=0.3, label="5% to 95%")
    ax.plot(times, median, label="median")
    ax.plot(times, [m - s for m, s in zip(mean, std)], ":", color="k", label="mean - std")
    ax.plot(times, [m + s for m, s in zip(mean, std)], ":", color="k", label="mean + std")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("total energy [J]")
    ax.set_title(f"spread of the energy over {len(series)} samples")
    ax.legend()
    fig.tight_layout()
    fig.savefig(OUT / "energy_spread.png", dpi=90)
    made.append("energy_spread.png")


def main():
    made = []
    histograms(made)
    energy_over_time(made)
    (OUT / "plots.txt").write_text("".join(name + "\n" for name in made))


main()
