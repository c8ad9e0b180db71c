"""Shared fixtures of the Python suite: the repository's data folder and the irid program.

ctest runs the suite with PYTHONPATH naming the build's python/ folder and IRID_CLI the
build's irid program (tests/python/CMakeLists.txt)."""

import os
import pathlib

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
DATA = REPO / "data"


@pytest.fixture(scope="session")
def irid_cli():
    path = os.environ.get("IRID_CLI")
    if not path:
        pytest.skip("IRID_CLI is not set (run the suite through ctest)")
    return path
