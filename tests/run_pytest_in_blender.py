"""Runs pytest inside Blender: Blender's embedded Python in background mode, or a Python with the
`bpy` module (a PyPI wheel) with Blender loaded in-process first.

    blender -b --factory-startup --python-exit-code 1 \
        --python tests/run_pytest_in_blender.py -- <pytest args>
    <venv>/bin/python tests/run_pytest_in_blender.py <pytest args>

The process exits with pytest's status (5, "no tests collected", is non-zero, hence a failure).
With the bpy module it exits without the interpreter's shutdown: bpy 4.2 crashes while Python
finalizes after every test has passed, which would turn a pass into a failure.
Point BLENDER_USER_CONFIG and BLENDER_USER_SCRIPTS at a temporary folder before starting Blender so
no user configuration is read or written; Blender reads them at start-up, too early for this script.
"""

import os
import site
import sys


def pytest_args(argv):
    """The arguments after Blender's '--' separator, else (the script run by a Python with the
    bpy module) everything after the script's name."""
    if "--" in argv:
        return argv[argv.index("--") + 1:]
    return argv[1:] if argv and argv[0].endswith(".py") else []


def ensure_system_site_packages():
    # Debian's python3-pytest and numpy live in dist-packages; a Blender build with its own
    # Python may not list them, and this runner needs pytest importable. Only for the Python
    # Debian built them for (3.11): a bpy wheel's venv of another Python has its own.
    extra = ["/usr/lib/python3/dist-packages"] if sys.version_info[:2] == (3, 11) else []
    for path in site.getsitepackages() + extra:
        if os.path.isdir(path) and path not in sys.path:
            sys.path.append(path)


def main():
    ensure_system_site_packages()
    for name in ("BLENDER_USER_CONFIG", "BLENDER_USER_SCRIPTS"):
        if name not in os.environ:
            print(f"run_pytest_in_blender: warning: {name} is not set; Blender may use the user's folders",
                  file=sys.stderr)
    import pytest

    import bpy

    # Blender's own sys.argv would confuse anything reading it; give pytest a plain one.
    args = pytest_args(sys.argv)
    sys.argv = ["pytest", *args]
    status = int(pytest.main(args))
    if not bpy.app.binary_path:  # the bpy module: skip the interpreter's shutdown (see above)
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(status)
    sys.exit(status)


main()
