"""Where the tests find the repository and the command line: GP_ROOT and GP_BIN, which ctest
sets (tests/CMakeLists.txt); the module itself comes from PYTHONPATH=<build>/python."""
import os
import pathlib

import pytest


@pytest.fixture
def root():
    return pathlib.Path(os.environ["GP_ROOT"])


@pytest.fixture
def cli():
    return os.environ["GP_BIN"]
