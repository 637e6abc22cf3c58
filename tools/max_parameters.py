#!/usr/bin/env python3
"""Lists the functions declared or defined under the given folders that take more than N
parameters (default 6), and exits 1 if there are any.

Usage: max_parameters.py [--max N] FOLDER_OR_FILE...

A declaration is found by its shape: a name, a parenthesised list whose every entry reads as a
type followed by a name, then `{`, `;`, `const` or `override`. Calls do not match, because their
arguments are not typed.
"""
import argparse
import pathlib
import re
import sys

SIGNATURE = re.compile(
    r"\b([A-Za-z_][\w:<>~]*)\s*\(([^()]*(?:\([^()]*\)[^()]*)*)\)\s*(?:const)?\s*(?:override)?\s*[{;]")
KEYWORDS = {"if", "for", "while", "switch", "return", "sizeof", "static_assert", "decltype"}
TYPED = re.compile(r"[\w>&*]\s+[&*]?\w+\s*(=.*)?$")


def parameters(text):
    depth, count = 0, 1 if text.strip() else 0
    for ch in text:
        if ch in "<([{":
            depth += 1
        elif ch in ">)]}":
            depth -= 1
        elif ch == "," and depth == 0:
            count += 1
    return count


def too_long(path, most):
    code = re.sub(r"//[^\n]*", "", path.read_text())
    for match in SIGNATURE.finditer(code):
        name, args = match.group(1), match.group(2)
        if name in KEYWORDS or parameters(args) <= most:
            continue
        if all(TYPED.search(a.strip()) for a in args.split(",") if a.strip()):
            yield f"{path}: {name} takes {parameters(args)} parameters"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--max", type=int, default=6)
    parser.add_argument("paths", nargs="+", type=pathlib.Path)
    options = parser.parse_args()
    files = []
    for p in options.paths:
        files += sorted(p.rglob("*.[ch]pp")) if p.is_dir() else [p]
    found = [line for f in files for line in too_long(f, options.max)]
    print("\n".join(found) if found else f"no function takes more than {options.max} parameters")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
