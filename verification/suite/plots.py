"""Plots of the verification report, from the CSV files `gamephysics verify` writes.

Usage: python3 plots.py OUT_DIR   (reads OUT_DIR/data/*.csv, writes OUT_DIR/*.png and plots.txt)
Needs matplotlib (Debian: python3-matplotlib).
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only: no display on a build machine
import matplotlib.pyplot as plt  # noqa: E402


def rows(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def positive(value):
    # Exact results (error 0) cannot sit on a log axis: show them at the rounding floor.
    return max(float(value), 1e-16)


def save(fig, ax, out, name, made):
    # Grid, legend, file and the list of plots made: the same for every figure.
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, name), dpi=110)
    plt.close(fig)
    made.append(name)


def work_precision(out, made):
    data = rows(os.path.join(out, "data", "work_precision.csv"))
    for scene in sorted({r["scene"] for r in data}):
        fig, ax = plt.subplots(figsize=(6, 4.5))
        for method in sorted({r["method"] for r in data if r["scene"] == scene}):
            points = [r for r in data if r["scene"] == scene and r["method"] == method]
            ax.loglog([positive(r["position_error"]) for r in points],
                      [positive(r["cpu_seconds_per_simulated_second"]) for r in points],
                      marker="o", label=method)
        ax.set_xlabel("largest position error against the oracle [m]")
        ax.set_ylabel("CPU time per simulated second [s]")
        ax.set_title(f"speed against error: {scene}")
        save(fig, ax, out, f"wp_{scene}.png", made)


def convergence(out, made):
    data = rows(os.path.join(out, "data", "convergence.csv"))
    if not data:
        return
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for (scene, method) in sorted({(r["scene"], r["integrator"]) for r in data}):
        points = [r for r in data if r["scene"] == scene and r["integrator"] == method]
        ax.loglog([float(r["dt"]) for r in points], [positive(r["position_error"]) for r in points],
                  marker="o", label=f"{scene}: {method}")
    ax.set_xlabel("step dt [s]")
    ax.set_ylabel("largest position error [m]")
    ax.set_title("observed order of convergence")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "convergence.png"), dpi=110)
    plt.close(fig)
    made.append("convergence.png")


def accuracy(out, made):
    data = rows(os.path.join(out, "data", "accuracy.csv"))
    if not data:
        return
    scenes = sorted({r["scene"] for r in data})
    methods = sorted({r["integrator"] for r in data})
    fig, ax = plt.subplots(figsize=(8, 4.5))
    width = 0.8 / len(methods)
    for i, method in enumerate(methods):
        values = []
        for scene in scenes:
            match = [r for r in data if r["scene"] == scene and r["integrator"] == method]
            values.append(positive(match[0]["position"]) if match else math.nan)
        ax.bar([k + i * width for k in range(len(scenes))], values, width, label=method)
    ax.set_yscale("log")
    ax.set_xticks([k + 0.4 - width / 2 for k in range(len(scenes))])
    ax.set_xticklabels(scenes, rotation=30, ha="right")
    ax.set_ylabel("largest position error [m]")
    ax.set_title("game integrators against the oracle, at each scene's dt")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "accuracy.png"), dpi=110)
    plt.close(fig)
    made.append("accuracy.png")


def pile_energy(out, made):
    # The chaotic pile: energy over time, ours against the oracle (trajectories are not compared).
    data = rows(os.path.join(out, "data", "pile_energy.csv"))
    for scene in sorted({r["scene"] for r in data}):
        fig, ax = plt.subplots(figsize=(6, 4.5))
        for source in sorted({r["source"] for r in data if r["scene"] == scene}):
            points = [r for r in data if r["scene"] == scene and r["source"] == source]
            ax.plot([float(r["time"]) for r in points], [float(r["energy"]) for r in points],
                    marker="." if source == "ours" else None, label=source)
        ax.set_xlabel("time [s]")
        ax.set_ylabel("mechanical energy [J]")
        ax.set_title(f"energy over time: {scene}")
        save(fig, ax, out, f"energy_{scene}.png", made)


def main():
    out = sys.argv[1]
    made = []
    accuracy(out, made)
    convergence(out, made)
    work_precision(out, made)
    pile_energy(out, made)
    with open(os.path.join(out, "plots.txt"), "w") as f:
        f.write("".join(name + "\n" for name in made))


if __name__ == "__main__":
    main()
