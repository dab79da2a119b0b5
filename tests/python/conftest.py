"""Shared fixtures of the Python module's tests: the repository root and its example files."""
import os
import pathlib

import pytest

REPO = pathlib.Path(os.environ.get("SOMA_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


def repo_file(rel):
    return REPO / rel


@pytest.fixture
def robots():
    return REPO / "studies" / "robots"


@pytest.fixture
def platforms():
    return REPO / "studies" / "platforms"
