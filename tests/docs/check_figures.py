#!/usr/bin/env python3
"""Every marked figure of README.md and docs/*.md is what the program gives today.

A figure is marked by an HTML comment right after it (and its unit): `2.0e-9 m<!-- figure: KEY -->`.
KEY names an entry of figures.py, which either computes the figure by running the command line
(checked every time) or reads it from a row of `gamephysics verify`'s report.md (checked when
--report names a report; an entry marked long only by a report of `verify --long`). The figure
passes when the value rounds to it at the precision it is printed with: 4.5 admits [4.45, 4.55].
An unknown KEY, a marker with no number before it, or an entry no document uses fails.

Usage: check_figures.py --root ROOT --bin GAMEPHYSICS [--report DIR] [--docs FILE ...]
Exit 0 when every checked figure agrees, 1 when one does not, 2 on bad usage.
"""
import argparse
import pathlib
import re
import sys

import figures

NUMBER = r"[−-]?\d+(?:\.\d+)?(?:e[−-]?\d+)?"
# The figure is the last number before the marker, followed by at most a short unit (no digits).
MARKED = re.compile(r"(" + NUMBER + r")([^\d<>]{0,16})<!-- figure: ([\w.-]+) -->")
MARKER = re.compile(r"<!-- figure: ([\w.-]+) -->")


def parse_number(text):
    """The value of a printed figure and half a unit of its last digit."""
    text = text.replace("−", "-")
    mantissa, _, exponent = text.partition("e")
    decimals = len(mantissa.partition(".")[2])
    scale = 10.0 ** int(exponent or 0)
    return float(text), 0.5 * 10.0**-decimals * scale


def marked_figures(path):
    """(key, printed figure or None when no number stands right before it, line) of each marker."""
    text = path.read_text(encoding="utf-8")
    printed = {m.end(): m.group(1) for m in MARKED.finditer(text)}
    return [(m.group(1), printed.get(m.end()), text.count("\n", 0, m.start()) + 1)
            for m in MARKER.finditer(text)]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--root", type=pathlib.Path, required=True)
    parser.add_argument("--bin", type=pathlib.Path, required=True)
    parser.add_argument("--report", type=pathlib.Path, help="a report folder of gamephysics verify")
    parser.add_argument("--docs", type=pathlib.Path, nargs="*")
    args = parser.parse_args()
    docs = args.docs or [args.root / "README.md", *sorted((args.root / "docs").glob("*.md"))]
    registry = figures.registry()
    run = figures.Runner(args.root, args.bin)
    if args.report and not (args.report / "report.md").is_file():
        print(f"error: {args.report / 'report.md'}: no such file (gamephysics verify writes it)",
              file=sys.stderr)
        return 2
    report = figures.Report(args.report) if args.report else None

    failed, used = False, set()
    for doc in docs:
        for key, printed, line in marked_figures(doc):
            where = f"{doc.name}:{line} {key} = {printed}"
            used.add(key)
            if printed is None:
                print(f"FAILED {doc.name}:{line} {key}: no number right before the marker")
                failed = True
                continue
            entry = registry.get(key)
            if entry is None:
                print(f"FAILED {where}: no entry {key} in tests/docs/figures.py")
                failed = True
                continue
            try:
                value = entry.measure(run, report)
            except LookupError as error:
                print(f"FAILED {where}: {error}")
                failed = True
                continue
            if value is None:
                print(f"skip   {where}: {entry.skip_reason(report)}")
                continue
            figure, half_unit = parse_number(printed)
            ok = abs(value - figure) <= half_unit * (1 + 1e-9)
            failed |= not ok
            print(f"{'ok    ' if ok else 'FAILED'} {where}: measured {value:.6g} ({entry.source})")
    if not args.docs:
        for key in sorted(set(registry) - used):
            print(f"FAILED {key}: in tests/docs/figures.py but marked in no document")
            failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
