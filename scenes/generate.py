#!/usr/bin/env python3
"""Writes the large shipped scenes, pyramid20.json and rain1000.json, into this folder (or into
the folder given as the only argument: a test compares that output with the committed files).

Positions are on regular grids (no randomness), so the files are reproducible; run
`python3 scenes/generate.py` after changing this script and commit its output. One body per line
keeps the files small and their diffs readable. Standard library only.
"""

import json
import sys
from pathlib import Path

OUT = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parent
GRAVITY = [0, -9.81]
DT = 1 / 60  # the game step


def write_scene(name, header, bodies):
    """header: the scene's fields except bodies, in order; bodies: a list of body objects."""
    lines = [f"  {json.dumps(key)}: {json.dumps(value)}," for key, value in header.items()]
    body_lines = ",\n".join(f"    {json.dumps(body)}" for body in bodies)
    text = "{\n" + "\n".join(lines) + '\n  "bodies": [\n' + body_lines + "\n  ]\n}\n"
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / name).write_text(text)


def pyramid20():
    """210 unit boxes in 20 rows resting on a static ground box; each box straddles two below."""
    rows, size, gap, friction = 20, 1.0, 0.05, 0.6
    bodies = [{
        "name": "ground", "type": "static", "position": [0, -0.5],
        "shapes": [{"type": "box", "width": 40, "height": 1, "friction": friction}],
    }]
    pitch = size + gap
    for row in range(rows):
        count = rows - row
        for column in range(count):
            x = (column - (count - 1) / 2) * pitch
            y = size / 2 + row * size
            bodies.append({
                "name": f"box{row:02d}_{column:02d}", "position": [round(x, 6), y],
                "shapes": [{"type": "box", "width": size, "height": size, "friction": friction}],
            })
    write_scene("pyramid20.json", {
        "description": "A pyramid of 210 unit boxes (1 kg each) in 20 rows, 0.05 m apart, "
                       "friction 0.6, on a static ground box 40 m wide: it should stand still.",
        "gravity": GRAVITY, "dt": DT, "duration": 5.0, "output_dt": 0.1,
    }, bodies)


def rain1000():
    """1000 balls on a 40 x 25 grid, alternate rows offset by half a pitch, falling into an open
    box of three static segments 80 m wide."""
    columns, rows, pitch, radius, friction = 40, 25, 1.5, 0.5, 0.6
    half_width, wall_height = 40.0, 60.0
    bodies = [{
        "name": "box", "type": "static", "position": [0, 0],
        "shapes": [
            {"type": "segment", "a": [-half_width, 0], "b": [half_width, 0], "friction": friction},
            {"type": "segment", "a": [-half_width, 0], "b": [-half_width, wall_height],
             "friction": friction},
            {"type": "segment", "a": [half_width, 0], "b": [half_width, wall_height],
             "friction": friction},
        ],
    }]
    for row in range(rows):
        offset = pitch / 2 if row % 2 else 0.0
        for column in range(columns):
            x = (column - (columns - 1) / 2) * pitch + offset
            y = 5.0 + row * pitch
            bodies.append({
                "name": f"ball{row * columns + column:04d}", "position": [x, y],
                "shapes": [{"type": "circle", "radius": radius, "friction": friction}],
            })
    write_scene("rain1000.json", {
        "description": "1000 balls of radius 0.5 m (density 1 kg/m^2), friction 0.6, released "
                       "from a 40 x 25 grid 1.5 m apart into an open box of three static "
                       "segments 80 m wide, where they come to rest in a heap.",
        "gravity": GRAVITY, "dt": DT, "duration": 8.0, "output_dt": 0.1,
    }, bodies)


if __name__ == "__main__":
    pyramid20()
    rain1000()
