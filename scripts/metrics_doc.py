#!/usr/bin/env python3
"""Writes the metric tables of docs/metrics.md from the library's one list (hbc.METRIC_FIELDS):
the text between the markers `<!-- metrics table: begin -->` and `<!-- metrics table: end -->` is
replaced, the rest of the doc (formulas, rationale) is kept. tests/python/test_metrics.py checks
that the doc is current. Usage: PYTHONPATH=BUILD/python metrics_doc.py [docs/metrics.md]"""
import pathlib
import sys

BEGIN, END = "<!-- metrics table: begin -->", "<!-- metrics table: end -->"
TITLES = {"census": "Census", "singular": "Singular structure", "complex": "Hybrid base complex",
          "sheets": "Sheets", "non_hex": "Non-hex clustering", "quality": "Quality beside structure",
          "summary": "Summary"}
REFINEMENT = {"invariant": "unchanged", "x8": "× 8", "x2": "× 2", "x4": "× 4", "none": "no rule"}


def table():
    import hbc

    lines, group = [], None
    for f in hbc.METRIC_FIELDS:
        if f.group != group:
            group = f.group
            lines += ["", f"#### {TITLES[group]}", "",
                      "| metric | label | unit | refined 2× | meaning |", "|---|---|---|---|---|"]
        lines.append(f"| `{f.group}.{f.key}` | {f.label} | {f.unit} | {REFINEMENT[f.refinement]} | {f.meaning} |")
    return "\n".join(lines[1:]) + "\n"


def main():
    path = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parents[1] / "docs/metrics.md")
    text = path.read_text()
    head, rest = text.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    path.write_text(f"{head}{BEGIN}\n{table()}{END}{tail}")


if __name__ == "__main__":
    main()
