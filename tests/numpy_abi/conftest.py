"""What both tests here share (imported as `from conftest import env`, as tests/addon/blender does)."""

import os

import pytest


def env(name):
    """The value of the environment variable `name`, which ctest sets (tests/CMakeLists.txt); the
    test fails, saying so, when it is missing."""
    value = os.environ.get(name)
    if not value:
        pytest.fail(f"{name} is not set (ctest sets it: tests/CMakeLists.txt)")
    return value
