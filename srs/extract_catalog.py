#!/usr/bin/env python3
"""Extract a machine-readable catalog from the GamePhysics SRS.

Parses the Drasil-generated Software Requirements Specification
(``shared/srs/GamePhysics_SRS.md``, Markdown with LaTeX math written as
``\\\\( ... \\\\)`` / ``\\\\[ ... \\\\]`` and Markdown-escaped characters) and
emits ``srs/catalog.json``: goals, assumptions, theoretical models, general
definitions, data definitions, instance models, input/output data constraints,
requirements, likely/unlikely changes and the traceability matrices.

Usage (from the repository root)::

    python3 srs/extract_catalog.py ../shared/srs/GamePhysics_SRS.md --out srs/catalog.json

Without a positional argument the SRS is looked up at
``<repo root>/srs/GamePhysics_SRS.md``, then ``<repo root>/../shared/srs/GamePhysics_SRS.md``; without ``--out`` the JSON is
printed to stdout.  The output is deterministic (``indent=2``,
``ensure_ascii=False``, fixed key order, trailing newline).

Conventions of the output:

* LaTeX is "unescaped" to what KaTeX renders: ``\\\\,`` -> ``\\,``,
  ``\\_`` -> ``_``, ``\\*`` -> ``*``, ``\\|`` -> ``|``; everything else is kept
  as the SRS writes it.  Equation fields carry no math delimiters.
* Prose fields (``text``, ``notes``, ``source``, descriptions) are plain text:
  Markdown links are reduced to their link text and inline math is kept as
  ``\\( ... \\)`` with unescaped LaTeX.
* Units are ASCII SI text (``"m/s^2"``, ``"kg*m^2"``, ``"1"`` for unitless).

The script exits non-zero with a message when the expected item counts or the
spot-checked traceability facts do not hold.  Consistency findings (SRS text
vs. traceability tables, table of symbols vs. model descriptions) are printed
to stderr as ``warning:`` lines; they do not change the exit status.

Standard library only.
"""

import argparse
import json
import math
import os
import re
import sys

# ---------------------------------------------------------------------------
# Constants
# ---------------------------------------------------------------------------

SCRIPT_DIR = os.path.dirname(os.path.abspath(__file__))
REPO_ROOT = os.path.dirname(SCRIPT_DIR)
WORKSPACE_ROOT = os.path.dirname(REPO_ROOT)
# Where a user puts the SRS (it is not in the repository), else beside the repository.
DEFAULT_SRS = next((p for p in (os.path.join(REPO_ROOT, "srs", "GamePhysics_SRS.md"),
                                os.path.join(WORKSPACE_ROOT, "shared", "srs", "GamePhysics_SRS.md"))
                    if os.path.exists(p)),
                   os.path.join(WORKSPACE_ROOT, "shared", "srs", "GamePhysics_SRS.md"))
LICENCE_NAME = "LICENSE-Drasil"

EXPECTED_COUNTS = {
    "goals": 2,
    "assumptions": 7,
    "theoretical_models": 4,
    "general_definitions": 2,
    "data_definitions": 15,
    "instance_models": 3,
    "input_constraints": 11,
    "output_constraints": 4,
    "functional_requirements": 8,
    "nonfunctional_requirements": 5,
    "likely_changes": 4,
    "unlikely_changes": 4,
}

# Facts from the SRS traceability tables that the parse must reproduce.
EXPECTED_USES = {
    "GD:accelGravity": ["TM:UniversalGravLaw"],
    "IM:transMot": ["DD:ctrOfMass", "DD:linDisp", "DD:linVel", "DD:linAcc",
                    "TM:NewtonSecLawMot", "GD:accelGravity"],
    "IM:rotMot": ["DD:angDisp", "DD:angVel", "DD:angAccel", "TM:NewtonSecLawRotMot"],
    "IM:col2D": ["DD:ctrOfMass", "GD:impulse"],
}
EXPECTED_ASSUMPTIONS = {
    "IM:col2D": ["A:objectTy", "A:objectDimension", "A:axesDefined",
                 "A:collisionType", "A:dampingInvolvement",
                 "A:constraintsAndJointsInvolvement"],
}

# Regular expressions over the raw (escaped) Markdown.
INLINE_MATH = r"\\\\\((.*?)\\\\\)"          # \\( ... \\)
DISPLAY_MATH = r"\\\\\[(.*?)\\\\\]"         # \\[ ... \\]
MATH_RE = re.compile(INLINE_MATH + "|" + DISPLAY_MATH, re.S)
INLINE_MATH_RE = re.compile(INLINE_MATH, re.S)
DISPLAY_MATH_RE = re.compile(DISPLAY_MATH, re.S)
LINK_RE = re.compile(r"\[([^\]]*)\]\(([^)]*)\)")
ID_LINK_RE = re.compile(r"\[((?:A|TM|GD|DD|IM|GS|FR|NFR|LC|UC):[^\]]+)\]\([^)]*\)")
H1_RE = re.compile(r"^# (.*?) \{#([^}]*)\}\s*$", re.M)
H2_RE = re.compile(r"^## (.*?) \{#([^}]*)\}\s*$", re.M)
H4_DERIV_RE = re.compile(r"^#### (.*?) \{#([^}]*)Deriv\}\s*$", re.M)
LABELLED_ITEM_RE = re.compile(
    r'<div id="([^"]+)"></div>\s*\n\s*\n([A-Za-z][\w-]*): ([^\n]*)')
LI_RE = re.compile(r"<li>(.*?)</li>", re.S)
DESCRIPTION_RE = re.compile(
    r"^\\\\\((?P<sym>.*?)\\\\\) is the (?P<desc>.*) "
    r"\((?:\\\\\((?P<unit>.*)\\\\\)|(?P<unitless>Unitless))\)$", re.S)


class SrsError(Exception):
    """Raised when the SRS does not have the structure this script expects."""


WARNINGS = []


def warn(message):
    """Record a non-fatal consistency finding (printed to stderr at the end)."""
    WARNINGS.append(message)


# ---------------------------------------------------------------------------
# Text helpers
# ---------------------------------------------------------------------------

def unescape_latex(latex):
    """Undo the Markdown escaping of LaTeX: \\\\, -> \\, ; \\_ -> _ ; \\* -> * ; \\| -> |."""
    def repl(match):
        return "\\" + match.group(1) if match.group(1) is not None else match.group(2)
    return re.sub(r"\\\\([^\w\s])|\\([_*|])", repl, latex).strip()


def unescape_markdown(text):
    """Undo Markdown backslash escapes in prose (outside math)."""
    return re.sub(r"\\([\\`*_{}\[\]()#+\-.!|<>])", r"\1", text)


def plain_text(markdown):
    """Convert inline Markdown to plain text.

    Links become their text, HTML tags are dropped, inline math is kept as
    ``\\( ... \\)`` (display math as ``\\[ ... \\]``) with unescaped LaTeX.
    """
    parts = []
    pos = 0
    for match in MATH_RE.finditer(markdown):
        parts.append(_plain_prose(markdown[pos:match.start()]))
        if match.group(1) is not None:
            parts.append("\\(" + unescape_latex(match.group(1)) + "\\)")
        else:
            parts.append("\\[" + unescape_latex(match.group(2)) + "\\]")
        pos = match.end()
    parts.append(_plain_prose(markdown[pos:]))
    return re.sub(r"\s+", " ", "".join(parts)).strip()


def _plain_prose(text):
    text = LINK_RE.sub(lambda m: m.group(1), text)
    text = re.sub(r"<[^>]+>", "", text)
    return unescape_markdown(text)


def single_inline_math(cell, what):
    """Return the unescaped LaTeX of the only inline math in ``cell``."""
    maths = INLINE_MATH_RE.findall(cell)
    if len(maths) != 1 or INLINE_MATH_RE.sub("", cell).strip():
        raise SrsError("expected exactly one inline formula for %s, got %r" % (what, cell))
    return unescape_latex(maths[0])


def display_maths(cell):
    """All display formulas (unescaped, without delimiters) in ``cell``."""
    return [unescape_latex(m) for m in DISPLAY_MATH_RE.findall(cell)]


def ids_in(text):
    """Catalog ids (``A:x``, ``DD:y`` ...) of the links in ``text``, in order."""
    return ID_LINK_RE.findall(text)


def null_if_dashes(cell):
    return None if cell.strip() in ("---", "") else cell


# ---------------------------------------------------------------------------
# Units and numbers
# ---------------------------------------------------------------------------

def _strip_braces(latex):
    latex = latex.strip()
    while latex.startswith("{") and latex.endswith("}") and _balanced(latex[1:-1]):
        latex = latex[1:-1].strip()
    return latex


def _balanced(latex):
    depth = 0
    for char in latex:
        depth += {"{": 1, "}": -1}.get(char, 0)
        if depth < 0:
            return False
    return depth == 0


def _unit_product(latex):
    """``\\text{kg}\\text{m}^{2}`` -> ``["kg", "m^2"]``."""
    latex = _strip_braces(latex)
    factor_re = re.compile(r"\\text\{([A-Za-z]+)\}(?:\^\{(-?\d+)\})?")
    factors, pos = [], 0
    for match in factor_re.finditer(latex):
        if latex[pos:match.start()].strip():
            raise SrsError("cannot read unit %r" % latex)
        factors.append(match.group(1) + ("^" + match.group(2) if match.group(2) else ""))
        pos = match.end()
    if latex[pos:].strip() or not factors:
        raise SrsError("cannot read unit %r" % latex)
    return factors


def unit_to_ascii(latex):
    """Convert an SRS unit (LaTeX or the word ``Unitless``) to ASCII SI text."""
    latex = unescape_latex(latex)
    if latex.strip() in ("Unitless", "---", ""):
        return "1"
    latex = _strip_braces(latex)
    frac = re.fullmatch(r"\\frac\{(.*?)\}\{(.*)\}", latex)
    if frac:
        num = _unit_product(frac.group(1))
        den = _unit_product(frac.group(2))
        num_text = "*".join(num)
        den_text = "*".join(den)
        if len(num) > 1:
            num_text = "(" + num_text + ")"
        if len(den) > 1:
            den_text = "(" + den_text + ")"
        return num_text + "/" + den_text
    return "*".join(_unit_product(latex))


def latex_number(latex):
    """Numeric value of a reasonable-value cell (as a float)."""
    text = latex.strip()
    sci = re.fullmatch(r"(-?[\d.]+)\\cdot\{\}10\^\{(-?\d+)\}", text)
    if sci:
        return float(sci.group(1) + "e" + sci.group(2))
    frac = re.fullmatch(r"\\frac\{(.*?)\}\{(.*?)\}", text)
    if frac:
        return latex_number(frac.group(1)) / latex_number(frac.group(2))
    if text == "π":
        return math.pi
    if re.fullmatch(r"-?\d+(\.\d+)?", text):
        return float(text)
    raise SrsError("cannot read number %r" % latex)


def percentage(cell):
    """``10\\\\(\\\\%\\\\)`` -> 0.1"""
    match = re.fullmatch(r"\s*(\d+(?:\.\d+)?)\s*\\\\\(\\\\%\\\\\)\s*", cell)
    if not match:
        raise SrsError("cannot read uncertainty %r" % cell)
    return float(match.group(1)) / 100.0


# ---------------------------------------------------------------------------
# Document structure
# ---------------------------------------------------------------------------

def split_sections(doc):
    """Map top-level section anchor (e.g. ``Sec:TMs``) -> section body."""
    heads = list(H1_RE.finditer(doc))
    sections = {}
    for index, head in enumerate(heads):
        end = heads[index + 1].start() if index + 1 < len(heads) else len(doc)
        sections[head.group(2)] = doc[head.end():end]
    return sections


def split_row(line):
    """Split a Markdown table row on unescaped ``|`` (escapes are kept)."""
    line = line.strip()
    if not (line.startswith("|") and line.endswith("|")):
        raise SrsError("not a table row: %r" % line[:80])
    cells, current, i = [], [], 1
    while i < len(line) - 1:
        char = line[i]
        if char == "\\" and i + 1 < len(line) - 1:
            current.append(line[i:i + 2])
            i += 2
            continue
        if char == "|":
            cells.append("".join(current))
            current = []
        else:
            current.append(char)
        i += 1
    cells.append("".join(current))
    return cells


def table_lines_after(text, start):
    """The consecutive ``|``-lines of the first table at or after ``start``."""
    lines = text[start:].split("\n")
    rows, started = [], False
    for line in lines:
        if line.startswith("|"):
            started = True
            rows.append(line)
        elif started:
            break
    if not rows:
        raise SrsError("no table found")
    return rows


def table_by_id(doc, table_id):
    """Header cells and data rows of the table placed after ``<div id=table_id>``."""
    marker = '<div id="%s"></div>' % table_id
    start = doc.find(marker)
    if start < 0:
        raise SrsError("table %s not found" % table_id)
    lines = table_lines_after(doc, start)
    header = split_row(lines[0])
    if not all(re.fullmatch(r":?-{3,}:?", c) for c in split_row(lines[1])):
        raise SrsError("table %s: missing separator row" % table_id)
    rows = [split_row(line) for line in lines[2:]]
    for row in rows:
        if len(row) != len(header):
            raise SrsError("table %s: row %r has %d cells, header has %d"
                           % (table_id, row[0], len(row), len(header)))
    return header, rows


def key_value_table(text):
    """Parse a two-column ``|Key|Value|`` model table into an ordered dict."""
    lines = table_lines_after(text, 0)
    result = {}
    for line in [lines[0]] + lines[2:]:
        cells = split_row(line)
        if len(cells) != 2:
            raise SrsError("model table row with %d cells: %r" % (len(cells), line[:80]))
        result[cells[0]] = cells[1]
    return result


def labelled_items(section):
    """``<div id=..>`` + ``Label: text`` paragraphs of a section, in order."""
    return [(anchor, label.strip(), text.strip())
            for anchor, label, text in LABELLED_ITEM_RE.findall(section)]


# ---------------------------------------------------------------------------
# Sections
# ---------------------------------------------------------------------------

def parse_source(doc, srs_path):
    title_match = re.match(r"# (.*?)(?: \{#[^}]*\})?\s*$", doc.split("\n", 1)[0])
    if not title_match:
        raise SrsError("cannot read title")
    first_h1 = H1_RE.search(doc, len(doc.split("\n", 1)[0]))
    authors = doc[len(doc.split("\n", 1)[0]):first_h1.start()].strip()
    srs_abs = os.path.abspath(srs_path)
    licence_abs = os.path.join(os.path.dirname(srs_abs), LICENCE_NAME)
    if not os.path.exists(licence_abs):
        warn("licence file %s not found" % licence_abs)
    return {
        "title": title_match.group(1),
        "file": _workspace_relpath(srs_abs),
        "authors": authors,
        "licence": _workspace_relpath(licence_abs),
    }


def _workspace_relpath(path):
    return os.path.relpath(path, WORKSPACE_ROOT).replace(os.sep, "/")


def parse_simple_items(section, prefix):
    """Goals, requirements: ``{"id", "label", "text"}``."""
    return [{"id": prefix + ":" + label, "label": label, "text": plain_text(text)}
            for _anchor, label, text in labelled_items(section)]


def parse_assumptions(section):
    items = []
    for _anchor, label, text in labelled_items(section):
        refby = re.search(r"\s*\(RefBy: (.*)\)\s*$", text)
        if refby:
            body, ref_by = text[:refby.start()], ids_in(refby.group(1))
        else:
            body, ref_by = text, []
            warn("A:%s has no RefBy list in the text" % label)
        items.append({"id": "A:" + label, "label": label,
                      "text": plain_text(body), "ref_by": ref_by})
    return items


def parse_changes(section, prefix):
    """Likely/unlikely changes; a leading ``[A:x](..) - `` names an assumption."""
    items = []
    for _anchor, label, text in labelled_items(section):
        lead = re.match(r"((?:\[A:[^\]]+\]\([^)]*\)(?:,\s*)?)+)\s+-\s+", text)
        assumptions = ids_in(lead.group(1)) if lead else []
        body = text[lead.end():] if lead else text
        items.append({"id": prefix + ":" + label, "label": label,
                      "text": plain_text(body), "assumptions": assumptions})
    return items


def parse_symbol_table(doc):
    """Table of symbols: latex -> {"description", "unit"}."""
    header, rows = table_by_id(doc, "Table:ToS")
    if header != ["Symbol", "Description", "Units"]:
        raise SrsError("unexpected Table of Symbols header %r" % header)
    symbols = {}
    for sym, desc, unit in rows:
        latex = single_inline_math(sym, "ToS symbol")
        symbols[latex] = {
            "description": plain_text(desc),
            "unit": "1" if unit.strip() == "---" else unit_to_ascii(
                single_inline_math(unit, "ToS unit")),
        }
    return symbols


def quantity_name(symbol, symbols):
    entry = symbols.get(symbol)
    if entry is None:
        raise SrsError("symbol %r not in the Table of Symbols" % symbol)
    name = entry["description"]
    return name[:1].lower() + name[1:]


def parse_input_constraints(doc, symbols):
    header, rows = table_by_id(doc, "Table:InDataConstraints")
    expected = ["Var", "Physical Constraints", "Software Constraints",
                "Reasonable Value", "Uncert."]
    if header != expected:
        raise SrsError("unexpected input constraints header %r" % header)
    result = []
    for var, phys, soft, value, uncert in rows:
        symbol = single_inline_math(var, "constraint variable")
        maths = INLINE_MATH_RE.findall(value)
        if not 1 <= len(maths) <= 2 or INLINE_MATH_RE.sub("", value).strip():
            raise SrsError("cannot read reasonable value %r" % value)
        value_text = unescape_latex(maths[0])
        unit = unit_to_ascii(maths[1]) if len(maths) == 2 else "1"
        tos_unit = symbols.get(symbol, {}).get("unit")
        if tos_unit is not None and tos_unit != unit:
            warn("input constraint %s: unit %s differs from Table of Symbols %s"
                 % (symbol, unit, tos_unit))
        result.append({
            "symbol": symbol,
            "quantity": quantity_name(symbol, symbols),
            "physical_constraint": _optional_math(phys),
            "software_constraint": _optional_math(soft),
            "reasonable_value": latex_number(value_text),
            "reasonable_value_text": value_text,
            "unit": unit,
            "uncertainty": percentage(uncert),
        })
    return result


def _optional_math(cell):
    return None if null_if_dashes(cell) is None else single_inline_math(cell, "constraint")


def parse_output_constraints(doc, symbols):
    header, rows = table_by_id(doc, "Table:OutDataConstraints")
    if header != ["Var", "Physical Constraints"]:
        raise SrsError("unexpected output constraints header %r" % header)
    result = []
    for var, phys in rows:
        symbol = single_inline_math(var, "constraint variable")
        result.append({"symbol": symbol,
                       "quantity": quantity_name(symbol, symbols),
                       "physical_constraint": _optional_math(phys)})
    return result


# ---------------------------------------------------------------------------
# Models (TM, GD, DD, IM)
# ---------------------------------------------------------------------------

def parse_description(cell, model_id):
    entries = []
    for item in LI_RE.findall(cell):
        match = DESCRIPTION_RE.match(item.strip())
        if not match:
            raise SrsError("%s: cannot read description item %r" % (model_id, item))
        entries.append({
            "symbol": unescape_latex(match.group("sym")),
            "description": plain_text(match.group("desc")),
            "unit": "1" if match.group("unitless") else unit_to_ascii(match.group("unit")),
        })
    return entries


def parse_models(section, kind, derivations):
    heads = list(H2_RE.finditer(section))
    models = []
    for index, head in enumerate(heads):
        model_id = head.group(2)
        if not model_id.startswith(kind + ":"):
            raise SrsError("unexpected model %s in %s section" % (model_id, kind))
        end = heads[index + 1].start() if index + 1 < len(heads) else len(section)
        table = key_value_table(section[head.end():end])
        if table.get("Refname") != model_id:
            raise SrsError("%s: Refname row is %r" % (model_id, table.get("Refname")))
        equations = display_maths(table["Equation"])
        if len(equations) != 1:
            raise SrsError("%s: expected one equation, got %d" % (model_id, len(equations)))
        model = {
            "id": model_id,
            "kind": kind,
            "label": plain_text(table["Label"]),
            "symbol": single_inline_math(table["Symbol"], model_id + " symbol")
            if kind == "DD" else None,
            "units": unit_to_ascii(_unit_cell(table["Units"])) if "Units" in table else None,
            "equation": equations[0],
            "symbols": parse_description(table["Description"], model_id),
            "notes": [plain_text(note) for note in LI_RE.findall(table["Notes"])],
        }
        if kind == "IM":
            model["inputs"] = [unescape_latex(m) for m in INLINE_MATH_RE.findall(table["Input"])]
            model["outputs"] = [unescape_latex(m) for m in INLINE_MATH_RE.findall(table["Output"])]
            model["input_constraints"] = display_maths(table["Input Constraints"])
            model["output_constraints"] = display_maths(table["Output Constraints"])
        source = null_if_dashes(table["Source"])
        model["source"] = plain_text(source) if source is not None else None
        model["ref_by"] = ids_in(table["RefBy"])
        model["assumptions"] = []   # filled from the traceability tables
        model["uses"] = []
        if model_id in derivations:
            model["derivation"] = derivations[model_id]
        models.append(model)
    return models


def _unit_cell(cell):
    return "Unitless" if cell.strip() == "Unitless" else single_inline_math(cell, "units")


def parse_derivations(doc):
    """Model id -> list of display equations of its "Detailed derivation" block."""
    derivations = {}
    for match in H4_DERIV_RE.finditer(doc):
        stop = re.compile(r"^(<div align=\"center\">|#{1,4} )", re.M).search(doc, match.end())
        body = doc[match.end():stop.start() if stop else len(doc)]
        derivations[match.group(2)] = display_maths(body)
    return derivations


# ---------------------------------------------------------------------------
# Traceability
# ---------------------------------------------------------------------------

def parse_trace_table(doc, table_id):
    """Return (column ids, [(row id, [column ids marked X])])."""
    header, rows = table_by_id(doc, table_id)
    if header[0].strip():
        raise SrsError("table %s: first header cell should be empty" % table_id)
    columns = [_single_id(cell, table_id) for cell in header[1:]]
    parsed = []
    for row in rows:
        row_id = _single_id(row[0], table_id)
        marked = []
        for column, cell in zip(columns, row[1:]):
            if cell.strip() == "X":
                marked.append(column)
            elif cell.strip():
                raise SrsError("table %s: unexpected cell %r" % (table_id, cell))
        parsed.append((row_id, marked))
    return columns, parsed


def _single_id(cell, table_id):
    found = ids_in(cell)
    if len(found) != 1:
        raise SrsError("table %s: cannot read id from %r" % (table_id, cell))
    return found[0]


def parse_traceability(doc):
    tables = {}
    for key, table_id in (("assumptions_vs_assumptions", "Table:TraceMatAvsA"),
                          ("assumptions_vs_items", "Table:TraceMatAvsAll"),
                          ("items_vs_items", "Table:TraceMatRefvsRef"),
                          ("requirements_vs_items", "Table:TraceMatAllvsR")):
        tables[key] = parse_trace_table(doc, table_id)
    return tables


def pairs(table):
    _columns, rows = table
    return [[row_id, column] for row_id, marked in rows for column in marked]


# ---------------------------------------------------------------------------
# Assembly, checks and cross-checks
# ---------------------------------------------------------------------------

def build_catalog(doc, srs_path):
    sections = split_sections(doc)

    def section(anchor):
        if anchor not in sections:
            raise SrsError("section %s not found" % anchor)
        return sections[anchor]

    symbols = parse_symbol_table(doc)
    derivations = parse_derivations(doc)
    tables = parse_traceability(doc)

    catalog = {
        "source": parse_source(doc, srs_path),
        "goals": parse_simple_items(section("Sec:GoalStmt"), "GS"),
        "assumptions": parse_assumptions(section("Sec:Assumps")),
        "theoretical_models": parse_models(section("Sec:TMs"), "TM", derivations),
        "general_definitions": parse_models(section("Sec:GDs"), "GD", derivations),
        "data_definitions": parse_models(section("Sec:DDs"), "DD", derivations),
        "instance_models": parse_models(section("Sec:IMs"), "IM", derivations),
        "input_constraints": parse_input_constraints(doc, symbols),
        "output_constraints": parse_output_constraints(doc, symbols),
        "functional_requirements": parse_simple_items(section("Sec:FRs"), "FR"),
        "nonfunctional_requirements": parse_simple_items(section("Sec:NFRs"), "NFR"),
        "likely_changes": parse_changes(section("Sec:LCs"), "LC"),
        "unlikely_changes": parse_changes(section("Sec:UCs"), "UC"),
        "traceability": {key: pairs(table) for key, table in tables.items()},
    }

    avs_all = dict(tables["assumptions_vs_items"][1])
    ref_vs_ref = dict(tables["items_vs_items"][1])
    for model in all_models(catalog):
        if model["id"] not in avs_all or model["id"] not in ref_vs_ref:
            raise SrsError("%s missing from a traceability table" % model["id"])
        model["assumptions"] = avs_all[model["id"]]
        model["uses"] = ref_vs_ref[model["id"]]
    unknown = set(derivations) - {m["id"] for m in all_models(catalog)}
    if unknown:
        raise SrsError("derivations for unknown models: %s" % sorted(unknown))

    known_ids = {m["id"] for m in all_models(catalog)}
    for key in ("goals", "assumptions", "functional_requirements",
                "nonfunctional_requirements", "likely_changes", "unlikely_changes"):
        known_ids.update(item["id"] for item in catalog[key])
    for key, (columns, rows) in tables.items():
        unknown = sorted(set(columns + [row_id for row_id, _ in rows]) - known_ids)
        if unknown:
            raise SrsError("traceability table %s mentions ids not defined in the text: %s"
                           % (key, ", ".join(unknown)))

    cross_check(catalog, tables, symbols)
    return catalog


def all_models(catalog):
    for key in ("theoretical_models", "general_definitions",
                "data_definitions", "instance_models"):
        yield from catalog[key]


def check_expectations(catalog):
    """Fatal checks: counts and spot-checked traceability facts."""
    errors = []
    for key, expected in EXPECTED_COUNTS.items():
        if len(catalog[key]) != expected:
            errors.append("%s: expected %d, found %d" % (key, expected, len(catalog[key])))
    models = {m["id"]: m for m in all_models(catalog)}
    for model_id, expected in EXPECTED_USES.items():
        got = models.get(model_id, {}).get("uses")
        if got is None or sorted(got) != sorted(expected):
            errors.append("%s uses %r, expected %r" % (model_id, got, expected))
    for model_id, expected in EXPECTED_ASSUMPTIONS.items():
        got = models.get(model_id, {}).get("assumptions")
        if got is None or sorted(got) != sorted(expected):
            errors.append("%s depends on %r, expected %r" % (model_id, got, expected))
    for model in models.values():
        if model["kind"] == "IM" and (not model["inputs"] or not model["outputs"]):
            errors.append("%s: empty inputs/outputs" % model["id"])
    return errors


def cross_check(catalog, tables, symbols):
    """Non-fatal comparison of the SRS text against its own tables."""
    models = {m["id"]: m for m in all_models(catalog)}

    # Model RefBy rows vs. the "uses" table read backwards.
    used_by = {}
    for row_id, marked in tables["items_vs_items"][1]:
        for column in marked:
            used_by.setdefault(column, []).append(row_id)
    for model in models.values():
        text, table = set(model["ref_by"]), set(used_by.get(model["id"], []))
        if text != table:
            warn("%s: RefBy row %s but TraceMatRefvsRef has it used by %s"
                 % (model["id"], sorted(text), sorted(table)))

    # Assumption RefBy lists vs. the assumption columns of TraceMatAvsAll.
    depends = {}
    for row_id, marked in tables["assumptions_vs_items"][1]:
        for column in marked:
            depends.setdefault(column, []).append(row_id)
    for assumption in catalog["assumptions"]:
        text, table = set(assumption["ref_by"]), set(depends.get(assumption["id"], []))
        if text != table:
            warn("%s: RefBy text %s but TraceMatAvsAll column has %s"
                 % (assumption["id"], sorted(text), sorted(table)))
    for change in catalog["likely_changes"] + catalog["unlikely_changes"]:
        table = [a for row_id, marked in tables["assumptions_vs_items"][1]
                 if row_id == change["id"] for a in marked]
        if sorted(change["assumptions"]) != sorted(table):
            warn("%s: text names %s but TraceMatAvsAll marks %s"
                 % (change["id"], change["assumptions"], table))

    # Notes "(from [A:x])" / "[DD:y]" links vs. the table rows.
    for model in models.values():
        noted = set(re.findall(r"\b(?:A|TM|GD|DD|IM):[A-Za-z0-9_-]+",
                               " ".join(model["notes"])))
        noted_a = {i for i in noted if i.startswith("A:")}
        noted_m = noted - noted_a
        if noted_a != set(model["assumptions"]):
            warn("%s: notes cite assumptions %s, TraceMatAvsAll marks %s"
                 % (model["id"], sorted(noted_a), sorted(model["assumptions"])))
        if noted_m - set(model["uses"]):
            warn("%s: notes cite %s, not marked as used in TraceMatRefvsRef"
                 % (model["id"], sorted(noted_m - set(model["uses"]))))

    # Symbols, units and descriptions vs. the Table of Symbols.
    for model in models.values():
        if model["kind"] == "DD" and model["symbols"][0]["symbol"] != model["symbol"]:
            warn("%s: Symbol row differs from the first description entry" % model["id"])
        if model["units"] is not None and model["symbols"][0]["unit"] != model["units"]:
            warn("%s: Units row %s differs from its description %s"
                 % (model["id"], model["units"], model["symbols"][0]["unit"]))
        for entry in model["symbols"]:
            tos = symbols.get(entry["symbol"])
            if tos is None:
                warn("%s: symbol %s not in the Table of Symbols" % (model["id"], entry["symbol"]))
                continue
            if tos["unit"] != entry["unit"]:
                warn("%s: unit of %s is %s, Table of Symbols says %s"
                     % (model["id"], entry["symbol"], entry["unit"], tos["unit"]))
            if tos["description"].lower() != entry["description"].lower():
                warn("%s: %s described as %r, Table of Symbols says %r"
                     % (model["id"], entry["symbol"], entry["description"], tos["description"]))


def counts_line(catalog):
    parts = ["%s=%d" % (key, len(catalog[key])) for key in EXPECTED_COUNTS]
    parts += ["%s=%d" % (key, len(value)) for key, value in catalog["traceability"].items()]
    return "counts: " + ", ".join(parts)


# ---------------------------------------------------------------------------
# Entry point
# ---------------------------------------------------------------------------

def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("srs", nargs="?", default=DEFAULT_SRS,
                        help="path to GamePhysics_SRS.md (default: %(default)s)")
    parser.add_argument("--out", help="write the JSON here instead of stdout")
    args = parser.parse_args(argv)

    try:
        with open(args.srs, encoding="utf-8") as handle:
            doc = handle.read().replace("\r\n", "\n")
        catalog = build_catalog(doc, args.srs)
    except (OSError, SrsError) as error:
        print("extract_catalog: error: %s" % error, file=sys.stderr)
        return 2

    print(counts_line(catalog), file=sys.stderr)
    for message in WARNINGS:
        print("warning: " + message, file=sys.stderr)
    errors = check_expectations(catalog)
    if errors:
        for message in errors:
            print("extract_catalog: error: " + message, file=sys.stderr)
        return 1

    text = json.dumps(catalog, indent=2, ensure_ascii=False) + "\n"
    if args.out:
        with open(args.out, "w", encoding="utf-8", newline="\n") as handle:
            handle.write(text)
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
