# pytest set-up for the bindings' tests: ctest runs them with PYTHONPATH=build/python and
# ERGO_SOURCE_DIR set (tests/CMakeLists.txt); by hand:
#   PYTHONPATH=build/python /usr/bin/python3 -m pytest tests/python
import os
import pathlib

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("ERGO_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture(scope="session")
def source_dir():
    return SOURCE_DIR


@pytest.fixture(scope="session")
def bump():
    """The small bump scene (a soft ball on a plate with a Gaussian bump), coarse."""
    import ergo
    return ergo.scenario("bump", bump_edge_length=0.014, bump_plate_cells=12)
