#!/usr/bin/env python3
"""Writes the generated shipped scenes into this folder (or into the folder given as the only
argument: a test compares that output with the committed files): the large ones, pyramid20.json
and rain1000.json, the small pile ensembles/rain100.json, and the contact scenes of the oracle
(bodies resting, sliding, rolling, tipping, settling), whose placements on slopes are computed
here.

With `--bench DIR` it writes instead the benchmark scenes of Box2D 3's suite (its
shared/benchmarks.c), too large to commit, which the build generates for gamephysics_bench:
large_pyramid.json (and large_pyramid_coloured.json, its island solved colour by colour),
many_pyramids.json and tumbler.json; and rain1000_coloured.json, rain1000.json's pile solved colour
by colour.

Positions are on regular grids (no randomness), so the files are reproducible; run
`python3 scenes/generate.py` after changing this script and commit its output. One body per line
keeps the files small and their diffs readable. Standard library only.
"""

import argparse
import json
import math
from pathlib import Path

OUT = Path(__file__).resolve().parent  # where write_scene writes; main() may change it
GRAVITY = [0, -9.81]
DT = 1 / 60  # the game step


def write_scene(name, header, bodies):
    """header: the scene's fields except bodies, in order; bodies: a list of body objects."""
    lines = [f"  {json.dumps(key)}: {json.dumps(value)}," for key, value in header.items()]
    body_lines = ",\n".join(f"    {json.dumps(body)}" for body in bodies)
    text = "{\n" + "\n".join(lines) + '\n  "bodies": [\n' + body_lines + "\n  ]\n}\n"
    (OUT / name).parent.mkdir(parents=True, exist_ok=True)
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


def rain(name, columns, rows, half_width, duration, description, settings=None):
    """columns x rows balls, alternate rows offset by half a pitch, falling into an open box of
    three static segments 2 * half_width wide; `settings` are added to the scene's header."""
    pitch, radius, friction, wall_height = 1.5, 0.5, 0.6, 60.0
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
    write_scene(name, {
        "description": description,
        "gravity": GRAVITY, "dt": DT, "duration": duration, "output_dt": 0.1,
        **(settings or {}),
    }, bodies)


RAIN1000 = ("1000 balls of radius 0.5 m (density 1 kg/m^2), friction 0.6, released from a 40 x 25 "
            "grid 1.5 m apart into an open box of three static segments 80 m wide, where they come "
            "to rest in a heap.")


def rain1000():
    """1000 balls on a 40 x 25 grid falling into a box 80 m wide."""
    rain("rain1000.json", 40, 25, 40.0, 8.0, RAIN1000)


def rain1000_coloured():
    """rain1000.json with every island of more than one contact solved colour by colour, as
    Box2D 3 solves every island: its one-point contacts then go four at a time (AVX2)."""
    rain("rain1000_coloured.json", 40, 25, 40.0, 8.0, RAIN1000 + " Colour by colour.",
         {"coloured_island_contacts": 1})


def rain100():
    """100 balls on a 10 x 10 grid falling into a box 20 m wide: the pile of the ensembles
    (docs/ensembles.md), small enough for thousands of samples. In a folder of its own, so that
    `verify`, which runs every scene of scenes/, does not take it for one of its scenes."""
    rain("ensembles/rain100.json", 10, 10, 10.0, 3.0,
         "100 balls of radius 0.5 m (density 1 kg/m^2), friction 0.6, released from a "
         "10 x 10 grid 1.5 m apart into an open box of three static segments 20 m wide; "
         "after 3 s they are piling up.")


def box(width, height, **surface):
    return {"type": "box", "width": width, "height": height, **surface}


def on_slope(angle, along, above):
    """The point `along` metres up a slope through the origin at `angle` (rad) and `above` metres
    off it, along its normal."""
    return [along * math.cos(angle) - above * math.sin(angle),
            along * math.sin(angle) + above * math.cos(angle)]


def slope_scene(name, description, angle, body, duration=1.0):
    """A static ramp 20 m long, 1 m thick, whose top face runs through the origin at `angle`,
    and one body on it."""
    ramp = {"name": "ramp", "type": "static", "angle": angle,
            "position": on_slope(angle, 0.0, -0.5), "shapes": [box(20, 1, friction=body.pop("ramp_friction"))]}
    write_scene(name, {"description": description, "gravity": GRAVITY, "dt": DT,
                       "duration": duration, "output_dt": 0.05}, [ramp, body])


def contact_scenes():
    """The oracle's contact scenes with closed forms (docs/oracle.md), and a settling pile."""
    ramp = math.radians(30)
    slope_scene("ramp_slide.json",
                "A 1 m x 0.5 m block released 2 m up a 30-degree ramp, friction 0.2 on both: it "
                "slides down with a = g (sin 30 - 0.2 cos 30) = 3.206 m/s^2.",
                ramp, {"name": "block", "angle": ramp, "position": on_slope(ramp, 2.0, 0.25),
                       "shapes": [box(1, 0.5, friction=0.2)], "ramp_friction": 0.2})
    slope_scene("disc_roll.json",
                "A uniform disc of radius 0.5 m released 2 m up a 30-degree ramp, friction 0.6: "
                "it rolls without slipping, a = 2/3 g sin 30 = 3.27 m/s^2 and omega = -v/r.",
                ramp, {"name": "disc", "position": on_slope(ramp, 2.0, 0.5),
                       "shapes": [{"type": "circle", "radius": 0.5, "friction": 0.6}],
                       "ramp_friction": 0.6})
    hill = math.radians(20)
    slope_scene("static_friction.json",
                "A 1 m box at rest on a 20-degree slope, friction 0.6 > tan 20 = 0.364: static "
                "friction holds it where it is.",
                hill, {"name": "box", "angle": hill, "position": on_slope(hill, 0.0, 0.5),
                       "shapes": [box(1, 1, friction=0.6)], "ramp_friction": 0.6})
    ground = {"name": "ground", "type": "static", "position": [0, -0.5],
              "shapes": [box(20, 1, friction=0.6)]}
    write_scene("box_drop.json", {
        "description": "A 1 m box dropped flat from 1 m onto the ground, C_R = 0: it lands at "
                       "t = sqrt(2/9.81) = 0.4515 s and stays at rest.",
        "gravity": GRAVITY, "dt": DT, "duration": 1.0, "output_dt": 0.05,
    }, [ground, {"name": "box", "position": [0, 1.5], "shapes": [box(1, 1, friction=0.6)]}])
    write_scene("stack3.json", {
        "description": "Three 1 m boxes stacked at rest on the ground, friction 0.6: they stay.",
        "gravity": GRAVITY, "dt": DT, "duration": 2.0, "output_dt": 0.05,
    }, [ground] + [{"name": f"box{k}", "position": [0, 0.5 + k],
                    "shapes": [box(1, 1, friction=0.6)]} for k in range(3)])
    write_scene("step_tip.json", {
        "description": "A 1 m box on the edge of a step, its centre 0.3 m beyond the edge, "
                       "friction 1: it tips over the edge, turning about it while it sticks "
                       "(omega^2 = 2 m g (h0 - h) / I_edge).",
        "gravity": GRAVITY, "dt": DT, "duration": 0.5, "output_dt": 0.025,
    }, [{"name": "step", "type": "static", "position": [-2.5, -0.5],
         "shapes": [box(5, 1, friction=1.0)]},
        {"name": "box", "position": [0.3, 0.5], "shapes": [box(1, 1, friction=1.0)]}])
    rows, pitch = 6, 1.05
    bodies = [{"name": "ground", "type": "static", "position": [0, -0.5],
               "shapes": [box(20, 1, friction=0.6)]}]
    for row in range(rows):
        count = rows - row
        for column in range(count):
            bodies.append({"name": f"box{row}_{column}",
                           "position": [round((column - (count - 1) / 2) * pitch, 6), 0.5 + row],
                           "shapes": [box(1, 1, friction=0.6)]})
    write_scene("pyramid6.json", {
        "description": "A pyramid of 21 unit boxes in 6 rows, 0.05 m apart, friction 0.6, on a "
                       "static ground box: it should stand still.",
        "gravity": GRAVITY, "dt": DT, "duration": 2.0, "output_dt": 0.05,
    }, bodies)
    discs = [{"name": "box", "type": "static", "position": [0, 0], "shapes": [
        {"type": "segment", "a": [-3, 0], "b": [3, 0]},
        {"type": "segment", "a": [-3, 0], "b": [-3, 12]},
        {"type": "segment", "a": [3, 0], "b": [3, 12]}]}]
    for k in range(50):
        row, column = divmod(k, 5)
        discs.append({"name": f"disc{k:02d}",
                      "position": [-2.0 + column + 0.25 * (row % 2), 1.0 + 1.05 * row],
                      "shapes": [{"type": "circle", "radius": 0.4}]})
    write_scene("settle50.json", {
        "description": "50 frictionless discs of radius 0.4 m (C_R = 0) dropped into a 6 m wide "
                       "box: they settle into a heap. Chaotic: compare energy over time and the "
                       "settled heap, not trajectories.",
        "gravity": GRAVITY, "dt": DT, "duration": 3.0, "output_dt": 0.05,
    }, discs)


# Box2D 3's benchmarks run at 60 Hz under g = -10 m/s², density 1 and friction 0.6, sleeping off.
BENCH_GRAVITY = [0, -10]


def bench_box(x, y, half):
    return {"position": [x, y],
            "shapes": [{"type": "box", "width": 2 * half, "height": 2 * half, "friction": 0.6}]}


def large_pyramid():
    """5050 unit boxes in a pyramid of base 100 on a ground box 200 m x 2 m; 500 steps."""
    base, a = 100, 0.5
    bodies = [{"name": "ground", "type": "static", "position": [0, -1],
               "shapes": [{"type": "box", "width": 200, "height": 2, "friction": 0.6}]}]
    for i in range(base):
        y = (2 * i + 1) * a
        for j in range(i, base):
            x = (i + 1) * a + 2 * (j - i) * a - a * base
            bodies.append({"name": f"box{i:03d}_{j:03d}", **bench_box(x, y, a)})
    header = {
        "description": "Box2D 3's large_pyramid: 5050 unit boxes, base 100, on a 200 m ground box.",
        "gravity": BENCH_GRAVITY, "dt": DT, "duration": 500 * DT, "output_dt": 500 * DT,
    }
    write_scene("large_pyramid.json", header, bodies)
    # The same, its single island of about 10,000 contacts solved colour by colour, as Box2D 3
    # solves every island: what lets two threads share it.
    write_scene("large_pyramid_coloured.json", {
        **header, "description": header["description"] + " Colour by colour.",
        "coloured_island_contacts": 4096}, bodies)


def many_pyramids():
    """20 x 20 pyramids of base 10 (22,000 boxes) on 20 ground segments; 200 steps."""
    base, extent, rows, columns = 10, 0.5, 20, 20
    ground_dy = 2 * extent * (base + 1)
    ground_width = 2 * extent * columns * (base + 1)
    ground = {"name": "ground", "type": "static", "position": [0, 0], "shapes": [
        {"type": "segment", "a": [-0.5 * ground_width, r * ground_dy],
         "b": [0.5 * ground_width, r * ground_dy], "friction": 0.6} for r in range(rows)]}
    bodies = [ground]
    base_width = 2 * extent * base
    for r in range(rows):
        base_y = r * ground_dy
        for c in range(columns):
            center_x = -0.5 * ground_width + c * (base_width + 2 * extent) + 2 * extent
            for i in range(base):
                y = (2 * i + 1) * extent + base_y
                for j in range(i, base):
                    x = (i + 1) * extent + 2 * (j - i) * extent + center_x - 0.5
                    bodies.append({"name": f"p{r:02d}_{c:02d}_{i}_{j}", **bench_box(x, y, extent)})
    write_scene("many_pyramids.json", {
        "description": "Box2D 3's many_pyramids: 400 pyramids of base 10, 22,000 boxes.",
        "gravity": BENCH_GRAVITY, "dt": DT, "duration": 200 * DT, "output_dt": 200 * DT,
    }, bodies)


def tumbler():
    """2025 boxes of 0.25 m in a hollow 20 m box turning at 25°/s about its centre; 750 steps.
    Box2D drives its tumbler with a motor joint; here the box is kinematic."""
    walls = []
    for cx, cy, hx, hy in ((10, 0, 0.5, 10), (-10, 0, 0.5, 10), (0, 10, 10, 0.5), (0, -10, 10, 0.5)):
        walls.append({"type": "polygon", "friction": 0.6, "vertices": [
            [cx - hx, cy - hy], [cx + hx, cy - hy], [cx + hx, cy + hy], [cx - hx, cy + hy]]})
    bodies = [{"name": "tumbler", "type": "kinematic", "position": [0, 10],
               "angular_velocity": math.radians(25), "shapes": walls}]
    grid = 45
    for i in range(grid):
        y = -0.2 * grid + 10 + 0.4 * i
        for j in range(grid):
            x = -0.2 * grid + 0.4 * j
            bodies.append({"name": f"box{i:02d}_{j:02d}", **bench_box(x, y, 0.125)})
    write_scene("tumbler.json", {
        "description": "Box2D 3's tumbler: 2025 small boxes in a hollow box turning at 25°/s.",
        "gravity": BENCH_GRAVITY, "dt": DT, "duration": 750 * DT, "output_dt": 750 * DT,
    }, bodies)


def main():
    global OUT
    parser = argparse.ArgumentParser(
        description="Writes the generated scenes (see the top of this file).")
    parser.add_argument("--bench", action="store_true",
                        help="write Box2D 3's benchmark scenes instead of the shipped ones")
    parser.add_argument("folder", nargs="?", type=Path,
                        help="where to write them (default: this script's folder; "
                             "required with --bench)")
    args = parser.parse_args()
    if args.bench and args.folder is None:
        parser.error("--bench writes scenes too large to commit: give the folder to write into")
    if args.folder is not None:
        OUT = args.folder
    if args.bench:
        large_pyramid()
        many_pyramids()
        tumbler()
        rain1000_coloured()
    else:
        pyramid20()
        rain1000()
        rain100()
        contact_scenes()


if __name__ == "__main__":
    main()
