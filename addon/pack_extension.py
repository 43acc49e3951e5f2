"""Packs the assembled add-on as a Blender extension (4.2+): the add-on's files (with its
subpackages) without the bundled hbc folder, the hbc wheels under wheels/, and a manifest listing
them. Blender installs the wheel matching its Python when the extension is installed.

    python pack_extension.py ADDON_DIR WHEEL_DIR OUT_ZIP
"""

import glob
import os
import re
import sys
import zipfile


def manifest_with_wheels(text, wheels):
    listed = ",\n".join(f'  "./wheels/{w}"' for w in wheels)
    text = re.sub(r"(?ms)^wheels = \[.*?\]\n", "", text)
    block = f"wheels = [\n{listed},\n]\n"
    # Top-level keys must come before the first table ([permissions]).
    head, sep, tail = text.partition("\n[")
    return head.rstrip("\n") + "\n\n" + block + (sep + tail if sep else "")


def addon_sources(addon_dir):
    """The add-on's Python files and its user guide (README.md), relative to its folder: the package and its subpackages, not the
    bundled hbc package (the extension installs hbc from its wheel) nor bytecode caches."""
    found = []
    for folder, dirs, files in os.walk(addon_dir):
        rel = os.path.relpath(folder, addon_dir)
        dirs[:] = sorted(d for d in dirs if d != "__pycache__" and not (rel == "." and d == "hbc"))
        found += [os.path.normpath(os.path.join(rel, f)) for f in files if f.endswith((".py", ".md"))]
    return sorted(found)


def main(addon_dir, wheel_dir, out_zip):
    wheels = sorted(os.path.basename(w) for w in glob.glob(os.path.join(wheel_dir, "hbc-*.whl")))
    if not wheels:
        sys.exit(f"pack_extension: no hbc wheels in {wheel_dir} (run scripts/wheels.sh)")
    name = os.path.basename(os.path.normpath(addon_dir))
    with open(os.path.join(addon_dir, "blender_manifest.toml"), encoding="utf-8") as f:
        manifest = manifest_with_wheels(f.read(), wheels)
    os.makedirs(os.path.dirname(os.path.abspath(out_zip)), exist_ok=True)
    tmp = out_zip + ".tmp"
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as z:
        z.writestr("blender_manifest.toml", manifest)
        for rel in addon_sources(addon_dir):
            z.write(os.path.join(addon_dir, rel), rel.replace(os.sep, "/"))
        for w in wheels:
            z.write(os.path.join(wheel_dir, w), f"wheels/{w}")
    os.replace(tmp, out_zip)
    print(f"pack_extension: {out_zip} ({name}, wheels: {', '.join(wheels)})")


if __name__ == "__main__":
    main(*sys.argv[1:4])
