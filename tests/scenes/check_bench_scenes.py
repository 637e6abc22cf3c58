#!/usr/bin/env python3
"""Checks the benchmark scenes that `scenes/generate.py --bench DIR` wrote into DIR against Box2D
3's definitions (shared/benchmarks.c), computed here by hand: body counts, corner and top boxes,
step counts at 60 Hz, and the tumbler's turning speed; and the coloured copies against their
originals."""
import json
import math
import sys
from pathlib import Path

folder = Path(sys.argv[1])
failures = []


def check(what, got, want, tolerance=1e-12):
    ok = abs(got - want) <= tolerance if isinstance(want, float) else got == want
    if not ok:
        failures.append(f"{what}: got {got}, want {want}")


def load(name):
    return json.loads((folder / name).read_text())


large = load("large_pyramid.json")
check("large_pyramid bodies", len(large["bodies"]), 1 + 5050)
# Row 0 starts at x = 0.5 - 50 + 0 = -49.5; the top box (i = j = 99) is at x = 0, y = 99.5.
check("large_pyramid first box x", large["bodies"][1]["position"][0], -49.5)
check("large_pyramid top box", large["bodies"][-1]["position"], [0.0, 99.5])
check("large_pyramid steps", round(large["duration"] / large["dt"]), 500)
check("large_pyramid gravity", large["gravity"], [0, -10])
coloured = load("large_pyramid_coloured.json")
check("large_pyramid_coloured bodies are large_pyramid's", coloured["bodies"] == large["bodies"], True)
check("large_pyramid_coloured colours islands over", coloured["coloured_island_contacts"], 4096)

many = load("many_pyramids.json")
check("many_pyramids bodies", len(many["bodies"]), 1 + 400 * 55)
check("many_pyramids ground segments", len(many["bodies"][0]["shapes"]), 20)
# Ground 220 m wide; the first pyramid's centre x = -110 + 1 = -109, its first box at -109 + 0.5
# - 0.5, on the floor at y = 0.5.
check("many_pyramids first box", many["bodies"][1]["position"], [-109.0, 0.5])
check("many_pyramids steps", round(many["duration"] / many["dt"]), 200)

tumbler = load("tumbler.json")
check("tumbler bodies", len(tumbler["bodies"]), 1 + 45 * 45)
check("tumbler turning speed", tumbler["bodies"][0]["angular_velocity"], 25 * math.pi / 180)
check("tumbler first box", tumbler["bodies"][1]["position"], [-9.0, 1.0])
check("tumbler steps", round(tumbler["duration"] / tumbler["dt"]), 750)

rain = load("rain1000_coloured.json")
shipped = json.loads((Path(__file__).resolve().parents[2] / "scenes" / "rain1000.json").read_text())
check("rain1000_coloured bodies are rain1000's", rain["bodies"] == shipped["bodies"], True)
check("rain1000_coloured colours islands over", rain["coloured_island_contacts"], 1)

print("\n".join(failures) if failures else "the benchmark scenes follow Box2D 3's definitions")
sys.exit(1 if failures else 0)
