"""One word per concept on every surface: every term of every JSON key and CSV column the `hbc`
command writes, every label of its text (the schema's and the metrics' labels), the Python
package's public names, the add-on's identifiers and UI labels and the web viewer's labels is
defined in the glossary of docs/concepts.md or is one of its plain words, and none uses a word the
glossary retires (except the deprecated aliases it lists).

Environment (ctest, tests/CMakeLists.txt): HBC_CLI the command, PYTHONPATH the built package.
Run by hand, `python tests/vocabulary/test_vocabulary.py` prints every word that is not defined.
"""

from __future__ import annotations

import ast
import json
import os
import re
import subprocess
import sys
import tempfile
from html.parser import HTMLParser
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
CONCEPTS = ROOT / "docs" / "concepts.md"
ADDON = ROOT / "addon" / "hybrid_base_complex"
WEB_PAGE = ROOT / "web" / "src" / "index.html"
#: The add-on's folders whose words a user sees (figures/ draws captions from plan/ too).
ADDON_PARTS = ("ui", "plan", "blender")
MAX_PHRASE = 4
#: The surfaces whose names are keys other programs read: there a deprecated alias may stand.
KEY_SURFACES = ("json", "python", "operator")

# ---------------------------------------------------------------------------------------------
# Words

IRREGULAR = {"vertices": "vertex", "hexahedra": "hexahedron", "polyhedra": "polyhedron",
             "tetrahedra": "tetrahedron", "indices": "index", "matrices": "matrix", "axes": "axis",
             "children": "child", "meshes": "mesh", "classes": "class", "boxes": "box", "hexes": "hex",
             "crosses": "cross", "passes": "pass", "analyses": "analysis"}
KEEP = {"viridis", "analysis", "class", "pass", "cross", "bias", "axis", "is", "this", "its", "has", "was", "us",
        "as", "less", "previous", "various", "plus", "minus", "status", "gauss", "process", "radius",
        "focus", "always", "across", "pseudo", "ids"}


def normal(word: str) -> str:
    """One spelling per word: lower case, singular."""
    w = word.lower()
    if w in IRREGULAR:
        return IRREGULAR[w]
    if w in KEEP or len(w) <= 3 and w != "ids":
        return w
    if w == "ids":
        return "id"
    if w.endswith("ies") and len(w) > 4:
        return w[:-3] + "y"
    if w.endswith(("ches", "shes", "sses", "xes")):
        return w[:-2]
    if w.endswith("s") and not w.endswith("ss"):
        return w[:-1]
    return w


def tokens(text: str) -> list[str]:
    """The words of a key, an identifier or a label: split at `_`, `.`, `-`, spaces and case
    changes (`MetricField`), numbers and single letters dropped (`type1`, `x`)."""
    text = re.sub(r"([a-z])([A-Z])", r"\1 \2", text)
    return [normal(w) for w in re.findall(r"[A-Za-z]+", text) if len(w) > 1]


# ---------------------------------------------------------------------------------------------
# The glossary (docs/concepts.md, section "Glossary")

def glossary_section() -> str:
    text = CONCEPTS.read_text(encoding="utf-8")
    assert "\n## Glossary\n" in text, "docs/concepts.md has no section '## Glossary'"
    return text.split("\n## Glossary\n", 1)[1].split("\n## ", 1)[0]


def subsection(text: str, title: str) -> str:
    assert f"\n### {title}\n" in text, f"the glossary has no subsection '### {title}'"
    return text.split(f"\n### {title}\n", 1)[1].split("\n### ", 1)[0]


def table_rows(text: str) -> list[list[str]]:
    # Cells split at pipes that are not escaped (`\\|H_B\\|` is text).
    rows = [[c.strip() for c in re.split(r"(?<!\\)\|", line.strip().strip("|"))]
            for line in text.splitlines() if line.startswith("|")]
    return [r for r in rows[2:]]  # header and rule


def phrase(cell: str) -> tuple[str, ...]:
    return tuple(tokens(cell.replace("*", "").replace("`", "")))


class Glossary:
    def __init__(self):
        section = glossary_section()
        # | **term** (other spellings of the same term, comma-separated) | paper | definition |
        self.terms = set()
        for row in table_rows(subsection(section, "Terms")):
            head = row[0]
            names = re.findall(r"\*\*([^*]+)\*\*", head)
            for other in re.findall(r"\(([^)]*)\)", head):
                names += other.split(",")
            self.terms.update(p for p in map(phrase, names) if p)
        plain = subsection(section, "Plain words")
        self.plain = {normal(w) for w in re.findall(r"`([A-Za-z]+)`", plain)}
        # | retired words | the glossary's word | surfaces (json, text, python, operator, addon, web, or all) | aliases kept |
        self.retired, self.aliases = [], set()
        for row in table_rows(subsection(section, "Retired words")):
            olds = [phrase(w) for w in re.findall(r"`([^`]+)`", row[0])]
            surfaces = set(re.findall(r"[a-z]+", row[2])) if row[2] != "all" else None
            aliases = set(re.findall(r"`([^`]+)`", row[3].split("(")[0]))  # a note in brackets after them
            self.retired.append((olds, row[1], surfaces, aliases))
            self.aliases |= aliases

    def segments(self, w: list[str]) -> list[tuple[int, int, bool]]:
        """(start, end, defined) of each term (longest first) or single word of `w`."""
        out, i = [], 0
        while i < len(w):
            for n in range(min(MAX_PHRASE, len(w) - i), 0, -1):
                if tuple(w[i:i + n]) in self.terms:
                    out.append((i, i + n, True))
                    i += n
                    break
            else:
                out.append((i, i + 1, w[i] in self.plain))
                i += 1
        return out

    def undefined(self, text: str) -> list[str]:
        """The words of `text` that no term covers and no plain word is."""
        w = tokens(text)
        return [w[a] for a, _, ok in self.segments(w) if not ok]

    def retired_in(self, surface: str, text: str, name: str) -> list[str]:
        w = tuple(tokens(text))
        # A retired word counts where a term or word starts: "non-hex component" holds no "hex component".
        starts = [a for a, _, _ in self.segments(list(w))]
        found = []
        for olds, instead, surfaces, aliases in self.retired:
            if surfaces is not None and surface not in surfaces or surface in KEY_SURFACES and name in aliases:
                continue
            for old in olds:
                if any(w[i:i + len(old)] == old for i in starts):
                    found.append(f"{' '.join(old)!r} (say {instead})")
        return found


# ---------------------------------------------------------------------------------------------
# The surfaces: (surface, where, name, text). `name` is what an alias list names (a JSON key path,
# an identifier); `text` what is checked (a key with its parent key, a label).

def cli(*args, check=True) -> str:
    exe = os.environ.get("HBC_CLI")
    assert exe, "HBC_CLI is not set (ctest sets it to the built hbc)"
    run = subprocess.run([exe, *map(str, args)], capture_output=True, text=True)
    assert not check or run.returncode == 0, f"hbc {' '.join(map(str, args))}: {run.stderr}"
    return run.stdout


def json_keys(value, parent="", out=None):
    """(path, parent key, key) of every object key, through lists."""
    out = {} if out is None else out
    if isinstance(value, dict):
        for k, v in value.items():
            path = f"{parent}.{k}" if parent else k
            out.setdefault(re.sub(r"\.\d+", "", path), (parent.rsplit(".", 1)[-1], k))
            json_keys(v, path, out)
    elif isinstance(value, list):
        for item in value:
            json_keys(item, parent, out)
    return out


def cli_surfaces():
    items = []
    with tempfile.TemporaryDirectory() as tmp:
        # A twisted pair has every structure: pyramids (non-hex cells), type 3 sheets, subsheets.
        mesh = Path(tmp) / "pair.mesh"
        cli("generate", "twisted-pair", "--section", "2", "--sections", "8", "-o", mesh)
        runs = {"info": ["info", mesh, "--json"], "analyze": ["analyze", mesh, "--json"],
                "analyze --skip-invalid": ["analyze", mesh, "--json", "--skip-invalid"],
                "sheets": ["sheets", mesh, "--json"], "sheets fewest": ["sheets", mesh, "--json", "--subsheets",
                                                                       "fewest"],
                "wireframe": ["wireframe", mesh, "--json"], "wireframe --sheet": ["wireframe", mesh, "--json",
                                                                                  "--sheet", "0"],
                "quality": ["quality", mesh, "--json"], "metrics": ["metrics", mesh, "--json"],
                "check": ["check", mesh, "--json"]}
        for what, args in runs.items():
            for path, (parent, key) in json_keys(json.loads(cli(*args, check=what != "check"))).items():
                items.append(("json", f"hbc {what} --json", path, f"{parent} {key}"))
        for what in ("analyze", "metrics"):
            for col in cli(what, mesh, "--csv").splitlines()[0].split(","):
                items.append(("json", f"hbc {what} --csv", col, col.replace(".", " ")))
    return items


def python_surfaces():
    import hbc
    items = [("python", "hbc", name, name) for name in hbc.__all__]
    for table in ("STAT_FIELDS", "TIMING_FIELDS", "WIREFRAME_COUNT_FIELDS", "METRIC_FIELDS"):
        for f in getattr(hbc, table):
            name = f"{f.group}.{f.key}" if table == "METRIC_FIELDS" else f.key
            items.append(("text", f"hbc.{table}", name, f.label))
    return items


def _strings(node):
    return [n.value for n in ast.walk(node) if isinstance(n, ast.Constant) and isinstance(n.value, str)]


def addon_surfaces():
    items = []
    for part in ADDON_PARTS:
        for path in sorted((ADDON / part).rglob("*.py")):
            if path.name == "upgrade.py":  # the old names it upgrades, on purpose
                continue
            where = str(path.relative_to(ROOT))
            for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
                if isinstance(node, ast.Assign) and any(getattr(t, "id", "") == "bl_label" for t in node.targets):
                    items += [("addon", where, s, s) for s in _strings(node.value)]
                elif isinstance(node, ast.keyword) and node.arg in ("name", "text"):
                    items += [("addon", where, s, s) for s in _strings(node.value) if s.strip()]
                elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
                    items.append(("addon", where, node.target.id, node.target.id))  # property names
                elif (isinstance(node, ast.Tuple) and len(node.elts) >= 2
                      and all(isinstance(e, ast.Constant) and isinstance(e.value, str) for e in node.elts[:2])
                      and re.fullmatch(r"[a-z][a-z0-9_]*|[A-Z][A-Z0-9_]*", node.elts[0].value)):
                    # (key, ..., words) rows: layers, legend entries, enum items, highlights, the
                    # metrics box's rows. Words: a capitalised string of at most 4 words (longer
                    # ones are descriptions, sentences in plain English).
                    labels = [e.value for e in node.elts[1:] if isinstance(e, ast.Constant)
                              and isinstance(e.value, str) and re.match(r"[A-Z]", e.value)
                              and len(e.value.split()) <= 4]
                    if labels:
                        items.append(("addon", where, node.elts[0].value, node.elts[0].value))
                        items += [("addon", where, label, label) for label in labels]
                elif isinstance(node, ast.Constant) and isinstance(node.value, str):
                    m = re.fullmatch(r"hbc([_.])([a-z0-9_]+)", node.value)
                    if m:  # custom properties and attributes; operator ids (bpy.ops.hbc.*, a Python API)
                        items.append(("addon" if m.group(1) == "_" else "operator", where, node.value, m.group(2)))
    return items


class _PageText(HTMLParser):
    def __init__(self):
        super().__init__()
        self.texts = []

    def handle_data(self, data):
        if data.strip() and self.lasttag not in ("script", "style"):
            self.texts.append(data.strip())


def web_surfaces():
    page = _PageText()
    page.feed(WEB_PAGE.read_text(encoding="utf-8"))
    return [("web", "web/src/index.html", t, t) for t in page.texts]


def every_surface():
    return cli_surfaces() + python_surfaces() + addon_surfaces() + web_surfaces()


# ---------------------------------------------------------------------------------------------
# The tests

def _problems():
    g = Glossary()
    undefined, retired = {}, []
    for surface, where, name, text in every_surface():
        if surface in KEY_SURFACES and name in g.aliases:  # a deprecated key, written for old readers
            continue  # (a label has no alias: the label of a renamed key says the new word)
        for w in g.undefined(text):
            undefined.setdefault(w, set()).add(f"{where}: {name}")
        for r in g.retired_in(surface, text, name):
            retired.append(f"{where}: {name!r} uses {r}")
    return undefined, sorted(set(retired))


def test_glossary_parses():
    g = Glossary()
    assert len(g.terms) > 50 and len(g.plain) > 50 and g.retired
    # The retired words are not terms of the glossary too (one word per concept).
    for olds, _, surfaces, _ in g.retired:
        assert surfaces is not None or not any(o in g.terms for o in olds), olds


def test_every_word_is_defined():
    undefined, _ = _problems()
    assert not undefined, "words of keys and labels not in docs/concepts.md's glossary:\n" + "\n".join(
        f"  {w}: {', '.join(sorted(where)[:4])}" for w, where in sorted(undefined.items()))


def test_no_retired_word():
    _, retired = _problems()
    assert not retired, "retired words on a surface:\n  " + "\n  ".join(retired)


def test_deprecated_keys_are_still_written():
    """Every deprecated JSON key the glossary lists is still in the output (a reader of the old name
    finds it), as a JSON key and as a CSV column."""
    g = Glossary()
    written = {name for surface, _, name, _ in cli_surfaces() if surface == "json"}
    keys = {a for a in g.aliases if not a.startswith("hbc.")}
    assert keys and not keys - written, f"listed as kept but not written: {sorted(keys - written)}"


def test_tokens_split_keys_and_labels():
    # A key path, an identifier and a label give the same words.
    assert tokens("singular.curves") == ["singular", "curve"]
    assert tokens("MetricField") == ["metric", "field"]
    assert tokens("Non-hex components") == ["non", "hex", "component"]
    assert tokens("hbc_pseudo_singular_vertices") == ["hbc", "pseudo", "singular", "vertex"]


if __name__ == "__main__":
    undefined, retired = _problems()
    for w, where in sorted(undefined.items()):
        print(f"{w}\t{len(where)}\t{'; '.join(sorted(where)[:3])}")
    print("\n".join(retired))
    sys.exit(1 if undefined or retired else 0)
